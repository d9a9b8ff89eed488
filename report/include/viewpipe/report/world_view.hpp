#pragma once

// How the world view frames a stage and moves between stages, and the camera
// it looks through: one computation for the app's painter (which hands the
// camera to VTK), the exports and the web page (which computes it in the
// browser). The camera is VTK's perspective camera (vtkCamera): the same
// view and projection matrices. No VTK, no Qt.

#include <optional>
#include <vector>

#include "viewpipe/report/figure.hpp"

namespace viewpipe {

// Where the world view's camera looks and how much it must see: a sphere
// about everything framed, and the points near its surface, which a camera
// fitted a little closer than the sphere (most directions see less of it)
// could leave out.
struct Framing {
    Vec3<double> center = Vec3<double>::Zero();
    double radius = 1;
    std::vector<Vec3<double>> outermost;
    // While a step's framing blends into the next: the two, and each one's share. The camera stands
    // back from the blended sphere by the shares of how far each one's outermost points set it back.
    struct Share {
        Vec3<double> center = Vec3<double>::Zero();
        double radius = 1;
        std::vector<Vec3<double>> outermost;
        double share = 0;
    };
    std::vector<Share> blended;
};

// What framing shows every element as it would be through `cumulatives` (the
// canonical outline included when `withCanonical`); an element partly behind
// the eye does not count.
Framing framingOf(const EvaluatedScene& scene, const std::vector<Mat4<double>>& cumulatives, bool withCanonical);
// The framing of stage k at rest: one for all the stages framed together with
// it (translations and rotations between them are seen moving, rotations'
// sweeps included).
Framing stageFraming(const EvaluatedScene& scene, int stage);
// With `fixed` (export --framing fixed): one framing that holds every stage; else none.
std::optional<Framing> fixedFraming(const EvaluatedScene& scene, bool fixed);

// The canonical outline fades in while the last stage is reached.
double canonicalOpacityAt(double position, std::size_t stageCount);
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
// Stage k at rest: framed on its own, or on `fixed` (export --framing fixed).
WorldMoment stageAtRest(const EvaluatedScene& scene, int stage, const std::optional<Framing>& fixed = std::nullopt);
// A moment as the pictures show it: its matrix, canonical outline, cut and ghost.
StageShown stageShown(const EvaluatedScene& scene, const WorldMoment& moment);

// One animated step between stages, as a function of progress s in [0, 1]:
// the camera first widens to take in the whole motion, the picture then moves
// with the interpolated cumulative matrix under a still camera (so the motion
// reads against the screen), and the camera finally closes in on the result.
// Nothing jumps: every phase starts where the last one ended. With `fixed`
// (export --framing fixed) the camera holds that framing throughout.
class StageMotion {
public:
    StageMotion(const EvaluatedScene& scene, int from, int to, const std::optional<Framing>& fixed = std::nullopt);
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
// How far the camera, looking at the framing's center, must stand to see all of it in the scene area
// (while framings blend, about what each of them would see).
double fitDistance(const WorldCamera& camera, const Framing& framing, const ViewFit& fit);
// Aims the camera at a framing, keeping its direction and the user's zoom and
// pan, with the focal point at the scene area's center; fits the clipping range.
void frameOn(WorldCamera& camera, const Framing& framing, const ViewFit& fit);
// The near and far planes around everything framed and the fixed axes
// (which reach frameReach(framing) from the origin).
void fitClippingRange(WorldCamera& camera, const Framing& framing);
// How far the fixed axes reach for a framing: across everything in view.
double frameReach(const Framing& framing);

} // namespace viewpipe
