#pragma once

// Small numerical building blocks shared by the Foley and OpenGL forms:
// homogeneous matrix constructors, an accurate cross product and a stable
// orthonormal basis. Templated on the scalar type; no I/O.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

#include "viewpipe/error.hpp"

namespace viewpipe {

template <class T> using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T> using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T> using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T> using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T> using Mat4 = Eigen::Matrix<T, 4, 4>;

// The exact number type (exact.hpp): no rounding to scale against, no angles.
class Exact;
template <class T> inline constexpr bool isExactScalar = std::is_same_v<T, Exact>;

template <class T> T epsilonOf() { return std::numeric_limits<T>::epsilon(); }

template <class T> Mat4<T> translation(const Vec3<T>& d)
{
    Mat4<T> m = Mat4<T>::Identity();
    m.template topRightCorner<3, 1>() = d;
    return m;
}

template <class T> Mat4<T> scaling(const T& sx, const T& sy, const T& sz)
{
    Mat4<T> m = Mat4<T>::Identity();
    m(0, 0) = sx;
    m(1, 1) = sy;
    m(2, 2) = sz;
    return m;
}

// x += shx * z, y += shy * z (Foley's SH_per / SH_par form).
template <class T> Mat4<T> shearXYbyZ(const T& shx, const T& shy)
{
    Mat4<T> m = Mat4<T>::Identity();
    m(0, 2) = shx;
    m(1, 2) = shy;
    return m;
}

template <class T> Mat4<T> embedLinear(const Mat3<T>& r)
{
    Mat4<T> m = Mat4<T>::Identity();
    m.template topLeftCorner<3, 3>() = r;
    return m;
}

// a*b - c*d with one rounding error (Kahan's algorithm with fused multiply-add):
// keeps the cross product of nearly parallel vectors accurate.
template <class T> T diffOfProducts(const T& a, const T& b, const T& c, const T& d)
{
    using std::fma;
    const T cd = c * d;
    const T err = fma(-c, d, cd);
    const T dop = fma(a, b, -cd);
    return dop + err;
}

template <class T> Vec3<T> accurateCross(const Vec3<T>& a, const Vec3<T>& b)
{
    return {diffOfProducts(a.y(), b.z(), a.z(), b.y()), diffOfProducts(a.z(), b.x(), a.x(), b.z()),
            diffOfProducts(a.x(), b.y(), a.y(), b.x())};
}

template <class T> bool allFinite(const Vec3<T>& v)
{
    using std::isfinite;
    return isfinite(v.x()) && isfinite(v.y()) && isfinite(v.z());
}

template <class T> std::string formatNumber(const T& x)
{
    std::ostringstream out;
    out.precision(6);
    out << x;
    return out.str();
}

template <class T> void requireFinite(const T& x, const std::string& field)
{
    using std::isfinite;
    if (!isfinite(x))
        throw InputError(field, "must be a finite number (got " + formatNumber(x) + ")");
}

template <class T> void requireFinite(const Vec3<T>& v, const std::string& field)
{
    if (!allFinite(v))
        throw InputError(field, "must have finite components (got NaN or infinity)");
}

// Scales v by a power of two (exact) so that its largest component lies in
// [0.5, 1): products of such vectors neither overflow nor underflow.
template <class T> Vec3<T> powerOfTwoNormalized(const Vec3<T>& v)
{
    if constexpr (isExactScalar<T>) {
        return v;
    } else {
        using std::frexp;
        using std::ldexp;
        int exponent = 0;
        frexp(v.cwiseAbs().maxCoeff(), &exponent);
        return v.unaryExpr([exponent](const T& x) { return T(ldexp(x, -exponent)); });
    }
}

template <class T> Vec3<T> unitVector(const Vec3<T>& v, const std::string& field)
{
    requireFinite(v, field);
    if (v.isZero(T(0)))
        throw InputError(field, "must not be the zero vector");
    return powerOfTwoNormalized(v).normalized();
}

// Angle between two lines (not oriented), in radians, computed stably.
template <class T> T angleBetweenLines(const Vec3<T>& a, const Vec3<T>& b)
{
    using std::abs;
    using std::atan2;
    const Vec3<T> as = powerOfTwoNormalized(a);
    const Vec3<T> bs = powerOfTwoNormalized(b);
    return atan2(accurateCross(as, bs).norm(), abs(as.dot(bs)));
}

// Below this angle between the up vector and the view-plane normal the roll of
// the view is set by the inputs' rounding, so the specification is refused.
template <class T> T minUpAngle() { return T(16) * epsilonOf<T>(); }

// Right-handed orthonormal basis (u, v, n) from a normal direction and an up
// direction: n = normal/|normal|, u = up x n / |up x n|, v = n x u. The cross
// product is taken on the exactly rescaled inputs with one rounding error per
// component, so u, v, n are orthonormal to a few ulps at any accepted angle.
template <class T> struct Basis {
    Vec3<T> u, v, n;
    Mat3<T> rotation() const
    {
        Mat3<T> r;
        r.row(0) = u.transpose();
        r.row(1) = v.transpose();
        r.row(2) = n.transpose();
        return r;
    }
};

template <class T>
Basis<T> orthonormalBasis(const Vec3<T>& normal, const Vec3<T>& up, const std::string& normalField,
                          const std::string& upField)
{
    const Vec3<T> n = unitVector(normal, normalField);
    unitVector(up, upField);
    if constexpr (isExactScalar<T>) {
        if (up.cross(normal).isZero(T(0)))
            throw InputError(upField, "is parallel to " + normalField + " (exactly): nothing fixes which way is up");
    } else {
        const T angle = angleBetweenLines(up, normal);
        if (!(angle >= minUpAngle<T>())) {
            using std::acos;
            const T degreesPerRadian = T(180) / acos(T(-1));
            throw InputError(upField, "is parallel to " + normalField + " (angle " +
                                          formatNumber(angle * degreesPerRadian) + " degrees; it must be at least " +
                                          formatNumber(minUpAngle<T>() * degreesPerRadian) +
                                          " degrees from it to fix which way is up)");
        }
    }
    const Vec3<T> side = accurateCross(powerOfTwoNormalized(up), powerOfTwoNormalized(normal));
    Basis<T> basis;
    basis.n = n;
    basis.u = powerOfTwoNormalized(side).normalized();
    basis.v = basis.n.cross(basis.u);
    return basis;
}

} // namespace viewpipe
