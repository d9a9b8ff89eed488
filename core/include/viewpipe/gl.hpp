#pragma once

// The OpenGL 1.x forms, as the reference pages define them: gluLookAt,
// glFrustum, glOrtho, gluPerspective. Right-handed eye space looking down -z;
// clip space with NDC x, y, z in [-1, 1] after the divide. Column-vector
// convention (p' = M p). glFrustum and gluPerspective accept far = +infinity
// and return the infinite projection's exact limit.
//
// The other APIs' cameras are these forms with at most two more stages: a
// left-handed camera (lookAtLH, eye looking down +z) mirrors z before the
// projection, and each API's normalized device coordinates are reached from
// OpenGL's by one linear map of clip space (depth in [0, 1], y down, reversed
// depth). Their products are the APIs' own matrices (glm's *_NO/*_ZO,
// DirectXMath's XMMatrix*LH/RH transposed), as tests/core/api_test.cpp checks.

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

// The graphics API whose conventions the camera follows (scene key "api").
enum class Api { OpenGL, Direct3D, Vulkan, Metal, WebGPU };
enum class Handedness { Right, Left };   // right: the eye looks down -z; left: down +z
enum class DepthMode { Standard, Reversed }; // reversed: near -> the far end of the depth range, far -> the near end

inline constexpr Api kApis[] = {Api::OpenGL, Api::Direct3D, Api::Vulkan, Api::Metal, Api::WebGPU};

// "opengl", "direct3d", "vulkan", "metal", "webgpu": as scene files name it.
std::string apiName(Api api);
// "OpenGL", "Direct3D", "Vulkan", "Metal", "WebGPU": as people name it.
std::string apiTitle(Api api);
// The API called `name`; throws InputError(field, ...) naming the known ones.
Api apiNamed(const std::string& name, const std::string& field);
std::string handednessName(Handedness handedness); // "right", "left"
std::string depthModeName(DepthMode depth);        // "standard", "reversed"

// Direct3D's cameras are left-handed by default, every other API's right-handed.
inline Handedness defaultHandedness(Api api)
{
    return api == Api::Direct3D ? Handedness::Left : Handedness::Right;
}
// NDC depth in [0, 1] (every API but OpenGL, whose depth is in [-1, 1]).
inline bool zeroToOneDepth(Api api)
{
    return api != Api::OpenGL;
}
// Vulkan's NDC y points down; its matrices negate clip y so that up stays up.
inline bool yDown(Api api)
{
    return api == Api::Vulkan;
}
// Window (framebuffer) coordinates start at the top left, y down (OpenGL's at the bottom left, y up).
inline bool windowOriginTopLeft(Api api)
{
    return api != Api::OpenGL;
}

template <class T> struct Camera {
    LookAt<T> lookAt;
    ProjectionSpec<T> projection;
    Api api = Api::OpenGL;
    Handedness handedness = Handedness::Right;
    DepthMode depth = DepthMode::Standard;

    // Every number converted by `convert` (T to U).
    template <class U, class F> Camera<U> convert(F&& convert) const
    {
        auto v = [&](const Vec3<T>& x) { return Vec3<U>(convert(x.x()), convert(x.y()), convert(x.z())); };
        Camera<U> out;
        out.api = api;
        out.handedness = handedness;
        out.depth = depth;
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

template <class T> bool operator==(const LookAt<T>& a, const LookAt<T>& b)
{
    return a.eye == b.eye && a.center == b.center && a.up == b.up;
}
template <class T> bool operator==(const Frustum<T>& a, const Frustum<T>& b)
{
    return a.left == b.left && a.right == b.right && a.bottom == b.bottom && a.top == b.top && a.zNear == b.zNear &&
           a.zFar == b.zFar;
}
template <class T> bool operator==(const Ortho<T>& a, const Ortho<T>& b)
{
    return a.left == b.left && a.right == b.right && a.bottom == b.bottom && a.top == b.top && a.zNear == b.zNear &&
           a.zFar == b.zFar;
}
template <class T> bool operator==(const Perspective<T>& a, const Perspective<T>& b)
{
    return a.fovyDegrees == b.fovyDegrees && a.aspect == b.aspect && a.zNear == b.zNear && a.zFar == b.zFar;
}
template <class T> bool operator==(const Camera<T>& a, const Camera<T>& b)
{
    return a.lookAt == b.lookAt && a.projection == b.projection && a.api == b.api && a.handedness == b.handedness &&
           a.depth == b.depth;
}

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

// The rows of the view rotation: right-handed (gluLookAt, glm::lookAtRH) s, u, -f;
// left-handed (glm::lookAtLH, XMMatrixLookAtLH) up x f = -s, u, f.
template <class T> Mat3<T> eyeRotation(const LookAt<T>& look, Handedness handedness)
{
    Mat3<T> r = eyeBasis(look).rotation();
    if (handedness == Handedness::Left) {
        r.row(0) = -r.row(0);
        r.row(2) = -r.row(2);
    }
    return r;
}

template <class T> Mat4<T> lookAt(const LookAt<T>& look, Handedness handedness = Handedness::Right)
{
    const Mat3<T> r = eyeRotation(look, handedness);
    Mat4<T> m = embedLinear(r);
    // Summed left to right as written: the same bits with SIMD (here) and without (the page's WebAssembly).
    for (int i = 0; i < 3; ++i)
        m(i, 3) = -(r(i, 0) * look.eye.x() + r(i, 1) * look.eye.y() + r(i, 2) * look.eye.z());
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
    if constexpr (isExactScalar<T>) {
        return cotOfHalfDegrees(fovyDegrees); // exact at the angles whose cotangent is a square-root expression
    } else {
        using std::acos;
        using std::tan;
        const T radiansPerHalfDegree = acos(T(-1)) / T(360);
        // cot(x) = tan(90 deg - x); 180 - fovy is exact near 180, so is fovy near 0.
        if (fovyDegrees <= T(90))
            return T(1) / tan(fovyDegrees * radiansPerHalfDegree);
        return tan((T(180) - fovyDegrees) * radiansPerHalfDegree);
    }
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

// A left-handed eye space (looking down +z) as the right-handed one the
// OpenGL forms are written for: z mirrored. glm's *LH_* projections are its
// *RH_* ones times this matrix, and so are DirectXMath's (glm 0.9.9's
// frustumLH_* excepted: its off-center terms keep the RH signs, glm#982).
template <class T> Mat4<T> handednessFlip()
{
    return scaling<T>(T(1), T(1), T(-1));
}

// OpenGL's clip coordinates to the API's, one linear map of (x, y, z, w):
// depth in [0, 1] takes z' = (z + w)/2 (reversed: (w - z)/2), OpenGL's
// reversed depth z' = -z, and Vulkan's y down y' = -y.
template <class T> Mat4<T> ndcConversion(Api api, DepthMode depth)
{
    const bool reversed = depth == DepthMode::Reversed;
    Mat4<T> m = Mat4<T>::Identity();
    if (zeroToOneDepth(api)) {
        m(2, 2) = T(reversed ? -1 : 1) / T(2);
        m(2, 3) = T(1) / T(2);
    } else if (reversed) {
        m(2, 2) = T(-1);
    }
    if (yDown(api))
        m(1, 1) = T(-1);
    return m;
}

// The camera's projection in the column-vector convention: its API's matrix
// (DirectXMath's transposed), with its handedness and depth.
template <class T> Mat4<T> projectionMatrix(const Camera<T>& camera)
{
    Mat4<T> m = ndcConversion<T>(camera.api, camera.depth) * projectionMatrix(camera.projection);
    if (camera.handedness == Handedness::Left)
        m = m * handednessFlip<T>();
    return m;
}

template <class T> Mat4<T> viewMatrix(const Camera<T>& camera)
{
    return lookAt(camera.lookAt, camera.handedness);
}

// The view transformation as stages: T(-eye), then R_eye (rows s, u, -f; left-handed -s, u, f).
template <class T> std::vector<Stage<T>> lookAtStages(const LookAt<T>& look, Handedness handedness = Handedness::Right)
{
    return {
        {StageKind::TranslateEye, "translate the eye to the origin", translation<T>(-look.eye)},
        {StageKind::RotateEye,
         handedness == Handedness::Left
             ? "rotate so that the view direction becomes $+z$ and up lies in the $yz$ plane (left-handed)"
             : "rotate so that the view direction becomes $-z$ and up lies in the $yz$ plane",
         embedLinear(eyeRotation(look, handedness))},
    };
}

// The stage after the projection that takes OpenGL's clip coordinates to the
// API's: NDC_direct3d, ..., NDC_vulkan_reversed with reversed depth, and
// NDC_reversed for OpenGL's (whose standard depth needs no such stage).
StageKind ndcStageKind(Api api, DepthMode depth);

template <class T> Stage<T> ndcStage(Api api, DepthMode depth)
{
    const bool reversed = depth == DepthMode::Reversed;
    std::string what;
    if (zeroToOneDepth(api))
        what = reversed ? "$z' = (w - z)/2$, near 1, far 0" : "$z' = (z + w)/2$, near 0, far 1";
    else
        what = "$z' = -z$, near 1, far $-1$";
    if (yDown(api))
        what += "; $y' = -y$ (or: a negative viewport height)";
    return {ndcStageKind(api, depth),
            "to " + apiTitle(api) + "'s clip coordinates" + (reversed ? ", reversed" : "") + ": " + what,
            ndcConversion<T>(api, depth)};
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
                    {StageKind::TranslateOrtho, "translate the center of the view box to the origin",
                     translation<T>(toCenter)},
                    {StageKind::ScaleOrtho,
                     "scale the box to the cube $[-1, 1]^3$, flipping $z$ so that near maps to $-1$",
                     scaling<T>(T(2) / (p.right - p.left), T(2) / (p.top - p.bottom), T(-2) / (p.zFar - p.zNear))},
                };
            } else if constexpr (std::is_same_v<P, Frustum<T>>) {
                const T shx = (p.right + p.left) / (T(2) * p.zNear);
                const T shy = (p.top + p.bottom) / (T(2) * p.zNear);
                return {
                    {StageKind::ShearFrustum, "shear so that the center line of the frustum becomes the $-z$ axis",
                     shearXYbyZ<T>(shx, shy)},
                    {StageKind::ScaleFrustum, "scale $x$ and $y$ so that the sides become $x = \\pm z$, $y = \\pm z$",
                     scaling<T>(T(2) * p.zNear / (p.right - p.left), T(2) * p.zNear / (p.top - p.bottom), T(1))},
                    {StageKind::PerspectiveDepth,
                     "perspective matrix: $w = -z$, and near to far mapped to $-1$ to 1 after the divide",
                     detail::perspectiveDepth(p.zNear, p.zFar)},
                };
            } else {
                const T f = detail::cotHalfFovy(p.fovyDegrees);
                return {
                    {StageKind::ScaleFovy,
                     "scale $x$ and $y$ so that the field of view becomes $90^\\circ$: $x = \\pm z$, $y = \\pm z$",
                     scaling<T>(f / p.aspect, f, T(1))},
                    {StageKind::PerspectiveDepth,
                     "perspective matrix: $w = -z$, and near to far mapped to $-1$ to 1 after the divide",
                     detail::perspectiveDepth(p.zNear, p.zFar)},
                };
            }
        },
        spec);
}

// The camera's stages: the view, a mirror of z for a left-handed camera, the
// OpenGL projection's stages, and the step to the API's clip coordinates.
template <class T> std::vector<Stage<T>> stages(const Camera<T>& camera)
{
    std::vector<Stage<T>> all = lookAtStages(camera.lookAt, camera.handedness);
    if (camera.handedness == Handedness::Left)
        all.push_back({StageKind::FlipZ,
                       "mirror $z$: the left-handed eye space, looking down $+z$, becomes the right-handed one the "
                       "projection is written for",
                       handednessFlip<T>()});
    for (Stage<T>& stage : projectionStages(camera.projection))
        all.push_back(std::move(stage));
    if (camera.api != Api::OpenGL || camera.depth == DepthMode::Reversed)
        all.push_back(ndcStage<T>(camera.api, camera.depth));
    return all;
}

// Where a finite far plane stands in for an infinite one (a projection turned
// into another type, the volume the accuracy is measured in): this times near.
constexpr double kStandInFar = 1000;

// False for an infinite far plane (glFrustum and gluPerspective's limit).
template <class T> bool hasFarFace(const Camera<T>& camera)
{
    using std::isinf;
    return std::visit([](const auto& p) { return !isinf(p.zFar); }, camera.projection);
}

// The view volume's 8 corners in world coordinates: near face first, then
// far face, each in the order (l,b), (r,b), (r,t), (l,t) of the eye's x and y
// (a left-handed eye's x is -s). They map to the NDC cube's corners, near face
// at z = -1, before the step to the API's clip coordinates.
template <class T> std::array<Vec3<T>, 8> viewVolumeCorners(const Camera<T>& camera)
{
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
    if (!hasFarFace(camera))
        throw InputError(kProjectionField + "far", "is infinite: the view volume has no far face");
    std::array<Vec3<T>, 8> corners;
    const std::array<std::array<T, 2>, 4> face = {
        {{box.left, box.bottom}, {box.right, box.bottom}, {box.right, box.top}, {box.left, box.top}}};
    for (std::size_t k = 0; k < 8; ++k) {
        const T depth = k < 4 ? box.zNear : box.zFar;
        // A frustum's far face is its near face scaled by far / near.
        const T spread = box.perspective ? depth / box.zNear : T(1);
        const T x = camera.handedness == Handedness::Left ? -face[k % 4][0] : face[k % 4][0];
        const Vec3<T> eyePoint(x * spread, face[k % 4][1] * spread, -depth);
        corners[k] = camera.lookAt.eye + eyePoint.x() * basis.u + eyePoint.y() * basis.v + eyePoint.z() * basis.n;
    }
    return corners;
}

} // namespace viewpipe::gl
