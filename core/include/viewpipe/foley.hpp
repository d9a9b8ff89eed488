#pragma once

// Foley & van Dam's viewing specification (Computer Graphics: Principles and
// Practice, 2nd ed., ch. 6) and its normalizing transformations
//   N_per = S_per * SH_per * T(-PRP) * R * T(-VRP)
//   N_par = S_par * T_par * SH_par * R * T(-VRP)
// Column-vector convention (p' = M p), right-handed world (WRC) and viewing
// (VRC: u, v, n) coordinates; n points from the view plane toward the viewer.
// Canonical volumes: perspective x = +-z, y = +-z, z = z_min, z = -1;
// parallel x, y in [-1, 1], z in [-1, 0].

#include <array>
#include <string>
#include <vector>

#include "viewpipe/linalg.hpp"
#include "viewpipe/stage.hpp"

namespace viewpipe::foley {

enum class Projection { Perspective, Parallel };

template <class T> struct Window {
    T umin, umax, vmin, vmax;
    T centerU() const { return (umin + umax) / T(2); }
    T centerV() const { return (vmin + vmax) / T(2); }
};

template <class T> struct ViewSpec {
    Projection projection = Projection::Perspective;
    Vec3<T> vrp, vpn, vup; // world coordinates
    Vec3<T> prp;           // VRC (u, v, n)
    Window<T> window;      // on the view plane n = 0
    T front, back;         // F and B, n-coordinates in VRC

    // Every number converted by `convert` (T to U).
    template <class U, class F> ViewSpec<U> convert(F&& convert) const
    {
        auto v = [&](const Vec3<T>& x) { return Vec3<U>(convert(x.x()), convert(x.y()), convert(x.z())); };
        return {projection,
                v(vrp),
                v(vpn),
                v(vup),
                v(prp),
                {convert(window.umin), convert(window.umax), convert(window.vmin), convert(window.vmax)},
                convert(front),
                convert(back)};
    }

    template <class U> ViewSpec<U> cast() const
    {
        return convert<U>([](const T& x) { return U(x); });
    }
};

template <class T> bool operator==(const Window<T>& a, const Window<T>& b)
{
    return a.umin == b.umin && a.umax == b.umax && a.vmin == b.vmin && a.vmax == b.vmax;
}
template <class T> bool operator==(const ViewSpec<T>& a, const ViewSpec<T>& b)
{
    return a.projection == b.projection && a.vrp == b.vrp && a.vpn == b.vpn && a.vup == b.vup && a.prp == b.prp &&
           a.window == b.window && a.front == b.front && a.back == b.back;
}

// Refuses every degenerate or impossible specification with an InputError
// naming the field ("view.vup", ...) and the reason.
template <class T> void validate(const ViewSpec<T>& spec)
{
    requireFinite(spec.vrp, "view.vrp");
    requireFinite(spec.prp, "view.prp");
    requireFinite(spec.window.umin, "view.window[0]");
    requireFinite(spec.window.umax, "view.window[1]");
    requireFinite(spec.window.vmin, "view.window[2]");
    requireFinite(spec.window.vmax, "view.window[3]");
    requireFinite(spec.front, "view.front");
    requireFinite(spec.back, "view.back");
    orthonormalBasis(spec.vpn, spec.vup, "view.vpn", "view.vup");
    if (!(spec.window.umin < spec.window.umax))
        throw InputError("view.window", "umin (" + formatNumber(spec.window.umin) + ") must be less than umax (" +
                                            formatNumber(spec.window.umax) + ")");
    if (!(spec.window.vmin < spec.window.vmax))
        throw InputError("view.window", "vmin (" + formatNumber(spec.window.vmin) + ") must be less than vmax (" +
                                            formatNumber(spec.window.vmax) + ")");
    if (!(spec.front > spec.back))
        throw InputError("view.front", "F (" + formatNumber(spec.front) + ") must be greater than B (" +
                                           formatNumber(spec.back) + ")");
    if (spec.prp.z() == T(0))
        throw InputError("view.prp", "lies on the view plane (PRP n = 0), leaving no direction of projection");
    if (spec.projection == Projection::Perspective && !(spec.prp.z() > spec.front))
        throw InputError("view.prp", "PRP n (" + formatNumber(spec.prp.z()) +
                                         ") must exceed the front plane F (" + formatNumber(spec.front) +
                                         ") for a perspective view: the center of projection must lie in "
                                         "front of the view volume");
}

template <class T> Basis<T> vrcBasis(const ViewSpec<T>& spec)
{
    return orthonormalBasis(spec.vpn, spec.vup, "view.vpn", "view.vup");
}

// Center of the window on the view plane, in VRC.
template <class T> Vec3<T> windowCenter(const ViewSpec<T>& spec)
{
    return {spec.window.centerU(), spec.window.centerV(), T(0)};
}

// Direction of projection CW - PRP, in VRC.
template <class T> Vec3<T> directionOfProjection(const ViewSpec<T>& spec)
{
    return windowCenter(spec) - spec.prp;
}

// SH_per and SH_par: shear so that the DOP becomes parallel to the n (z) axis.
template <class T> Mat4<T> shearDopToAxis(const ViewSpec<T>& spec)
{
    const Vec3<T> dop = directionOfProjection(spec);
    return shearXYbyZ<T>(-dop.x() / dop.z(), -dop.y() / dop.z());
}

// z_min = -(vrp'_z + F) / (vrp'_z + B) with vrp'_z = -PRP_n: the front plane
// in the canonical perspective volume.
template <class T> T zMin(const ViewSpec<T>& spec)
{
    return (spec.prp.z() - spec.front) / (spec.back - spec.prp.z());
}

// Foley's M (eq. 6.48): maps the canonical perspective volume onto the
// canonical parallel volume. 1 + z_min = (F - B) / (PRP_n - B) is formed
// directly, which keeps M accurate when F approaches B.
template <class T> Mat4<T> perspectiveToParallel(const ViewSpec<T>& spec)
{
    const T frontToBack = spec.front - spec.back;
    Mat4<T> m = Mat4<T>::Identity();
    m(2, 2) = (spec.prp.z() - spec.back) / frontToBack;
    m(2, 3) = (spec.prp.z() - spec.front) / frontToBack;
    m(3, 2) = T(-1);
    m(3, 3) = T(0);
    return m;
}

template <class T> std::vector<Stage<T>> perspectiveStages(const ViewSpec<T>& spec)
{
    validate(spec);
    const Basis<T> basis = vrcBasis(spec);
    // S_per = S(2 PRP_n / ((umax-umin)(PRP_n-B)), ..., 1 / (PRP_n-B)), formed
    // as ratios so that a scene scaled by 1e20 does not overflow in float.
    const T depth = spec.prp.z() - spec.back;
    const T perspective = spec.prp.z() / depth;
    const T sx = T(2) / (spec.window.umax - spec.window.umin) * perspective;
    const T sy = T(2) / (spec.window.vmax - spec.window.vmin) * perspective;
    return {
        {StageKind::TranslateVrp, "translate the view reference point to the origin", translation<T>(-spec.vrp)},
        {StageKind::Rotate, "rotate VRC onto the world axes: $u$ to $x$, $v$ to $y$, $n$ to $z$",
         embedLinear(basis.rotation())},
        {StageKind::TranslatePrp, "translate the center of projection (PRP) to the origin", translation<T>(-spec.prp)},
        {StageKind::ShearPerspective, "shear so that the center line of the view volume becomes the $z$ axis",
         shearDopToAxis(spec)},
        {StageKind::ScalePerspective, "scale so that the view volume becomes the canonical perspective volume",
         scaling<T>(sx, sy, T(1) / depth)},
    };
}

template <class T> std::vector<Stage<T>> parallelStages(const ViewSpec<T>& spec)
{
    validate(spec);
    const Basis<T> basis = vrcBasis(spec);
    const Vec3<T> toFrontCenter(-spec.window.centerU(), -spec.window.centerV(), -spec.front);
    return {
        {StageKind::TranslateVrp, "translate the view reference point to the origin", translation<T>(-spec.vrp)},
        {StageKind::Rotate, "rotate VRC onto the world axes: $u$ to $x$, $v$ to $y$, $n$ to $z$",
         embedLinear(basis.rotation())},
        {StageKind::ShearParallel, "shear so that the direction of projection becomes parallel to the $z$ axis",
         shearDopToAxis(spec)},
        {StageKind::TranslateParallel, "translate the center of the front face of the view volume to the origin",
         translation<T>(toFrontCenter)},
        {StageKind::ScaleParallel, "scale so that the view volume becomes the canonical parallel volume",
         scaling<T>(T(2) / (spec.window.umax - spec.window.umin), T(2) / (spec.window.vmax - spec.window.vmin),
                    T(1) / (spec.front - spec.back))},
    };
}

template <class T> std::vector<Stage<T>> stages(const ViewSpec<T>& spec)
{
    return spec.projection == Projection::Perspective ? perspectiveStages(spec) : parallelStages(spec);
}

// The normalizing matrix N_per or N_par in closed form, independent of the
// stage product. With SH3 the 3x3 shear and (cu, cv) the window center,
// SH_per * (-PRP) = -(cu, cv, PRP_n), so both forms read
//   N = S3 * [ SH3 R | SH3 (-R VRP) - (cu, cv, z0) ],  z0 = PRP_n or F,
// with S3 the 3x3 diagonal of S_per or S_par. Fewer roundings than the product.
template <class T> Mat4<T> normalizingMatrix(const ViewSpec<T>& spec)
{
    const std::vector<Stage<T>> parts = stages(spec);
    const Mat3<T> rotation = parts[1].matrix.template topLeftCorner<3, 3>();
    const Mat4<T>& shear = parts[spec.projection == Projection::Perspective ? 3 : 2].matrix;
    const Mat3<T> sh3 = shear.template topLeftCorner<3, 3>();
    const Vec3<T> scale = parts[4].matrix.diagonal().template head<3>();
    const T z0 = spec.projection == Projection::Perspective ? spec.prp.z() : spec.front;
    const Vec3<T> offset(spec.window.centerU(), spec.window.centerV(), z0);
    Mat4<T> n = Mat4<T>::Identity();
    n.template topLeftCorner<3, 3>() = scale.asDiagonal() * (sh3 * rotation);
    n.template topRightCorner<3, 1>() = scale.asDiagonal() * (sh3 * (-(rotation * spec.vrp)) - offset);
    return n;
}

// VRC point (u, v, n) in world coordinates.
template <class T> Vec3<T> vrcToWorld(const ViewSpec<T>& spec, const Basis<T>& basis, const Vec3<T>& p)
{
    return spec.vrp + p.x() * basis.u + p.y() * basis.v + p.z() * basis.n;
}

// The view volume's 8 corners in world coordinates: front face first (n = F),
// then back face (n = B), each face in the order (umin,vmin), (umax,vmin),
// (umax,vmax), (umin,vmax).
template <class T> std::array<Vec3<T>, 8> viewVolumeCorners(const ViewSpec<T>& spec)
{
    validate(spec);
    const Basis<T> basis = vrcBasis(spec);
    const Vec3<T> dop = directionOfProjection(spec);
    const std::array<std::array<T, 2>, 4> window = {{{spec.window.umin, spec.window.vmin},
                                                     {spec.window.umax, spec.window.vmin},
                                                     {spec.window.umax, spec.window.vmax},
                                                     {spec.window.umin, spec.window.vmax}}};
    std::array<Vec3<T>, 8> corners;
    const std::array<T, 2> planes = {spec.front, spec.back};
    for (std::size_t face = 0; face < 2; ++face) {
        for (std::size_t k = 0; k < 4; ++k) {
            const Vec3<T> onWindow(window[k][0], window[k][1], T(0));
            Vec3<T> vrc;
            if (spec.projection == Projection::Perspective) {
                // Along the projector from the PRP through the window corner.
                const T t = (spec.prp.z() - planes[face]) / spec.prp.z();
                vrc = spec.prp + t * (onWindow - spec.prp);
            } else {
                vrc = onWindow + (planes[face] / dop.z()) * dop;
            }
            corners[face * 4 + k] = vrcToWorld(spec, basis, vrc);
        }
    }
    return corners;
}

// The canonical positions of those corners, in the same order.
template <class T> std::array<Vec3<T>, 8> canonicalCorners(const ViewSpec<T>& spec)
{
    std::array<Vec3<T>, 8> corners;
    const std::array<std::array<T, 2>, 4> signs = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    const bool perspective = spec.projection == Projection::Perspective;
    const std::array<T, 2> depths = perspective ? std::array<T, 2>{zMin(spec), T(-1)} : std::array<T, 2>{T(0), T(-1)};
    for (std::size_t face = 0; face < 2; ++face) {
        const T half = perspective ? -depths[face] : T(1);
        for (std::size_t k = 0; k < 4; ++k)
            corners[face * 4 + k] = Vec3<T>(signs[k][0] * half, signs[k][1] * half, depths[face]);
    }
    return corners;
}

} // namespace viewpipe::foley
