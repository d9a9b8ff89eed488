#pragma once

// The elements of a viewing set-up that the app draws, in world coordinates:
// the VRC (or eye) frame, the PRP (center of projection), the window and its
// center CW, the direction of projection, the view volume, and where the
// view volume ends up (the canonical volume).

#include <array>

#include "viewpipe/effects.hpp"
#include "viewpipe/pipeline.hpp"

namespace viewpipe {

template <class T> struct ViewSetup {
    Vec3<T> origin;                        // VRP, or the eye for OpenGL cameras
    Basis<T> axes;                         // u, v, n (OpenGL: s, u, -f, whatever the camera's handedness)
    bool leftHanded = false;               // a left-handed camera: its eye axes are -s, u, f
    Vec3<T> prp;                           // center of projection; for parallel views, PRP as given
    bool perspective = true;
    std::array<Vec3<T>, 4> window;         // on the view plane (OpenGL: the near plane)
    Vec3<T> windowCenter;                  // CW
    std::array<Vec3<T>, 8> volume;         // front face, then back face
    std::array<Vec3<T>, 8> canonical;      // the canonical volume's corners, after the composite and divide
    bool perspectiveCanonical = false;     // canonical is Foley's perspective volume (x = ±z, ..., z = z_min)
};

template <class T> ViewSetup<T> viewSetup(const foley::ViewSpec<T>& spec)
{
    ViewSetup<T> s;
    s.axes = foley::vrcBasis(spec);
    s.origin = spec.vrp;
    s.prp = foley::vrcToWorld(spec, s.axes, spec.prp);
    s.perspective = spec.projection == foley::Projection::Perspective;
    s.perspectiveCanonical = s.perspective;
    const std::array<std::array<T, 2>, 4> corners = {{{spec.window.umin, spec.window.vmin},
                                                      {spec.window.umax, spec.window.vmin},
                                                      {spec.window.umax, spec.window.vmax},
                                                      {spec.window.umin, spec.window.vmax}}};
    for (std::size_t k = 0; k < 4; ++k)
        s.window[k] = foley::vrcToWorld(spec, s.axes, Vec3<T>(corners[k][0], corners[k][1], T(0)));
    s.windowCenter = foley::vrcToWorld(spec, s.axes, foley::windowCenter(spec));
    s.volume = foley::viewVolumeCorners(spec);
    s.canonical = foley::canonicalCorners(spec);
    return s;
}

template <class T> ViewSetup<T> viewSetup(const gl::Camera<T>& camera)
{
    ViewSetup<T> s;
    s.axes = gl::eyeBasis(camera.lookAt);
    s.origin = camera.lookAt.eye;
    s.prp = camera.lookAt.eye;
    s.perspective = !std::holds_alternative<gl::Ortho<T>>(camera.projection);
    s.volume = gl::viewVolumeCorners(camera);
    s.windowCenter = Vec3<T>::Zero();
    for (std::size_t k = 0; k < 4; ++k) {
        s.window[k] = s.volume[k];
        s.windowCenter += s.volume[k] / T(4);
    }
    s.leftHanded = camera.handedness == gl::Handedness::Left;
    // OpenGL's NDC cube, taken to the API's.
    const Mat4<T> toApi = gl::ndcConversion<T>(camera.api, camera.depth);
    for (std::size_t k = 0; k < 8; ++k) {
        const Vec4<T> corner((k % 4 == 1 || k % 4 == 2) ? 1 : -1, k % 4 >= 2 ? 1 : -1, k < 4 ? -1 : 1, 1);
        const Vec4<T> h = toApi * corner;
        s.canonical[k] = h.template head<3>() / h.w();
    }
    if (!s.perspective) // an orthographic camera's projectors run along -f from the near-plane corners
        s.prp = s.windowCenter + s.axes.n * (s.volume[4] - s.volume[0]).norm();
    return s;
}

template <class T> ViewSetup<T> viewSetup(const CameraSpec<T>& camera)
{
    return std::visit([](const auto& c) { return viewSetup(c); }, camera);
}

// With Divide, a perspective Foley view ends, after M, in the canonical parallel volume.
template <class T> ViewSetup<T> viewSetup(const CameraSpec<T>& camera, const EffectList& effects)
{
    ViewSetup<T> s = viewSetup(camera);
    const auto* spec = std::get_if<foley::ViewSpec<T>>(&camera);
    if (spec && effects.has(EffectKind::Divide) && spec->projection == foley::Projection::Perspective) {
        foley::ViewSpec<T> parallel = *spec;
        parallel.projection = foley::Projection::Parallel;
        s.canonical = foley::canonicalCorners(parallel);
        s.perspectiveCanonical = false;
    }
    return s;
}

} // namespace viewpipe
