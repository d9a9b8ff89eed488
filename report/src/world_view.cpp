#include "viewpipe/report/world_view.hpp"

#include <algorithm>
#include <cmath>

#include "viewpipe/animation.hpp"

namespace viewpipe::report {
namespace {

// Primitives up to this many points are framed point by point; larger ones by their box's corners
// (under a projective matrix the image of a box in front of the eye lies within its corners' hull).
constexpr std::size_t kExactFraming = 20000;

constexpr double kWiden = 0.2;   // share of a step spent widening the view
constexpr double kSettle = 0.2;  // and closing in at the end
constexpr int kSweepSamples = 8; // positions sampled to frame a rotation's sweep

constexpr double kPi = 3.14159265358979323846;

// Every framed point at most this share of the way from the scene area's center to its edge: room for
// a marker drawn whole and for the labels beside the points.
constexpr double kEdgeRoom = 0.95;
// The fixed axes run this share of the subject's size beyond it.
constexpr double kAxesBeyond = 0.08;

// Appends the primitive's points through `m` (a large one's by its box's corners); none when a
// point of it has no image. Points on the eye's side of `cut` do not count.
void appendThrough(std::vector<Vec3<double>>& framed, const Primitive& primitive, const Mat4<double>& m,
                   const std::optional<Vec4<double>>& cut)
{
    const std::size_t before = framed.size();
    auto add = [&](const Vec3<double>& p) {
        if (cut && cut->dot(p.homogeneous()) < 0)
            return true;
        const std::optional<Vec3<double>> q = projectPoint(m, p);
        if (q)
            framed.push_back(*q);
        return q.has_value();
    };
    const std::vector<Vec3<double>>& points =
        primitive.kind == PrimitiveKind::Lines ? primitive.segments : primitive.faces->vertices;
    bool seen = true;
    if (points.size() > kExactFraming) {
        seen = !primitive.bounds.isEmpty();
        for (int k = 0; k < 8 && seen; ++k)
            seen = add(primitive.bounds.corner(Eigen::AlignedBox<double, 3>::CornerType(k)));
    } else {
        for (std::size_t k = 0; k < points.size() && seen; ++k)
            seen = add(points[k]);
    }
    if (!seen)
        framed.resize(before);
}

Framing blend(const Framing& a, const Framing& b, double u)
{
    auto between = [u](const Eigen::AlignedBox<double, 3>& p, const Eigen::AlignedBox<double, 3>& q) {
        return p.isEmpty() || q.isEmpty() ? Eigen::AlignedBox<double, 3>()
                                          : Eigen::AlignedBox<double, 3>(p.min() + u * (q.min() - p.min()),
                                                                         p.max() + u * (q.max() - p.max()));
    };
    Framing blended;
    blended.center = a.center + u * (b.center - a.center);
    blended.radius = a.radius + u * (b.radius - a.radius);
    blended.box = between(a.box, b.box);
    blended.drawn = between(a.drawn, b.drawn);
    if (a.center == b.center && a.radius == b.radius && a.points == b.points && a.blended.empty() && b.blended.empty())
        blended.points = a.points; // one framing (a fixed one, or stages framed together)
    else
        blended.blended = {{a.center, a.radius, a.points, 1 - u}, {b.center, b.radius, b.points, u}};
    return blended;
}

// The camera's axes for its direction: the picture's across, up and ahead (across zero where the view
// up runs along the direction: the picture has no up).
struct CameraAxes {
    Vec3<double> across, up, ahead;
};
CameraAxes cameraAxes(const WorldCamera& camera)
{
    const Mat4<double> view = camera.view(); // its rows: the picture's across, up and backward
    return {view.row(0).head<3>(), view.row(1).head<3>(), -view.row(2).head<3>()};
}

// The aim at one set of points: the focal point moved across the view until their picture is centred,
// then the distance at which the farthest out of them reaches kEdgeRoom of the way to the edge.
CameraAim aimAt(const CameraAxes& axes, const Vec2<double>& half, const Vec3<double>& center, double radius,
                const std::vector<Vec3<double>>& points)
{
    constexpr int kCentring = 6; // rounds of centring: each one a perspective correction of the last
    const double sphere = radius / std::sin(std::atan(half.minCoeff()));
    if (points.empty() || axes.across.isZero())
        return {center, sphere};
    auto distanceFrom = [&](const Vec3<double>& focal) {
        double needed = 0, behind = -radius;
        for (const Vec3<double>& p : points) {
            const Vec3<double> offset = p - focal;
            const double depth = offset.dot(axes.ahead);
            needed = std::max(needed, std::max(std::abs(offset.dot(axes.across)) / half.x(),
                                               std::abs(offset.dot(axes.up)) / half.y()) / kEdgeRoom - depth);
            behind = std::max(behind, -depth);
        }
        return std::max(needed, behind + 1e-3 * radius); // nothing framed at or behind the eye
    };
    Vec3<double> focal = center;
    for (int round = 0; round < kCentring; ++round) {
        const double distance = distanceFrom(focal);
        Eigen::AlignedBox<double, 2> seen; // the points' picture, in tangents of the angle from the view's center
        for (const Vec3<double>& p : points) {
            const Vec3<double> offset = p - focal;
            seen.extend(Vec2<double>(offset.dot(axes.across), offset.dot(axes.up)) / (distance + offset.dot(axes.ahead)));
        }
        focal += distance * (seen.center().x() * axes.across + seen.center().y() * axes.up);
    }
    return {focal, distanceFrom(focal)};
}

} // namespace

bool framedElement(Element element)
{
    switch (element) {
    case Element::Window:
    case Element::Projectors:
    case Element::Frame:
    case Element::Vanishing:
        return false;
    default:
        return true;
    }
}

Framing framingOf(const EvaluatedScene& scene, const std::vector<Mat4<double>>& cumulatives, bool withCanonical)
{
    std::vector<Vec3<double>> framed, past; // past: drawn, not framed
    for (const Primitive& primitive : scene.primitives) {
        const bool canonical = primitive.canonical;
        if (canonical && !withCanonical)
            continue;
        for (const Mat4<double>& m : cumulatives)
            appendThrough(framedElement(primitive.element) ? framed : past, primitive,
                          canonical ? Mat4<double>::Identity() : m,
                          !canonical && isProjective(m) ? scene.nearCut : std::nullopt);
    }
    for (const Marker& marker : scene.markers) // the view's points: the PRP, CW
        for (const Mat4<double>& m : cumulatives)
            if (!(isProjective(m) && scene.nearCut && scene.nearCut->dot(marker.point.homogeneous()) < 0))
                if (const std::optional<Vec3<double>> q = projectPoint(m, marker.point))
                    framed.push_back(*q);
    if (framed.empty())
        return {};
    Framing framing;
    for (const Vec3<double>& p : framed)
        framing.box.extend(p);
    framing.center = framing.box.center();
    framing.radius = std::max(1e-9, 0.5 * framing.box.diagonal().norm());
    framing.drawn = framing.box;
    for (const Vec3<double>& p : past)
        framing.drawn.extend(p);
    framing.points = std::move(framed);
    return framing;
}

const char* framingModeName(FramingMode mode)
{
    switch (mode) {
    case FramingMode::Together: return "together";
    case FramingMode::PerStage: return "per-stage";
    case FramingMode::Fixed: return "fixed";
    }
    return "";
}

std::optional<FramingMode> framingModeNamed(const std::string& name)
{
    for (const FramingMode mode : {FramingMode::Together, FramingMode::PerStage, FramingMode::Fixed})
        if (name == framingModeName(mode))
            return mode;
    return std::nullopt;
}

Framing stageFraming(const EvaluatedScene& scene, int stage, FramingMode mode)
{
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    const bool canonical = canonicalOpacityAt(stage, stages) > 0;
    Framing own = framingOf(scene, {cumulativeAt(stages, stage)}, canonical);
    // Framed together, a stage that shows its ghost is framed with it: where the step moved it from.
    const std::optional<Mat4<double>> ghost = shownGhost(scene, stage);
    if (mode != FramingMode::Together || !ghost)
        return own;
    Framing both = framingOf(scene, {*ghost, cumulativeAt(stages, stage)}, canonical);
    both.shown = std::move(own.points);
    return both;
}

StageFramings stageFramings(const EvaluatedScene& scene, FramingMode mode)
{
    if (mode != FramingMode::Fixed)
        return {mode, std::nullopt};
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    std::vector<Mat4<double>> all;
    for (std::size_t k = 0; k <= stages.size(); ++k)
        all.push_back(cumulativeAt(stages, double(k)));
    return {mode, framingOf(scene, all, true)};
}

double canonicalOpacityAt(double position, const std::vector<Stage<double>>& stages)
{
    const auto lastMatrix = std::find_if(stages.rbegin(), stages.rend(), [](const Stage<double>& s) { return !s.divides(); });
    return std::clamp(position - double(stages.rend() - lastMatrix - 1), 0.0, 1.0);
}

double smoothStep(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

WorldMoment stageAtRest(const EvaluatedScene& scene, int stage, const StageFramings& framings)
{
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    return {cumulativeAt(stages, stage), canonicalOpacityAt(stage, stages), shownGhost(scene, stage),
            framings.fixed ? *framings.fixed : stageFraming(scene, stage, framings.mode)};
}

StageShown stageShown(const EvaluatedScene& scene, const WorldMoment& moment)
{
    StageShown shown(scene, moment.drawn, moment.canonicalOpacity);
    shown.ghost = moment.ghost;
    return shown;
}

StageMotion::StageMotion(const EvaluatedScene& scene, int from, int to, const StageFramings& framings)
    : stages_(scene.pipeline.stages), from_(from), to_(to)
{
    const std::vector<Stage<double>>& stages = stages_;
    ghost_ = to == from + 1 ? shownGhost(scene, to) : std::nullopt; // where it starts, while it moves
    if (framings.fixed) {
        start_ = sweep_ = end_ = *framings.fixed;
        return;
    }
    start_ = stageFraming(scene, from, framings.mode);
    end_ = stageFraming(scene, to, framings.mode);
    const int later = std::max(from, to);
    const bool together = std::abs(to - from) == 1 && !(later == to ? end_ : start_).shown.empty(); // framed with the one before
    if (together && stages[std::size_t(later - 1)].matrix.topLeftCorner<3, 3>().isIdentity(0)) {
        sweep_ = stageFraming(scene, later, framings.mode); // a translation: seen against the framing of both ends
        return;
    }
    // The camera takes in the whole motion (a rotation's arc leaves the stages' own framing).
    const bool canonical = canonicalOpacityAt(from, stages) > 0 || canonicalOpacityAt(to, stages) > 0;
    std::vector<Mat4<double>> sweep;
    for (int k = 0; k <= kSweepSamples; ++k)
        sweep.push_back(cumulativeAt(stages, from + (to - from) * double(k) / kSweepSamples));
    if (together) // and both ends whole
        for (const int k : {later - 1, later})
            sweep.push_back(cumulativeAt(stages, double(k)));
    sweep_ = framingOf(scene, sweep, canonical);
}

WorldMoment StageMotion::at(double s) const
{
    const std::vector<Stage<double>>& stages = stages_;
    const double motion = smoothStep((s - kWiden) / (1 - kWiden - kSettle));
    const double position = from_ + (to_ - from_) * motion;
    WorldMoment moment{cumulativeAt(stages, position), canonicalOpacityAt(position, stages), ghost_, sweep_};
    if (s < kWiden)
        moment.framing = blend(start_, sweep_, smoothStep(s / kWiden));
    else if (s > 1 - kSettle)
        moment.framing = blend(sweep_, end_, smoothStep((s - (1 - kSettle)) / kSettle));
    return moment;
}

Vec3<double> WorldCamera::direction() const
{
    return (focalPoint - position).normalized();
}

double WorldCamera::distance() const
{
    return (focalPoint - position).norm();
}

Mat4<double> WorldCamera::view() const
{
    // vtkPerspectiveTransform::SetupCamera: the rows are the view's sideways, up and backward directions.
    const Vec3<double> backward = (position - focalPoint).normalized();
    const Vec3<double> sideways = viewUp.cross(backward).normalized();
    const Vec3<double> up = backward.cross(sideways);
    Mat4<double> m = Mat4<double>::Identity();
    m.row(0).head<3>() = sideways.transpose();
    m.row(1).head<3>() = up.transpose();
    m.row(2).head<3>() = backward.transpose();
    m.topRightCorner<3, 1>() = -(m.topLeftCorner<3, 3>() * position);
    return m;
}

Mat4<double> WorldCamera::projection(double aspect) const
{
    // vtkCamera::ComputeProjectionTransform, then vtkPerspectiveTransform::Frustum.
    const double tangent = std::tan(viewAngle * kPi / 360);
    const double height = nearPlane * tangent, width = height * aspect;
    const double xmin = (windowCenter.x() - 1) * width, xmax = (windowCenter.x() + 1) * width;
    const double ymin = (windowCenter.y() - 1) * height, ymax = (windowCenter.y() + 1) * height;
    Mat4<double> m = Mat4<double>::Zero();
    m(0, 0) = 2 * nearPlane / (xmax - xmin);
    m(1, 1) = 2 * nearPlane / (ymax - ymin);
    m(0, 2) = (xmin + xmax) / (xmax - xmin);
    m(1, 2) = (ymin + ymax) / (ymax - ymin);
    m(2, 2) = -(nearPlane + farPlane) / (farPlane - nearPlane);
    m(2, 3) = -2 * nearPlane * farPlane / (farPlane - nearPlane);
    m(3, 2) = -1;
    return m;
}

CameraAim fitAim(const WorldCamera& camera, const Framing& framing, const ViewFit& fit)
{
    // The tangents of the scene area's half angles (where the picture's text leaves room), across and up.
    const double tangent = std::tan(camera.viewAngle * kPi / 360);
    const bool whole = fit.sceneArea.isEmpty() || fit.height <= 0;
    const Vec2<double> extent = whole ? Vec2<double>(fit.height > 0 ? double(fit.width) / fit.height : 1, 1)
                                      : Vec2<double>((fit.sceneArea.max - fit.sceneArea.min) / fit.height);
    const Vec2<double> half = tangent * extent;
    const CameraAxes axes = cameraAxes(camera);
    if (framing.blended.empty())
        return aimAt(axes, half, framing.center, framing.radius, framing.points);
    CameraAim aim{Vec3<double>::Zero(), 0};
    for (const Framing::Share& part : framing.blended) {
        const CameraAim own = aimAt(axes, half, part.center, part.radius, part.points);
        aim.focalPoint += part.share * own.focalPoint;
        aim.distance += part.share * own.distance;
    }
    return aim;
}

void frameOn(WorldCamera& camera, const Framing& framing, const ViewFit& fit)
{
    const Vec3<double> direction = camera.direction();
    const CameraAim aim = fitAim(camera, framing, fit);
    camera.focalPoint = aim.focalPoint + fit.pan * framing.radius;
    camera.position = camera.focalPoint - direction * fit.zoom * aim.distance;
    // The focal point at the scene area's center (VTK's window center is the view's center's opposite).
    if (fit.width > 0 && fit.height > 0 && !fit.sceneArea.isEmpty()) {
        const Vec2<double> center = (fit.sceneArea.min + fit.sceneArea.max) / 2;
        camera.windowCenter = Vec2<double>(1 - 2 * center.x() / fit.width, 2 * center.y() / fit.height - 1);
    } else {
        camera.windowCenter.setZero();
    }
    fitClippingRange(camera, framing);
}

std::vector<Vec2<double>> subjectOutline(const WorldCamera& camera, const Framing& framing, bool shownOnly)
{
    const CameraAxes axes = cameraAxes(camera);
    if (axes.across.isZero())
        return {};
    std::vector<Vec2<double>> seen;
    for (const Vec3<double>& p : shownOnly && !framing.shown.empty() ? framing.shown : framing.points)
        seen.emplace_back(p.dot(axes.across), -p.dot(axes.up));
    return convexHull(std::move(seen));
}

Eigen::AlignedBox<double, 3> frameExtent(const Framing& framing)
{
    Eigen::AlignedBox<double, 3> extent(Vec3<double>::Zero(), Vec3<double>::Zero());
    if (framing.box.isEmpty())
        return extent;
    extent.extend(framing.box);
    const double beyond = kAxesBeyond * framing.box.sizes().maxCoeff();
    return {extent.min() - Vec3<double>::Constant(beyond), extent.max() + Vec3<double>::Constant(beyond)};
}

TurnedCamera turnedCamera(const Mat4<double>& view, const Mat4<double>& projection, const Vec3<double>& focalPoint,
                          double yawDegrees, double pitchDegrees, double zoom)
{
    const Vec3<double> focal = (view * focalPoint.homogeneous()).head<3>();
    const Eigen::Affine3d orbit = Eigen::Translation3d(focal) * Eigen::AngleAxisd(pitchDegrees * kPi / 180, Vec3<double>::UnitX()) *
                                  Eigen::AngleAxisd(yawDegrees * kPi / 180, Vec3<double>::UnitY()) *
                                  Eigen::Translation3d(-focal);
    const Vec4<double> subject = projection * focal.homogeneous();
    Mat4<double> zoomed = Mat4<double>::Identity();
    for (int axis = 0; axis < 2; ++axis) {
        zoomed(axis, axis) = zoom;
        zoomed(axis, 3) = (1 - zoom) * subject(axis) / subject.w();
    }
    zoomed(2, 2) = kTurnedDepthScale;
    return {orbit.matrix() * view, zoomed * projection};
}

std::optional<Vec3<double>> pickVertex(const std::vector<Vec3<double>>& vertices, const Mat4<double>& drawn,
                                       const Vec2<double>& size, const Vec2<double>& at, const Vec2<double>& window,
                                       const std::optional<Vec4<double>>& cut)
{
    std::optional<Vec3<double>> best;
    double bestDistance = kPickShare * window.norm(), bestDepth = 2;
    for (const Vec3<double>& p : vertices) {
        if (cut && cut->dot(p.homogeneous()) < 0)
            continue; // cut away: not drawn
        const Vec4<double> h = drawn * p.homogeneous();
        if (!inFrontOfEye(h))
            continue;
        const Vec3<double> ndc = h.head<3>() / h.w();
        if (std::abs(ndc.z()) > 1)
            continue;
        const double distance = std::hypot((ndc.x() + 1) / 2 * size.x() - at.x(), (1 - ndc.y()) / 2 * size.y() - at.y());
        if (distance < bestDistance - 1e-9 || (distance <= bestDistance + 1e-9 && ndc.z() < bestDepth)) {
            best = p;
            bestDistance = distance;
            bestDepth = ndc.z();
        }
    }
    return best;
}

void fitClippingRange(WorldCamera& camera, const Framing& framing)
{
    // Everything drawn and the fixed axes lie within the sphere about their box.
    const Vec3<double> direction = camera.direction();
    Eigen::AlignedBox<double, 3> all = frameExtent(framing);
    if (!framing.drawn.isEmpty())
        all.extend(framing.drawn);
    const double along = (all.center() - camera.position).dot(direction), extent = 0.5 * 1.05 * all.diagonal().norm();
    const double nearest = along - extent, farthest = along + extent;
    camera.nearPlane = std::max(nearest, 1e-3 * farthest);
    camera.farPlane = farthest;
}

} // namespace viewpipe::report
