#pragma once

// One description of a normalizing transformation, whichever convention the
// scene's camera uses: its stages, their composite, and the homogeneous space
// in which the canonical volume is tested and the divide is taken.

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "viewpipe/foley.hpp"
#include "viewpipe/gl.hpp"

namespace viewpipe {

enum class Convention { Foley, OpenGL };

template <class T> using CameraSpec = std::variant<foley::ViewSpec<T>, gl::Camera<T>>;

template <class U, class T> CameraSpec<U> castCamera(const CameraSpec<T>& camera)
{
    return std::visit([](const auto& c) -> CameraSpec<U> { return c.template cast<U>(); }, camera);
}

template <class U, class T, class F> CameraSpec<U> convertCamera(const CameraSpec<T>& camera, F&& convert)
{
    return std::visit([&](const auto& c) -> CameraSpec<U> { return c.template convert<U>(convert); }, camera);
}

// The canonical volume in clip (homogeneous) coordinates, tested without
// dividing: Foley's parallel volume -w <= x, y <= w, -w <= z <= 0 (Foley's
// perspective volume is taken there by M), OpenGL's -w <= x, y, z <= w, the
// other APIs' -w <= x, y <= w, 0 <= z <= w; w > 0. Reversed volumes are the
// same sets with near and far exchanged.
enum class ClipVolume { FoleyParallel, OpenGL, OpenGLReversed, ZeroToOne, ZeroToOneReversed };

// The NDC z of the near (Foley: front) and far (back) planes.
inline double nearPlaneZ(ClipVolume volume)
{
    switch (volume) {
    case ClipVolume::FoleyParallel: return 0;
    case ClipVolume::OpenGL: return -1;
    case ClipVolume::ZeroToOne: return 0;
    case ClipVolume::OpenGLReversed:
    case ClipVolume::ZeroToOneReversed: return 1;
    }
    return 0;
}
inline double farPlaneZ(ClipVolume volume)
{
    switch (volume) {
    case ClipVolume::FoleyParallel: return -1;
    case ClipVolume::OpenGL:
    case ClipVolume::ZeroToOne: return 1;
    case ClipVolume::OpenGLReversed: return -1;
    case ClipVolume::ZeroToOneReversed: return 0;
    }
    return 0;
}
inline bool reversedDepth(ClipVolume volume)
{
    return volume == ClipVolume::OpenGLReversed || volume == ClipVolume::ZeroToOneReversed;
}

inline ClipVolume clipVolumeOf(gl::Api api, gl::DepthMode depth)
{
    const bool reversed = depth == gl::DepthMode::Reversed;
    if (gl::zeroToOneDepth(api))
        return reversed ? ClipVolume::ZeroToOneReversed : ClipVolume::ZeroToOne;
    return reversed ? ClipVolume::OpenGLReversed : ClipVolume::OpenGL;
}

// The projection a pipeline ends in: Foley's two, or OpenGL's three.
enum class ProjectionKind { Perspective, Parallel, Frustum, Ortho };

// "perspective", "parallel", "frustum", "ortho": as scene files and reports name it.
std::string projectionName(ProjectionKind kind);

template <class T> ProjectionKind projectionKind(const gl::ProjectionSpec<T>& spec)
{
    static constexpr ProjectionKind kinds[] = {ProjectionKind::Frustum, ProjectionKind::Ortho,
                                               ProjectionKind::Perspective}; // in the variant's order
    return kinds[spec.index()];
}

template <class T> struct Pipeline {
    Convention convention = Convention::Foley;
    ProjectionKind projection = ProjectionKind::Perspective;
    std::vector<Stage<T>> stages;
    Mat4<T> composite;                     // N_per, N_par, or P * V
    std::optional<T> zmin;                 // Foley perspective only
    std::optional<Mat4<T>> view;           // OpenGL: the lookAt matrix
    std::optional<Mat4<T>> projectionMatrix; // OpenGL: glFrustum, glOrtho or gluPerspective
    Mat4<T> toClip = Mat4<T>::Identity();  // after the composite, before the divide: Foley's M, or I
    ClipVolume clipVolume = ClipVolume::FoleyParallel;
    gl::Api api = gl::Api::OpenGL;         // a camera's API (Foley's views: OpenGL's orientation rules)
    // A face wound counter-clockwise seen from outside, turned toward the eye,
    // winds clockwise in NDC x, y: the picture is mirrored (a left-handed
    // camera, Vulkan's y down, left > right).
    bool frontFacesClockwise = false;
    bool ndcYDown = false;                 // Vulkan: NDC y = -1 is the top of the picture

    // World coordinates to clip coordinates: where the volume is tested and the divide taken.
    Mat4<T> clipMatrix() const { return toClip * composite; }
};

template <class T> Pipeline<T> buildPipeline(const foley::ViewSpec<T>& spec)
{
    Pipeline<T> p;
    p.convention = Convention::Foley;
    const bool perspective = spec.projection == foley::Projection::Perspective;
    p.projection = perspective ? ProjectionKind::Perspective : ProjectionKind::Parallel;
    p.stages = foley::stages(spec);
    p.composite = foley::normalizingMatrix(spec);
    if (perspective) {
        p.zmin = foley::zMin(spec);
        p.toClip = foley::perspectiveToParallel(spec);
    }
    p.clipVolume = ClipVolume::FoleyParallel;
    return p;
}

template <class T> Pipeline<T> buildPipeline(const gl::Camera<T>& camera)
{
    Pipeline<T> p;
    p.convention = Convention::OpenGL;
    p.projection = projectionKind(camera.projection);
    p.stages = gl::stages(camera);
    p.view = gl::viewMatrix(camera);
    p.projectionMatrix = gl::projectionMatrix(camera);
    p.composite = *p.projectionMatrix * *p.view;
    p.clipVolume = clipVolumeOf(camera.api, camera.depth);
    p.api = camera.api;
    p.ndcYDown = gl::yDown(camera.api);
    // The winding in x, y follows the signs of the x and y scales, and which way the eye looks along z.
    const T& xScale = (*p.projectionMatrix)(0, 0);
    const T& yScale = (*p.projectionMatrix)(1, 1);
    p.frontFacesClockwise = ((xScale > T(0)) != (yScale > T(0))) != (camera.handedness == gl::Handedness::Left);
    return p;
}

template <class T> Pipeline<T> buildPipeline(const CameraSpec<T>& camera)
{
    return std::visit([](const auto& c) { return buildPipeline(c); }, camera);
}

// The picture as a screen shows it, in OpenGL's clip coordinates (what an
// OpenGL renderer such as VTK draws with): Foley's parallel volume moved onto
// OpenGL's cube (z_gl = -2z - w), an API's clip coordinates taken back to
// OpenGL's, so that Vulkan's y down shows the right way up and reversed depth
// still draws near things in front.
template <class T> Mat4<T> screenClipMatrix(const Pipeline<T>& p)
{
    Mat4<T> toOpenGl = Mat4<T>::Identity();
    if (p.convention == Convention::Foley) {
        toOpenGl(2, 2) = T(-2);
        toOpenGl(2, 3) = T(-1);
    } else {
        const gl::DepthMode depth = reversedDepth(p.clipVolume) ? gl::DepthMode::Reversed : gl::DepthMode::Standard;
        toOpenGl = gl::ndcConversion<T>(p.api, depth).inverse();
    }
    return toOpenGl * p.clipMatrix();
}

// The six boundary values of a homogeneous point, in the order left, right,
// bottom, top, near, far: inside where all are >= 0, on a plane where its value is 0.
template <class T> std::array<T, 6> clipBoundaries(const Vec4<T>& p, ClipVolume volume)
{
    const T& w = p.w();
    const T nearZ(nearPlaneZ(volume)), farZ(farPlaneZ(volume));
    const T towardFar(farPlaneZ(volume) > nearPlaneZ(volume) ? 1 : -1);
    return {w + p.x(), w - p.x(), w + p.y(), w - p.y(), (p.z() - nearZ * w) * towardFar, (farZ * w - p.z()) * towardFar};
}

// Where a point lies against the canonical volume: bit k of `outside` set where
// boundary k is violated, of `on` where the point lies on plane k.
struct ClipVerdict {
    bool inside = false;
    bool behindEye = false; // w <= 0
    unsigned outside = 0, on = 0;
};

template <class T> ClipVerdict clipVerdict(const Vec4<T>& clip, ClipVolume volume)
{
    ClipVerdict verdict;
    const std::array<T, 6> b = clipBoundaries(clip, volume);
    for (int k = 0; k < 6; ++k) {
        verdict.outside |= b[std::size_t(k)] < T(0) ? 1u << k : 0u;
        verdict.on |= b[std::size_t(k)] == T(0) ? 1u << k : 0u;
    }
    verdict.behindEye = !(clip.w() > T(0));
    verdict.inside = !verdict.behindEye && verdict.outside == 0;
    return verdict;
}

template <class T> bool insideClipVolume(const Vec4<T>& clip, ClipVolume volume)
{
    const T& w = clip.w();
    if (!(w > T(0)))
        return false; // behind the eye or on the eye plane: outside, no divide needed
    const bool xyInside = -w <= clip.x() && clip.x() <= w && -w <= clip.y() && clip.y() <= w;
    const T zLow = volume == ClipVolume::ZeroToOne || volume == ClipVolume::ZeroToOneReversed ? T(0) : -w;
    const T zHigh = volume == ClipVolume::FoleyParallel ? T(0) : w;
    return xyInside && zLow <= clip.z() && clip.z() <= zHigh;
}

template <class T> struct PointTrace {
    std::vector<Vec4<T>> afterStage; // homogeneous point after each stage
    Vec4<T> clip;                    // before the divide (after Foley's M for perspective)
    std::optional<Vec3<T>> divided;  // absent where w = 0
    bool inside = false;
};

template <class T> PointTrace<T> tracePoint(const Pipeline<T>& pipeline, const Vec3<T>& point)
{
    PointTrace<T> trace;
    Vec4<T> p(point.x(), point.y(), point.z(), T(1));
    for (const Stage<T>& stage : pipeline.stages) {
        p = stage.matrix * p;
        // After a divide the trace shows the divided point; the clip coordinates stay undivided.
        trace.afterStage.push_back(stage.divides() && p.w() != T(0) ? Vec4<T>(p / p.w()) : p);
    }
    trace.clip = pipeline.toClip * p;
    if (trace.clip.w() != T(0))
        trace.divided = trace.clip.template head<3>() / trace.clip.w();
    trace.inside = insideClipVolume(trace.clip, pipeline.clipVolume);
    return trace;
}

} // namespace viewpipe

namespace viewpipe {
extern template Pipeline<float> buildPipeline(const CameraSpec<float>&);
extern template Pipeline<double> buildPipeline(const CameraSpec<double>&);
extern template Pipeline<long double> buildPipeline(const CameraSpec<long double>&);
extern template PointTrace<float> tracePoint(const Pipeline<float>&, const Vec3<float>&);
extern template PointTrace<double> tracePoint(const Pipeline<double>&, const Vec3<double>&);
extern template PointTrace<long double> tracePoint(const Pipeline<long double>&, const Vec3<long double>&);
} // namespace viewpipe
