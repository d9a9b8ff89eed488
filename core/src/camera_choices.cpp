#include "viewpipe/camera_choices.hpp"

#include <algorithm>
#include <cmath>

#include "viewpipe/error.hpp"

namespace viewpipe {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The near plane's rectangle, near and far of any OpenGL projection.
gl::Frustum<double> nearRectangle(const gl::ProjectionSpec<double>& projection)
{
    return std::visit(
        [](const auto& p) {
            using P = std::decay_t<decltype(p)>;
            const double zFar = std::isinf(p.zFar) ? gl::kStandInFar * p.zNear : p.zFar;
            if constexpr (std::is_same_v<P, gl::Perspective<double>>) {
                const double top = p.zNear * std::tan(p.fovyDegrees * kPi / 360);
                return gl::Frustum<double>{-top * p.aspect, top * p.aspect, -top, top, p.zNear, zFar};
            } else {
                return gl::Frustum<double>{p.left, p.right, p.bottom, p.top, p.zNear, zFar};
            }
        },
        projection);
}

// The projection's forms, in ProjectionSpec's order: OpenGL's calls, as the lecture notes name them;
// for another API the form itself, which takes the same numbers through that API's own call.
std::vector<std::string> projectionForms(gl::Api api)
{
    if (api == gl::Api::OpenGL)
        return {"glFrustum", "glOrtho", "gluPerspective"};
    return {"frustum", "orthographic", "perspective (field of view)"};
}

// Between a perspective and glOrtho, the rectangle is taken to or from the look-at
// distance `target`: what lies there keeps its size in the picture (the near
// plane's rectangle as the box would show the scene 2 to 100 times larger).
gl::ProjectionSpec<double> projectionOfType(const gl::ProjectionSpec<double>& from, int type, double target)
{
    gl::Frustum<double> box = nearRectangle(from);
    const bool wasOrtho = std::holds_alternative<gl::Ortho<double>>(from);
    if (wasOrtho != (type == 1) && std::isfinite(target) && target > 0) {
        const double scale = wasOrtho ? box.zNear / target : target / box.zNear;
        box.left *= scale, box.right *= scale, box.bottom *= scale, box.top *= scale;
    }
    if (type == 0)
        return box;
    if (type == 1)
        return gl::Ortho<double>{box.left, box.right, box.bottom, box.top, box.zNear, box.zFar};
    const double fovy = 2 * std::atan2((box.top - box.bottom) / 2, box.zNear) * 180 / kPi;
    return gl::Perspective<double>{fovy, (box.right - box.left) / (box.top - box.bottom), box.zNear, box.zFar};
}

} // namespace

std::vector<CameraChoice> cameraChoices(const CameraSpec<double>& camera)
{
    if (const auto* view = std::get_if<foley::ViewSpec<double>>(&camera))
        return {{"view.projection", "Projection", {"perspective", "parallel"},
                 view->projection == foley::Projection::Perspective ? 0 : 1}};
    const auto& gl = std::get<gl::Camera<double>>(camera);
    CameraChoice api{"camera.api", "API", {}, 0};
    for (const gl::Api a : gl::kApis) {
        if (a == gl.api)
            api.chosen = int(api.options.size());
        api.options.push_back(gl::apiTitle(a));
    }
    return {api,
            {"camera.handedness", "Handedness", {"right: the eye looks down −z", "left: down +z"},
             gl.handedness == gl::Handedness::Right ? 0 : 1},
            {"camera.depth", "Depth", {"standard: near to the low end", "reversed: near to 1"},
             gl.depth == gl::DepthMode::Standard ? 0 : 1},
            {"camera.projection.type", "Projection", projectionForms(gl.api), int(gl.projection.index())}};
}

CameraSpec<double> withChoice(const CameraSpec<double>& camera, const std::string& field, int index)
{
    const std::vector<CameraChoice> choices = cameraChoices(camera);
    const auto choice = std::find_if(choices.begin(), choices.end(), [&](const CameraChoice& c) { return c.field == field; });
    if (choice == choices.end())
        throw InputError(field, "is not a choice of this camera");
    if (index < 0 || index >= int(choice->options.size()))
        throw InputError(field, "has no option " + std::to_string(index) + " (it has " +
                                    std::to_string(choice->options.size()) + ")");
    CameraSpec<double> out = camera;
    if (auto* view = std::get_if<foley::ViewSpec<double>>(&out)) {
        view->projection = index == 0 ? foley::Projection::Perspective : foley::Projection::Parallel;
        return out;
    }
    auto& gl = std::get<gl::Camera<double>>(out);
    if (field == "camera.api")
        gl.api = gl::kApis[index];
    else if (field == "camera.handedness")
        gl.handedness = index == 0 ? gl::Handedness::Right : gl::Handedness::Left;
    else if (field == "camera.depth")
        gl.depth = index == 0 ? gl::DepthMode::Standard : gl::DepthMode::Reversed;
    else if (index != int(gl.projection.index()))
        gl.projection = projectionOfType(gl.projection, index, (gl.lookAt.eye - gl.lookAt.center).norm());
    return out;
}

} // namespace viewpipe
