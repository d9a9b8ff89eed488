#pragma once

// The OpenGL 1.x forms, as the reference pages define them: gluLookAt,
// glFrustum, glOrtho, gluPerspective. Right-handed eye space looking down -z;
// clip space with NDC x, y, z in [-1, 1] after the divide. Column-vector
// convention (p' = M p). glFrustum and gluPerspective accept far = +infinity
// and return the infinite projection's exact limit.

#include <array>
#include <string>
#include <variant>
#include <vector>

#include "viewpipe/linalg.hpp"
#include "viewpipe/stage.hpp"

namespace viewpipe::gl {

template <class T> struct LookAt {
    Vec3<T> eye, center, up;
};

template <class T> struct Frustum {
    T left, right, bottom, top, zNear, zFar;
};

template <class T> struct Ortho {
    T left, right, bottom, top, zNear, zFar;
};

template <class T> struct Perspective {
    T fovyDegrees, aspect, zNear, zFar;
};

template <class T> using ProjectionSpec = std::variant<Frustum<T>, Ortho<T>, Perspective<T>>;

template <class T> struct Camera {
    LookAt<T> lookAt;
    ProjectionSpec<T> projection;

    // Every number converted by `convert` (T to U).
    template <class U, class F> Camera<U> convert(F&& convert) const
    {
        auto v = [&](const Vec3<T>& x) { return Vec3<U>(convert(x.x()), convert(x.y()), convert(x.z())); };
        Camera<U> out;
        out.lookAt = {v(lookAt.eye), v(lookAt.center), v(lookAt.up)};
        std::visit(
            [&](const auto& p) {
                using P = std::decay_t<decltype(p)>;
                if constexpr (std::is_same_v<P, Perspective<T>>)
                    out.projection =
                        Perspective<U>{convert(p.fovyDegrees), convert(p.aspect), convert(p.zNear), convert(p.zFar)};
                else if constexpr (std::is_same_v<P, Frustum<T>>)
                    out.projection = Frustum<U>{convert(p.left), convert(p.right), convert(p.bottom),
                                                convert(p.top),  convert(p.zNear), convert(p.zFar)};
                else
                    out.projection = Ortho<U>{convert(p.left), convert(p.right), convert(p.bottom),
                                              convert(p.top),  convert(p.zNear), convert(p.zFar)};
            },
            projection);
        return out;
    }

    template <class U> Camera<U> cast() const
    {
        return convert<U>([](const T& x) { return U(x); });
    }
};

inline const std::string kProjectionField = "camera.projection.";

// Eye basis of gluLookAt: s = f x up, u = s x f, rows (s, u, -f). The same
// basis as Foley's (u, v, n) with n = eye - center and VUP = up.
template <class T> Basis<T> eyeBasis(const LookAt<T>& look)
{
    requireFinite(look.eye, "camera.look_at.eye");
    requireFinite(look.center, "camera.look_at.center");
    if (look.eye == look.center)
        throw InputError("camera.look_at.center", "equals the eye: there is no view direction");
    return orthonormalBasis<T>(look.eye - look.center, look.up, "camera.look_at.center - camera.look_at.eye",
                               "camera.look_at.up");
}

template <class T> Mat4<T> lookAt(const LookAt<T>& look)
{
    const Basis<T> basis = eyeBasis(look);
    const Mat3<T> r = basis.rotation();
    Mat4<T> m = embedLinear(r);
    m.template topRightCorner<3, 1>() = -(r * look.eye);
    return m;
}

namespace detail {

template <class T> void requireRange(const T& low, const T& high, const char* lowName, const char* highName)
{
    requireFinite(low, kProjectionField + lowName);
    requireFinite(high, kProjectionField + highName);
    if (low == high)
        throw InputError(kProjectionField + highName, std::string(lowName) + " = " + highName + " (" +
                                                          formatNumber(low) + ") leaves an empty volume");
}

template <class T> void requirePerspectiveDepth(const T& zNear, const T& zFar)
{
    using std::isinf;
    using std::isnan;
    requireFinite(zNear, kProjectionField + "near");
    if (!(zNear > T(0)))
        throw InputError(kProjectionField + "near",
                         "must be greater than 0 for a perspective projection (got " + formatNumber(zNear) + ")");
    if (isnan(zFar) || (isinf(zFar) && zFar < T(0)))
        throw InputError(kProjectionField + "far", "must be a number greater than near, or +infinity");
    if (zFar == zNear)
        throw InputError(kProjectionField + "far", "equals near (" + formatNumber(zNear) + "): empty depth range");
    if (!(zFar > T(0)))
        throw InputError(kProjectionField + "far",
                         "must be greater than 0 for a perspective projection (got " + formatNumber(zFar) + ")");
}

// The depth rows of glFrustum: z_c = C z + D, w_c = -z, with
// C = -(f+n)/(f-n), D = -2fn/(f-n), written in n/f so that f = inf gives
// C = -1, D = -2n exactly.
template <class T> Mat4<T> perspectiveDepth(const T& zNear, const T& zFar)
{
    const T ratio = zNear / zFar;
    Mat4<T> m = Mat4<T>::Identity();
    m(2, 2) = -(T(1) + ratio) / (T(1) - ratio);
    m(2, 3) = T(-2) * zNear / (T(1) - ratio);
    m(3, 2) = T(-1);
    m(3, 3) = T(0);
    return m;
}

// cot(fovy / 2), accurate near 0 and near 180 degrees.
template <class T> T cotHalfFovy(const T& fovyDegrees)
{
    using std::acos;
    using std::tan;
    const T radiansPerHalfDegree = acos(T(-1)) / T(360);
    // cot(x) = tan(90 deg - x); 180 - fovy is exact near 180, so is fovy near 0.
    if (fovyDegrees <= T(90))
        return T(1) / tan(fovyDegrees * radiansPerHalfDegree);
    return tan((T(180) - fovyDegrees) * radiansPerHalfDegree);
}

} // namespace detail

template <class T> void validate(const Frustum<T>& p)
{
    detail::requireRange(p.left, p.right, "left", "right");
    detail::requireRange(p.bottom, p.top, "bottom", "top");
    detail::requirePerspectiveDepth(p.zNear, p.zFar);
}

template <class T> void validate(const Ortho<T>& p)
{
    detail::requireRange(p.left, p.right, "left", "right");
    detail::requireRange(p.bottom, p.top, "bottom", "top");
    detail::requireRange(p.zNear, p.zFar, "near", "far");
}

template <class T> void validate(const Perspective<T>& p)
{
    requireFinite(p.fovyDegrees, kProjectionField + "fovy_deg");
    if (!(p.fovyDegrees > T(0) && p.fovyDegrees < T(180)))
        throw InputError(kProjectionField + "fovy_deg",
                         "must lie strictly between 0 and 180 degrees (got " + formatNumber(p.fovyDegrees) + ")");
    requireFinite(p.aspect, kProjectionField + "aspect");
    if (!(p.aspect > T(0)))
        throw InputError(kProjectionField + "aspect", "must be greater than 0 (got " + formatNumber(p.aspect) + ")");
    detail::requirePerspectiveDepth(p.zNear, p.zFar);
}

// glFrustum as its reference page defines it.
template <class T> Mat4<T> frustum(const Frustum<T>& p)
{
    validate(p);
    Mat4<T> m = detail::perspectiveDepth(p.zNear, p.zFar);
    m(0, 0) = T(2) * p.zNear / (p.right - p.left);
    m(0, 2) = (p.right + p.left) / (p.right - p.left);
    m(1, 1) = T(2) * p.zNear / (p.top - p.bottom);
    m(1, 2) = (p.top + p.bottom) / (p.top - p.bottom);
    return m;
}

template <class T> Mat4<T> ortho(const Ortho<T>& p)
{
    validate(p);
    Mat4<T> m = Mat4<T>::Identity();
    m(0, 0) = T(2) / (p.right - p.left);
    m(0, 3) = -(p.right + p.left) / (p.right - p.left);
    m(1, 1) = T(2) / (p.top - p.bottom);
    m(1, 3) = -(p.top + p.bottom) / (p.top - p.bottom);
    m(2, 2) = T(-2) / (p.zFar - p.zNear);
    m(2, 3) = -(p.zFar + p.zNear) / (p.zFar - p.zNear);
    return m;
}

// gluPerspective as its reference page defines it: f = cot(fovy/2).
template <class T> Mat4<T> perspective(const Perspective<T>& p)
{
    validate(p);
    const T f = detail::cotHalfFovy(p.fovyDegrees);
    Mat4<T> m = detail::perspectiveDepth(p.zNear, p.zFar);
    m(0, 0) = f / p.aspect;
    m(1, 1) = f;
    return m;
}

template <class T> Mat4<T> projectionMatrix(const ProjectionSpec<T>& spec)
{
    return std::visit(
        [](const auto& p) -> Mat4<T> {
            using P = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<P, Frustum<T>>)
                return frustum(p);
            else if constexpr (std::is_same_v<P, Ortho<T>>)
                return ortho(p);
            else
                return perspective(p);
        },
        spec);
}

// The view transformation as stages: T(-eye), then R_eye (rows s, u, -f).
template <class T> std::vector<Stage<T>> lookAtStages(const LookAt<T>& look)
{
    const Basis<T> basis = eyeBasis(look);
    return {
        {"T(-eye)", "translate the eye to the origin", translation<T>(-look.eye)},
        {"R_eye", "rotate so that the view direction becomes -z and up lies in the y-z plane",
         embedLinear(basis.rotation())},
    };
}

// Each projection as stages whose product is its reference matrix.
template <class T> std::vector<Stage<T>> projectionStages(const ProjectionSpec<T>& spec)
{
    return std::visit(
        [](const auto& p) -> std::vector<Stage<T>> {
            using P = std::decay_t<decltype(p)>;
            validate(p);
            if constexpr (std::is_same_v<P, Ortho<T>>) {
                const Vec3<T> toCenter(-(p.left + p.right) / T(2), -(p.bottom + p.top) / T(2),
                                       (p.zNear + p.zFar) / T(2));
                return {
                    {"T_ortho", "translate the center of the view box to the origin", translation<T>(toCenter)},
                    {"S_ortho", "scale the box to the cube [-1, 1]^3, flipping z so that near maps to -1",
                     scaling<T>(T(2) / (p.right - p.left), T(2) / (p.top - p.bottom), T(-2) / (p.zFar - p.zNear))},
                };
            } else if constexpr (std::is_same_v<P, Frustum<T>>) {
                const T shx = (p.right + p.left) / (T(2) * p.zNear);
                const T shy = (p.top + p.bottom) / (T(2) * p.zNear);
                return {
                    {"SH_frustum", "shear so that the center line of the frustum becomes the -z axis",
                     shearXYbyZ<T>(shx, shy)},
                    {"S_frustum", "scale x and y so that the sides become x = +-z, y = +-z",
                     scaling<T>(T(2) * p.zNear / (p.right - p.left), T(2) * p.zNear / (p.top - p.bottom), T(1))},
                    {"P_depth", "perspective matrix: w = -z, and near..far mapped to -1..1 after the divide",
                     detail::perspectiveDepth(p.zNear, p.zFar)},
                };
            } else {
                const T f = detail::cotHalfFovy(p.fovyDegrees);
                return {
                    {"S_fovy", "scale x and y so that the field of view becomes 90 degrees: x = +-z, y = +-z",
                     scaling<T>(f / p.aspect, f, T(1))},
                    {"P_depth", "perspective matrix: w = -z, and near..far mapped to -1..1 after the divide",
                     detail::perspectiveDepth(p.zNear, p.zFar)},
                };
            }
        },
        spec);
}

template <class T> std::vector<Stage<T>> stages(const Camera<T>& camera)
{
    std::vector<Stage<T>> all = lookAtStages(camera.lookAt);
    for (Stage<T>& stage : projectionStages(camera.projection))
        all.push_back(std::move(stage));
    return all;
}

// The view volume's 8 corners in world coordinates: near face first, then
// far face, each in the order (l,b), (r,b), (r,t), (l,t). They map to the NDC
// cube's corners, near face at z = -1.
template <class T> std::array<Vec3<T>, 8> viewVolumeCorners(const Camera<T>& camera)
{
    using std::isinf;
    const Basis<T> basis = eyeBasis(camera.lookAt);
    struct Box {
        T left, right, bottom, top, zNear, zFar;
        bool perspective;
    };
    const Box box = std::visit(
        [](const auto& p) -> Box {
            using P = std::decay_t<decltype(p)>;
            validate(p);
            if constexpr (std::is_same_v<P, Perspective<T>>) {
                const T top = p.zNear / detail::cotHalfFovy(p.fovyDegrees);
                return {-top * p.aspect, top * p.aspect, -top, top, p.zNear, p.zFar, true};
            } else {
                return {p.left, p.right, p.bottom, p.top, p.zNear, p.zFar, std::is_same_v<P, Frustum<T>>};
            }
        },
        camera.projection);
    if (isinf(box.zFar))
        throw InputError(kProjectionField + "far", "is infinite: the view volume has no far face");
    std::array<Vec3<T>, 8> corners;
    const std::array<std::array<T, 2>, 4> face = {
        {{box.left, box.bottom}, {box.right, box.bottom}, {box.right, box.top}, {box.left, box.top}}};
    for (std::size_t k = 0; k < 8; ++k) {
        const T depth = k < 4 ? box.zNear : box.zFar;
        // A frustum's far face is its near face scaled by far / near.
        const T spread = box.perspective ? depth / box.zNear : T(1);
        const Vec3<T> eyePoint(face[k % 4][0] * spread, face[k % 4][1] * spread, -depth);
        corners[k] = camera.lookAt.eye + eyePoint.x() * basis.u + eyePoint.y() * basis.v + eyePoint.z() * basis.n;
    }
    return corners;
}

} // namespace viewpipe::gl
