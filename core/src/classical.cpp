#include "viewpipe/classical.hpp"

#include "viewpipe/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace viewpipe {
namespace {

constexpr double kTolerance = 1e-9;
constexpr double kDegrees = M_PI / 180;

struct Named {
    ClassicalKind kind;
    const char* name;
};

const Named kNames[] = {{ClassicalKind::Front, "front"},         {ClassicalKind::Top, "top"},
                        {ClassicalKind::Side, "side"},           {ClassicalKind::Isometric, "isometric"},
                        {ClassicalKind::Dimetric, "dimetric"},   {ClassicalKind::Trimetric, "trimetric"},
                        {ClassicalKind::Cavalier, "cavalier"},   {ClassicalKind::Cabinet, "cabinet"},
                        {ClassicalKind::Oblique, "oblique"},     {ClassicalKind::OnePoint, "one-point"},
                        {ClassicalKind::TwoPoint, "two-point"},  {ClassicalKind::ThreePoint, "three-point"}};

bool near(double a, double b)
{
    return std::abs(a - b) <= kTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

std::string fixed(double x, int decimals)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
    return buffer;
}

// A window around the box's projection onto the view plane, with a margin.
foley::Window<double> windowAround(const foley::ViewSpec<double>& spec, const Vec3<double>& lo, const Vec3<double>& hi)
{
    const Basis<double> b = foley::vrcBasis(spec);
    const Vec3<double> dop = foley::directionOfProjection(spec);
    double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
    for (int k = 0; k < 8; ++k) {
        const Vec3<double> corner(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
        const Vec3<double> d = corner - spec.vrp;
        Vec3<double> vrc(d.dot(b.u), d.dot(b.v), d.dot(b.n));
        if (spec.projection == foley::Projection::Parallel) // along the projectors onto n = 0
            vrc -= (vrc.z() / dop.z()) * dop;
        else // through the PRP onto n = 0
            vrc = spec.prp + (spec.prp.z() / (spec.prp.z() - vrc.z())) * (vrc - spec.prp);
        umin = std::min(umin, vrc.x()), umax = std::max(umax, vrc.x());
        vmin = std::min(vmin, vrc.y()), vmax = std::max(vmax, vrc.y());
    }
    // Square, centered, 15% margin: the same frame for every kind.
    const double half = 0.575 * std::max(umax - umin, vmax - vmin);
    const double cu = (umin + umax) / 2, cv = (vmin + vmax) / 2;
    return {cu - half, cu + half, cv - half, cv + half};
}

} // namespace

std::string classicalName(ClassicalKind kind)
{
    for (const Named& n : kNames)
        if (n.kind == kind)
            return n.name;
    return "";
}

std::optional<ClassicalKind> classicalKindNamed(const std::string& name)
{
    for (const Named& n : kNames)
        if (name == n.name)
            return n.kind;
    return std::nullopt;
}

const std::vector<ClassicalKind>& allClassicalKinds()
{
    static const std::vector<ClassicalKind> kinds = [] {
        std::vector<ClassicalKind> out;
        for (const Named& n : kNames)
            out.push_back(n.kind);
        return out;
    }();
    return kinds;
}

foley::ViewSpec<double> classicalView(ClassicalKind kind, const Vec3<double>& boxMin, const Vec3<double>& boxMax,
                                      const ClassicalParameters& parameters)
{
    const Vec3<double> center = (boxMin + boxMax) / 2;
    const double size = (boxMax - boxMin).norm();
    foley::ViewSpec<double> spec;
    spec.vrp = center;
    spec.vup = {0, 1, 0};
    spec.projection = foley::Projection::Parallel;
    Vec3<double> dopOnSheet = Vec3<double>::Zero(); // oblique: the projectors' (u, v) per unit of n
    auto direction = [](double azimuth, double elevation) {
        const double a = azimuth * kDegrees, e = elevation * kDegrees;
        return Vec3<double>(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    };
    switch (kind) {
    case ClassicalKind::Front: spec.vpn = {0, 0, 1}; break;
    case ClassicalKind::Top: spec.vpn = {0, 1, 0}, spec.vup = {0, 0, -1}; break;
    case ClassicalKind::Side: spec.vpn = {1, 0, 0}; break;
    case ClassicalKind::Isometric: spec.vpn = {1, 1, 1}; break;
    case ClassicalKind::Dimetric: spec.vpn = direction(45, parameters.elevationDegrees.value_or(20)); break;
    case ClassicalKind::Trimetric:
        spec.vpn = direction(parameters.azimuthDegrees.value_or(30), parameters.elevationDegrees.value_or(25));
        break;
    case ClassicalKind::Cavalier:
    case ClassicalKind::Cabinet:
    case ClassicalKind::Oblique: {
        spec.vpn = {0, 0, 1};
        const double receding = kind == ClassicalKind::Cavalier ? 1 : kind == ClassicalKind::Cabinet ? 0.5 : parameters.receding;
        if (!(receding > 0))
            throw InputError("receding", "must be greater than 0 (got " + formatNumber(receding) + ")");
        const double angle = parameters.angleDegrees * kDegrees;
        // A point one unit behind the plane (n = -1) lands receding * (cos, sin) away.
        dopOnSheet = Vec3<double>(-receding * std::cos(angle), -receding * std::sin(angle), -1);
        break;
    }
    case ClassicalKind::OnePoint: spec.vpn = {0, 0, 1}, spec.projection = foley::Projection::Perspective; break;
    case ClassicalKind::TwoPoint: spec.vpn = direction(35, 0), spec.projection = foley::Projection::Perspective; break;
    case ClassicalKind::ThreePoint: spec.vpn = direction(35, 30), spec.projection = foley::Projection::Perspective; break;
    }
    const bool axonometric =
        kind == ClassicalKind::Isometric || kind == ClassicalKind::Dimetric || kind == ClassicalKind::Trimetric;
    if (axonometric && parameters.foreshortening) {
        // Axis i is foreshortened by sqrt(1 - n_i^2): n follows from the ratios.
        const auto& f = *parameters.foreshortening;
        double squares = 0;
        for (int i = 0; i < 3; ++i) {
            if (!(f[std::size_t(i)] > 0 && f[std::size_t(i)] <= 1))
                throw InputError("foreshortening[" + std::to_string(i) + "]", "must lie in (0, 1]");
            squares += f[std::size_t(i)] * f[std::size_t(i)];
            spec.vpn[i] = std::sqrt(1 - f[std::size_t(i)] * f[std::size_t(i)]);
        }
        if (std::abs(squares - 2) > 1e-6)
            throw InputError("foreshortening", "the squares of the three ratios must sum to 2 (they sum to " +
                                                   formatNumber(squares) + ")");
    }
    spec.vpn.normalize();
    spec.front = 0.6 * size;
    spec.back = -0.6 * size;
    if (spec.projection == foley::Projection::Parallel) {
        const Vec3<double> dop = dopOnSheet.isZero() ? Vec3<double>(0, 0, -1) : dopOnSheet;
        spec.prp = -2 * size * dop; // CW is (0, 0) until the window is placed
    } else {
        spec.prp = {0, 0, 2.2 * size};
    }
    spec.window = {-1, 1, -1, 1};
    spec.window = windowAround(spec, boxMin, boxMax);
    // Keep the DOP: the PRP moves with the window's center.
    spec.prp.x() += spec.window.centerU();
    spec.prp.y() += spec.window.centerV();
    if (spec.projection == foley::Projection::Perspective)
        spec.window = windowAround(spec, boxMin, boxMax);
    foley::validate(spec);
    return spec;
}

std::optional<VanishingPoint> vanishingPoint(const CameraSpec<double>& camera, int axis)
{
    const Pipeline<double> p = buildPipeline(camera);
    const ViewSetup<double> setup = viewSetup(camera);
    if (!setup.perspective)
        return std::nullopt;
    Vec4<double> direction = Vec4<double>::Zero();
    direction[axis] = 1;
    const double along = setup.axes.n[axis];
    if (std::abs(along) <= kTolerance)
        return std::nullopt; // parallel to the view plane: the lines stay parallel
    // Where the line from the center of projection along the axis meets the
    // window's plane (Foley: the view plane; OpenGL: the near plane).
    const Vec3<double> planePoint = setup.windowCenter;
    const double t = (planePoint - setup.prp).dot(setup.axes.n) / along;
    VanishingPoint vp;
    vp.axis = axis;
    vp.world = setup.prp + t * Vec3<double>::Unit(axis);
    const Vec4<double> h = p.clipMatrix() * direction;
    vp.image = h.head<3>() / h.w();
    return vp;
}

Classification classify(const CameraSpec<double>& camera)
{
    const ViewSetup<double> setup = viewSetup(camera);
    const Vec3<double>& n = setup.axes.n;
    Classification c;
    int alongAxes = 0; // principal axes not parallel to the view plane
    for (int i = 0; i < 3; ++i)
        alongAxes += std::abs(n[i]) > kTolerance;
    if (setup.perspective) {
        c.projection = ProjectionKind::Perspective;
        c.family = "perspective";
        static const char* counts[] = {"", "one-point", "two-point", "three-point"};
        c.kind = counts[alongAxes];
        for (int axis = 0; axis < 3; ++axis)
            if (const auto vp = vanishingPoint(camera, axis))
                c.vanishingPoints.push_back(*vp);
        c.description = "perspective, " + c.kind;
        return c;
    }
    c.projection = ProjectionKind::Parallel;
    // The direction of projection in world coordinates, and each axis's drawn length.
    Vec3<double> dop = setup.windowCenter - setup.prp;
    if (const auto* spec = std::get_if<foley::ViewSpec<double>>(&camera)) {
        const Vec3<double> d = foley::directionOfProjection(*spec); // in VRC
        dop = d.x() * setup.axes.u + d.y() * setup.axes.v + d.z() * setup.axes.n;
    }
    std::array<double, 3> ratios;
    for (int i = 0; i < 3; ++i) {
        const Vec3<double> e = Vec3<double>::Unit(i);
        const Vec3<double> onPlane = e - (e.dot(n) / dop.dot(n)) * dop;
        ratios[std::size_t(i)] = onPlane.norm();
    }
    c.foreshortening = ratios;
    const Vec3<double> dopUnit = dop.normalized();
    const bool orthographic = std::abs(std::abs(dopUnit.dot(n)) - 1) <= kTolerance;
    if (orthographic) {
        if (alongAxes == 1) {
            c.family = "multiview orthographic";
            c.kind = std::abs(n.z()) > kTolerance ? "front" : std::abs(n.y()) > kTolerance ? "top" : "side";
        } else {
            c.family = "axonometric";
            const int equalPairs = near(ratios[0], ratios[1]) + near(ratios[1], ratios[2]) + near(ratios[0], ratios[2]);
            c.kind = equalPairs == 3 ? "isometric" : equalPairs == 1 ? "dimetric" : "trimetric";
        }
        c.description = "parallel, " + c.family + ", " + c.kind;
    } else {
        c.family = "oblique";
        const double sine = std::abs(dopUnit.dot(n));
        c.alphaDegrees = std::asin(sine) / kDegrees;
        if (alongAxes == 1) {
            const int receding = std::abs(n.x()) > kTolerance ? 0 : std::abs(n.y()) > kTolerance ? 1 : 2;
            const double factor = ratios[std::size_t(receding)];
            c.kind = near(factor, 1) ? "cavalier" : near(factor, 0.5) ? "cabinet" : "general";
        } else {
            c.kind = "general";
        }
        c.description = "parallel, oblique, " + c.kind + " (alpha = " + fixed(*c.alphaDegrees, 2) + " deg)";
    }
    return c;
}

} // namespace viewpipe
