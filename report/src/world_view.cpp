#include "viewpipe/report/world_view.hpp"

#include <algorithm>
#include <cmath>

#include "viewpipe/animation.hpp"

namespace viewpipe {
namespace {

// Primitives up to this many points are framed point by point; larger ones by their box's corners
// (under a projective matrix the image of a box in front of the eye lies within its corners' hull).
constexpr std::size_t kExactFraming = 20000;

constexpr double kWiden = 0.2;   // share of a step spent widening the view
constexpr double kSettle = 0.2;  // and closing in at the end
constexpr int kSweepSamples = 8; // positions sampled to frame a rotation's sweep

constexpr double kPi = 3.14159265358979323846;

// The camera stands where it sees this share of the framing's sphere whole (the sphere overstates what
// most directions see).
constexpr double kSphereSeen = 0.95;
// Every framed point at most this share of the way from the scene area's center to its edge, so that a
// marker there is drawn whole: those within this share of that sphere are; those beyond it (the
// framing's outermost) are fitted one by one.
constexpr double kEdgeRoom = 0.95;

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
    Framing blended{a.center + u * (b.center - a.center), a.radius + u * (b.radius - a.radius), {}, {}};
    if (a.center == b.center && a.radius == b.radius && a.outermost == b.outermost && a.blended.empty() && b.blended.empty())
        blended.outermost = a.outermost; // one framing (a fixed one, or stages framed together)
    else
        blended.blended = {{a.center, a.radius, a.outermost, 1 - u}, {b.center, b.radius, b.outermost, u}};
    return blended;
}

} // namespace

Framing framingOf(const EvaluatedScene& scene, const std::vector<Mat4<double>>& cumulatives, bool withCanonical)
{
    std::vector<Vec3<double>> framed;
    for (const Primitive& primitive : scene.primitives) {
        const bool canonical = primitive.canonical;
        if (canonical && !withCanonical)
            continue;
        for (const Mat4<double>& m : cumulatives)
            appendThrough(framed, primitive, canonical ? Mat4<double>::Identity() : m,
                          !canonical && isProjective(m) ? scene.nearCut : std::nullopt);
    }
    if (framed.empty())
        return {};
    Eigen::AlignedBox<double, 3> box;
    for (const Vec3<double>& p : framed)
        box.extend(p);
    Framing framing{box.center(), std::max(1e-9, 0.5 * box.diagonal().norm()), {}, {}};
    for (const Vec3<double>& p : framed)
        if ((p - framing.center).norm() > kSphereSeen * kEdgeRoom * framing.radius)
            framing.outermost.push_back(p);
    return framing;
}

Framing stageFraming(const EvaluatedScene& scene, int stage)
{
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    const auto [first, last] = framedTogether(stages, stage);
    std::vector<Mat4<double>> positions;
    for (int k = first * kSweepSamples; k <= last * kSweepSamples; ++k)
        positions.push_back(drawnAt(stages, double(k) / kSweepSamples));
    return framingOf(scene, positions, canonicalOpacityAt(stage, stages.size()) > 0);
}

std::optional<Framing> fixedFraming(const EvaluatedScene& scene, bool fixed)
{
    if (!fixed)
        return std::nullopt;
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    std::vector<Mat4<double>> all;
    for (std::size_t k = 0; k <= stages.size(); ++k)
        all.push_back(drawnAt(stages, double(k)));
    return framingOf(scene, all, true);
}

double canonicalOpacityAt(double position, std::size_t stageCount)
{
    return std::clamp(position - (double(stageCount) - 1), 0.0, 1.0);
}

double smoothStep(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

WorldMoment stageAtRest(const EvaluatedScene& scene, int stage, const std::optional<Framing>& fixed)
{
    const std::vector<Stage<double>>& stages = scene.pipeline.stages;
    return {drawnAt(stages, stage), canonicalOpacityAt(stage, stages.size()), ghostAt(stages, stage),
            fixed ? *fixed : stageFraming(scene, stage)};
}

StageShown stageShown(const EvaluatedScene& scene, const WorldMoment& moment)
{
    StageShown shown(scene, moment.drawn, moment.canonicalOpacity);
    shown.ghost = moment.ghost;
    return shown;
}

StageMotion::StageMotion(const EvaluatedScene& scene, int from, int to, const std::optional<Framing>& fixed)
    : stages_(scene.pipeline.stages), from_(from), to_(to)
{
    const std::vector<Stage<double>>& stages = stages_;
    ghost_ = to == from + 1 ? ghostAt(stages, to) : std::nullopt; // where it starts, while it moves
    if (fixed) {
        start_ = sweep_ = end_ = *fixed;
        return;
    }
    start_ = stageFraming(scene, from);
    end_ = stageFraming(scene, to);
    if (framedTogether(stages, from) == framedTogether(stages, to)) {
        sweep_ = start_; // one framing: the motion is seen against it
        return;
    }
    const bool canonical = canonicalOpacityAt(from, stages.size()) > 0 || canonicalOpacityAt(to, stages.size()) > 0;
    std::vector<Mat4<double>> sweep;
    for (int k = 0; k <= kSweepSamples; ++k)
        sweep.push_back(drawnAt(stages, from + (to - from) * double(k) / kSweepSamples));
    sweep_ = framingOf(scene, sweep, canonical);
}

WorldMoment StageMotion::at(double s) const
{
    const std::vector<Stage<double>>& stages = stages_;
    const double motion = smoothStep((s - kWiden) / (1 - kWiden - kSettle));
    const double position = from_ + (to_ - from_) * motion;
    WorldMoment moment{drawnAt(stages, position), canonicalOpacityAt(position, stages.size()), ghost_, sweep_};
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

double fitDistance(const WorldCamera& camera, const Framing& framing, const ViewFit& fit)
{
    // The tangents of the scene area's half angles (where the picture's text leaves room), across and up.
    const double tangent = std::tan(camera.viewAngle * kPi / 360);
    const bool whole = fit.sceneArea.isEmpty() || fit.height <= 0;
    const Vec2<double> extent = whole ? Vec2<double>(fit.height > 0 ? double(fit.width) / fit.height : 1, 1)
                                      : Vec2<double>((fit.sceneArea.max - fit.sceneArea.min) / fit.height);
    const Vec2<double> half = tangent * extent;
    // Most of a sphere seen whole from any direction, in the narrower of the two angles (a point within
    // kSphereSeen * kEdgeRoom of its radius also a marker's room from the edge);
    const double sine = std::sin(std::atan(half.minCoeff()));
    auto sphere = [&](double radius) { return kSphereSeen * radius / sine; };
    // how much further back the outermost points each need the camera, from this direction.
    const Mat4<double> view = camera.view(); // its rows: the picture's across, up and backward
    const Vec3<double> across = view.row(0).head<3>(), up = view.row(1).head<3>(), ahead = -view.row(2).head<3>();
    auto further = [&](const Vec3<double>& center, double radius, const std::vector<Vec3<double>>& outermost) {
        if (across.isZero())
            return 0.0; // no up for the picture (the view up along the direction): the sphere alone
        double needed = 0;
        for (const Vec3<double>& p : outermost) {
            const Vec3<double> offset = p - center;
            needed = std::max(needed, std::max(std::abs(offset.dot(across)) / half.x(), std::abs(offset.dot(up)) / half.y()) /
                                          kEdgeRoom - offset.dot(ahead));
        }
        return std::max(0.0, needed - sphere(radius));
    };
    double distance = sphere(framing.radius) + further(framing.center, framing.radius, framing.outermost);
    for (const Framing::Share& part : framing.blended) // each framing's setting back, by its share: nothing jumps
        distance += part.share * further(part.center, part.radius, part.outermost);
    return distance;
}

void frameOn(WorldCamera& camera, const Framing& framing, const ViewFit& fit)
{
    const Vec3<double> direction = camera.direction();
    const double distance = fit.zoom * fitDistance(camera, framing, fit);
    camera.focalPoint = framing.center + fit.pan * framing.radius;
    camera.position = camera.focalPoint - direction * distance;
    // The focal point at the scene area's center (VTK's window center is the view's center's opposite).
    if (fit.width > 0 && fit.height > 0 && !fit.sceneArea.isEmpty()) {
        const Vec2<double> center = (fit.sceneArea.min + fit.sceneArea.max) / 2;
        camera.windowCenter = Vec2<double>(1 - 2 * center.x() / fit.width, 2 * center.y() / fit.height - 1);
    } else {
        camera.windowCenter.setZero();
    }
    fitClippingRange(camera, framing);
}

double frameReach(const Framing& framing)
{
    return framing.center.norm() + 1.5 * framing.radius;
}

void fitClippingRange(WorldCamera& camera, const Framing& framing)
{
    // Everything framed lies within the framing's sphere; the fixed axes within their reach of the origin.
    const Vec3<double> direction = camera.direction();
    const double reach = frameReach(framing);
    const double along = (framing.center - camera.position).dot(direction), extent = 1.05 * framing.radius;
    const double axesAlong = -camera.position.dot(direction);
    const double nearest = std::min(along - extent, axesAlong - reach);
    const double farthest = std::max(along + extent, axesAlong + reach);
    camera.nearPlane = std::max(nearest, 1e-3 * farthest);
    camera.farPlane = farthest;
}

} // namespace viewpipe
