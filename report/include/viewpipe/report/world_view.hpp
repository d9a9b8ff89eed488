#pragma once

// How the world view frames a stage and moves between stages, and the camera
// it looks through: one computation for the app's painter (which hands the
// camera to VTK), the exports and the web page (which computes it in the
// browser). The camera is VTK's perspective camera (vtkCamera): the same
// view and projection matrices. No VTK, no Qt.

#include <optional>
#include <string>
#include <vector>

#include "viewpipe/report/figure.hpp"

namespace viewpipe::report {

// What the world view frames: the stage's subject (objects, view volume,
// the view's points and axes: framedElement), every point of it, the box
// about them and a sphere about that box (for the clipping range and the
// user's pan, in its radii).
struct Framing {
    Vec3<double> center = Vec3<double>::Zero();
    double radius = 1;
    std::vector<Vec3<double>> points;
    Eigen::AlignedBox<double, 3> box;
    Eigen::AlignedBox<double, 3> drawn; // about every element drawn, framed or not: for the clipping range
    // Where stages are framed together: the points of the stage at rest alone (a still picture's text may
    // cover where the others go). Empty: `points`.
    std::vector<Vec3<double>> shown;
    // While a step's framing blends into the next: the two, and each one's share. The camera's aim
    // blends each one's aim by its share: nothing jumps.
    struct Share {
        Vec3<double> center = Vec3<double>::Zero();
        double radius = 1;
        std::vector<Vec3<double>> points;
        double share = 0;
    };
    std::vector<Share> blended;
};

// Whether the world view frames an element: the subject of a stage's picture. The window, the
// projectors and the fixed axes may run past it (the window lies where the view-plane is, often far
// beyond the volume).
bool framedElement(Element element);

// What framing shows every framed element and marker as it would be through
// `cumulatives` (the canonical outline included when `withCanonical`); an
// element partly behind the eye does not count.
Framing framingOf(const EvaluatedScene& scene, const std::vector<Mat4<double>>& cumulatives, bool withCanonical);
// How the pictures of a scene's stages are framed (export --framing): a stage
// reached by a step that keeps sizes (a translation or rotation) framed
// together with the stage before it, so that the step's motion shows, the
// default (not where the step moves the set-up about its size or farther:
// both would draw small, shownGhost); every stage on its own; or one framing that holds every stage, for
// comparing sizes.
enum class FramingMode { Together, PerStage, Fixed };
// The names --framing takes: "together", "per-stage", "fixed".
const char* framingModeName(FramingMode mode);
std::optional<FramingMode> framingModeNamed(const std::string& name);

// The framing of stage k at rest: Together, with the stage before it where
// the picture shows its ghost (shownGhost; the framing then has `shown`);
// otherwise its own.
Framing stageFraming(const EvaluatedScene& scene, int stage, FramingMode mode = FramingMode::Together);
// A scene's stages framed as a mode asks, Fixed's one framing made once.
struct StageFramings {
    FramingMode mode = FramingMode::Together;
    std::optional<Framing> fixed;
};
StageFramings stageFramings(const EvaluatedScene& scene, FramingMode mode);

// The canonical outline fades in while the last matrix is reached (a divide
// stage after it changes no picture).
double canonicalOpacityAt(double position, const std::vector<Stage<double>>& stages);
// Ease in and out: 0 at 0, 1 at 1, flat at both ends (u clamped to [0, 1]).
double smoothStep(double u);

// What the world view shows at one moment: the matrix drawn, the canonical
// outline's opacity, the ghost and the framing.
struct WorldMoment {
    Mat4<double> drawn = Mat4<double>::Identity();
    double canonicalOpacity = 0;
    std::optional<Mat4<double>> ghost;
    Framing framing;
};
// Stage k at rest, framed as `framings` ask.
WorldMoment stageAtRest(const EvaluatedScene& scene, int stage, const StageFramings& framings = {});
// A moment as the pictures show it: its matrix, canonical outline, cut and ghost.
StageShown stageShown(const EvaluatedScene& scene, const WorldMoment& moment);

// One animated step between stages, as a function of progress s in [0, 1]:
// the camera first widens to take in the whole motion, the picture then moves
// with the interpolated cumulative matrix under a still camera (so the motion
// reads against the screen), and the camera finally closes in on the result.
// Nothing jumps: every phase starts where the last one ended. With one fixed
// framing the camera holds it throughout.
// A step to the next stage takes kStepMilliseconds in the app and the page;
// one toward a stage further off, kSkipMilliseconds a stage (the app's).
constexpr int kStepMilliseconds = 1000, kSkipMilliseconds = 600;
class StageMotion {
public:
    StageMotion(const EvaluatedScene& scene, int from, int to, const StageFramings& framings = {});
    WorldMoment at(double s) const;
    int from() const { return from_; }
    int to() const { return to_; }

private:
    std::vector<Stage<double>> stages_; // a copy: the motion may outlive the scene it was made from
    int from_, to_;
    Framing start_, sweep_, end_;
    std::optional<Mat4<double>> ghost_;
};

// The world view's camera: VTK's perspective camera, with its defaults for
// the view angle and the viewpoint ViewPipe opens with.
struct WorldCamera {
    Vec3<double> position = Vec3<double>(1.7, 0.9, 1.0); // from the +x side, above: depth (z) runs across the picture
    Vec3<double> focalPoint = Vec3<double>::Zero();
    Vec3<double> viewUp = Vec3<double>::UnitY();
    double viewAngle = 30;                          // degrees, vertical
    Vec2<double> windowCenter = Vec2<double>::Zero(); // VTK's: the view's center moved, in half-views
    double nearPlane = 0.01, farPlane = 1000.01;

    Vec3<double> direction() const; // of projection: from the position to the focal point, unit
    double distance() const;
    // As vtkCamera's GetViewTransformMatrix: world -> eye coordinates.
    Mat4<double> view() const;
    // As vtkCamera's GetProjectionTransformMatrix(aspect, -1, 1): eye -> OpenGL clip coordinates.
    Mat4<double> projection(double aspect) const;
};

// The picture a camera is fitted to: its size in pixels, the part of it the
// text leaves free (layoutPicture's scene area; empty: the whole picture),
// and the user's zoom and pan relative to the automatic framing.
struct ViewFit {
    int width = 1280, height = 720;
    Box2 sceneArea;
    double zoom = 1;
    Vec3<double> pan = Vec3<double>::Zero(); // in framing radii
};
// Where the camera, looking along its direction, aims to see everything framed in the scene area, a
// little in from its edges, and as large as it can: the focal point (the framing's points centred in
// the scene area) and the distance from it (while framings blend, each one's aim by its share).
struct CameraAim {
    Vec3<double> focalPoint = Vec3<double>::Zero();
    double distance = 1;
};
CameraAim fitAim(const WorldCamera& camera, const Framing& framing, const ViewFit& fit);
// Aims the camera at a framing, keeping its direction and the user's zoom and
// pan, with the focal point at the scene area's center; fits the clipping range.
void frameOn(WorldCamera& camera, const Framing& framing, const ViewFit& fit);
// The near and far planes around everything framed and the fixed axes.
void fitClippingRange(WorldCamera& camera, const Framing& framing);

// The world view as the page's reader turned it: the camera (`view`: stage -> eye, `projection`: eye -> clip
// coordinates of the picture) turned by yaw and pitch, in degrees, about the focal point in the eye's axes
// (RotX(pitch) RotY(yaw)), and zoomed by `zoom` about where the focal point is in the picture (as export
// --zoom: the framing centres the subject there, in the room the picture's text leaves). Depth is scaled by
// kTurnedDepthScale, so nothing in front of the eye meets the near and far planes while turning.
constexpr double kTurnedDepthScale = 0.02;
struct TurnedCamera {
    Mat4<double> view, projection;
};
TurnedCamera turnedCamera(const Mat4<double>& view, const Mat4<double>& projection, const Vec3<double>& focalPoint,
                          double yawDegrees, double pitchDegrees, double zoom);

// The vertex a click picks: of `vertices` drawn through `drawn` (world -> clip coordinates) in a view of
// `size` pixels, the nearest to `at` (the view's pixels, y down) within kPickShare of the window's diagonal
// (`window`, pixels), and of those as near the nearest in depth; none cut away (kept where
// cut . (x, y, z, 1) >= 0), behind the eye or outside the depth range. The app's and the page's.
constexpr double kPickShare = 0.01;
std::optional<Vec3<double>> pickVertex(const std::vector<Vec3<double>>& vertices, const Mat4<double>& drawn,
                                       const Vec2<double>& size, const Vec2<double>& at, const Vec2<double>& window,
                                       const std::optional<Vec4<double>>& cut);
// The outline of what a framing frames through a camera looking along its direction, seen from afar
// (picture coordinates, y down, any scale), or of what its stage at rest shows (`shownOnly`, in the
// same coordinates): the picture's layout puts its legend where it costs the subject least.
std::vector<Vec2<double>> subjectOutline(const WorldCamera& camera, const Framing& framing, bool shownOnly = false);
// Where the fixed axes run for a framing: through the origin, a little beyond everything framed.
Eigen::AlignedBox<double, 3> frameExtent(const Framing& framing);

} // namespace viewpipe::report
