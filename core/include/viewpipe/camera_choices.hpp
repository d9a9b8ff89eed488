#pragma once

// The camera's settings picked from a list rather than typed: the Foley
// view's projection, and an OpenGL camera's API, handedness, depth mode and
// projection type. One listing for the app's Parameters and the page's Scene
// panel.

#include <string>
#include <vector>

#include "viewpipe/pipeline.hpp"

namespace viewpipe {

struct CameraChoice {
    std::string field;                // "view.projection", "camera.api", ...: the scene's field path
    std::string title;                // "Projection", "API", ...
    std::vector<std::string> options; // as people read them, in the order indices count
    int chosen = 0;                   // the camera's own
};

// The choices of `camera`'s convention, in the order the Parameters show them.
std::vector<CameraChoice> cameraChoices(const CameraSpec<double>& camera);

// `camera` with option `index` of choice `field` taken. Switching an OpenGL
// camera's projection keeps near and far (1000 · near for an infinite far
// in glOrtho); between glFrustum and gluPerspective the near plane's
// rectangle (its size only, centred, to gluPerspective); between either and
// glOrtho the rectangle at the look-at distance, so that what lies at the
// look-at point keeps its place and size in the picture.
// Throws InputError(field, ...) for a field the camera has no choice of, or
// an index out of range.
CameraSpec<double> withChoice(const CameraSpec<double>& camera, const std::string& field, int index);

} // namespace viewpipe
