// The classical projections of seed 001 against their defining properties
// and published matrices.

#include "support.hpp"
#include "viewpipe/classical.hpp"

namespace viewpipe {
namespace {

const Vec3<double> kCubeMin(-5, -5, -5), kCubeMax(5, 5, 5);

Classification classified(ClassicalKind kind, const ClassicalParameters& p = {})
{
    return classify(CameraSpec<double>(classicalView(kind, kCubeMin, kCubeMax, p)));
}

// The picture (x, y after N and the divide) of a world point.
Vec2<double> picture(const foley::ViewSpec<double>& spec, const Vec3<double>& p)
{
    const Pipeline<double> pipeline = buildPipeline(spec);
    const Vec4<double> h = pipeline.clipMatrix() * p.homogeneous();
    return h.head<2>() / h.w();
}

TEST(Classical, EveryKindIsNamedBack)
{
    for (ClassicalKind kind : allClassicalKinds()) {
        const Classification c = classified(kind);
        const std::string expected = kind == ClassicalKind::Oblique ? "cavalier" : classicalName(kind); // default receding 1
        EXPECT_EQ(c.kind, expected) << classicalName(kind) << ": " << c.description;
        EXPECT_EQ(classicalKindNamed(classicalName(kind)), kind);
    }
    EXPECT_EQ(classified(ClassicalKind::Oblique, {{}, {}, {}, 0.7, 30}).kind, "general");
}

TEST(Classical, IsometricForeshortensAllAxesBySqrtTwoThirds)
{
    const Classification c = classified(ClassicalKind::Isometric);
    EXPECT_EQ(c.description, "parallel, axonometric, isometric");
    for (double f : *c.foreshortening)
        EXPECT_NEAR(f, std::sqrt(2.0 / 3), 1e-12);
}

TEST(Classical, DimetricHasTwoEqualRatiosTrimetricNone)
{
    const auto d = *classified(ClassicalKind::Dimetric).foreshortening;
    EXPECT_NEAR(d[0], d[2], 1e-12);
    EXPECT_GT(std::abs(d[0] - d[1]), 1e-3);
    const auto t = *classified(ClassicalKind::Trimetric).foreshortening;
    EXPECT_GT(std::abs(t[0] - t[1]), 1e-3);
    EXPECT_GT(std::abs(t[1] - t[2]), 1e-3);
    EXPECT_GT(std::abs(t[0] - t[2]), 1e-3);
    // Orthographic: the squares of the three ratios sum to 2.
    for (const auto& f : {d, t})
        EXPECT_NEAR(f[0] * f[0] + f[1] * f[1] + f[2] * f[2], 2, 1e-12);
    // From ratios: (0.9, 0.9, sqrt(2 - 1.62)) is dimetric with exactly those ratios.
    ClassicalParameters p;
    p.foreshortening = std::array<double, 3>{0.9, 0.9, std::sqrt(2 - 1.62)};
    const auto r = *classified(ClassicalKind::Dimetric, p).foreshortening;
    EXPECT_NEAR(r[0], 0.9, 1e-12);
    EXPECT_NEAR(r[2], std::sqrt(0.38), 1e-12);
    p.foreshortening = std::array<double, 3>{0.9, 0.9, 0.9};
    test::expectRefused([&] { classicalView(ClassicalKind::Dimetric, kCubeMin, kCubeMax, p); }, "foreshortening",
                        "sum to 2");
}

TEST(Classical, CavalierKeepsRecedingLengthsCabinetHalvesThem)
{
    const Classification cavalier = classified(ClassicalKind::Cavalier);
    EXPECT_NEAR((*cavalier.foreshortening)[2], 1, 1e-12);
    EXPECT_NEAR(*cavalier.alphaDegrees, 45, 1e-9);
    const Classification cabinet = classified(ClassicalKind::Cabinet);
    EXPECT_NEAR((*cabinet.foreshortening)[2], 0.5, 1e-12);
    EXPECT_NEAR(*cabinet.alphaDegrees, std::atan(2.0) * 180 / M_PI, 1e-9); // 63.43 degrees
    EXPECT_EQ(cabinet.description, "parallel, oblique, cabinet (alpha = 63.43 deg)");
    for (const Classification& c : {cavalier, cabinet}) {
        EXPECT_NEAR((*c.foreshortening)[0], 1, 1e-12); // the front face is true
        EXPECT_NEAR((*c.foreshortening)[1], 1, 1e-12);
    }
}

// Oblique views keep angles in planes parallel to the view plane: a 30-degree
// angle drawn in the plane z = 3 comes out as 30 degrees, and a square as a square.
TEST(Classical, ObliqueKeepsAnglesInPlanesParallelToTheViewPlane)
{
    for (ClassicalKind kind : {ClassicalKind::Cavalier, ClassicalKind::Cabinet, ClassicalKind::Oblique}) {
        const foley::ViewSpec<double> spec = classicalView(kind, kCubeMin, kCubeMax, {{}, {}, {}, 0.8, 20});
        const Vec2<double> o = picture(spec, {0, 0, 3});
        const Vec2<double> a = picture(spec, {2, 0, 3}) - o;
        const Vec2<double> b = picture(spec, {2 * std::cos(M_PI / 6), 2 * std::sin(M_PI / 6), 3}) - o;
        EXPECT_NEAR(std::acos(a.normalized().dot(b.normalized())), M_PI / 6, 1e-12) << classicalName(kind);
        const Vec2<double> c = picture(spec, {0, 2, 3}) - o;
        EXPECT_NEAR(a.norm(), c.norm(), 1e-12);
        EXPECT_NEAR(a.dot(c), 0, 1e-12);
    }
}

TEST(Classical, CubeHasOneTwoAndThreeFiniteVanishingPoints)
{
    EXPECT_EQ(classified(ClassicalKind::OnePoint).vanishingPoints.size(), 1u);
    EXPECT_EQ(classified(ClassicalKind::TwoPoint).vanishingPoints.size(), 2u);
    EXPECT_EQ(classified(ClassicalKind::ThreePoint).vanishingPoints.size(), 3u);
    EXPECT_EQ(classified(ClassicalKind::Isometric).vanishingPoints.size(), 0u); // parallel: none

    // The images of a cube's parallel edges, extended, meet at the vanishing point.
    const foley::ViewSpec<double> spec = classicalView(ClassicalKind::ThreePoint, kCubeMin, kCubeMax);
    for (const VanishingPoint& vp : classify(CameraSpec<double>(spec)).vanishingPoints) {
        const Vec3<double> d = Vec3<double>::Unit(vp.axis);
        for (const Vec3<double>& start : {Vec3<double>(-5, -5, -5), Vec3<double>(5, 5, -5), Vec3<double>(-5, 5, 5)}) {
            const Vec2<double> p = picture(spec, start), q = picture(spec, start + 10 * d);
            const Vec2<double> r = vp.image.head<2>() - p;
            const Vec2<double> e = q - p;
            EXPECT_NEAR((e.x() * r.y() - e.y() * r.x()) / (e.norm() * r.norm()), 0, 1e-9) << vp.axis;
        }
    }
}

// Multiview views are the axis-aligned orthographic projections: the picture
// ignores the coordinate along the viewing axis.
TEST(Classical, MultiviewDropsTheViewingAxis)
{
    const std::array<std::pair<ClassicalKind, int>, 3> views = {
        {{ClassicalKind::Front, 2}, {ClassicalKind::Top, 1}, {ClassicalKind::Side, 0}}};
    for (const auto& [kind, dropped] : views) {
        const foley::ViewSpec<double> spec = classicalView(kind, kCubeMin, kCubeMax);
        Vec3<double> p(1, 2, 3), q = p;
        q[dropped] += 4;
        EXPECT_LE((picture(spec, p) - picture(spec, q)).norm(), 1e-14) << classicalName(kind);
        Vec3<double> r = p;
        r[(dropped + 1) % 3] += 4;
        EXPECT_GT((picture(spec, p) - picture(spec, r)).norm(), 0.1);
    }
}

// Wikipedia, "Isometric projection", section "Mathematics": the rotation
// 1/sqrt(6) [[sqrt3, 0, -sqrt3], [1, 2, 1], [sqrt2, -sqrt2, sqrt2]]. Its rows
// are a right-handed view frame with n = (1, -1, 1)/sqrt3 and up y: Foley's
// R for VPN (1, -1, 1), VUP (0, 1, 0) is that matrix.
TEST(Classical, PublishedIsometricMatrix)
{
    foley::ViewSpec<double> spec = classicalView(ClassicalKind::Isometric, kCubeMin, kCubeMax);
    spec.vpn = {1, -1, 1};
    const Mat3<double> r = foley::vrcBasis(spec).rotation();
    Mat3<double> published;
    published << std::sqrt(3.0), 0, -std::sqrt(3.0), 1, 2, 1, std::sqrt(2.0), -std::sqrt(2.0), std::sqrt(2.0);
    published /= std::sqrt(6.0);
    EXPECT_TRUE(r.isApprox(published, 1e-15)) << r;
}

// Wikipedia, "Oblique projection", cabinet projection: x' = x + (1/2) z cos a,
// y' = y + (1/2) z sin a, with z pointing into the picture. Ours has z toward
// the viewer, so the picture is (x - z/2 cos a, y - z/2 sin a), up to the
// window's scale and offset.
TEST(Classical, PublishedCabinetMatrix)
{
    for (double angle : {30.0, 45.0, 63.0}) {
        const foley::ViewSpec<double> spec = classicalView(ClassicalKind::Cabinet, kCubeMin, kCubeMax, {{}, {}, {}, 1, angle});
        const Mat4<double> n = buildPipeline(spec).composite;
        const double scale = n(0, 0), a = angle * M_PI / 180;
        EXPECT_NEAR(n(1, 1), scale, 1e-15);
        EXPECT_NEAR(n(0, 1), 0, 1e-15);
        EXPECT_NEAR(n(0, 2) / scale, -0.5 * std::cos(a), 1e-14);
        EXPECT_NEAR(n(1, 2) / scale, -0.5 * std::sin(a), 1e-14);
    }
}

} // namespace
} // namespace viewpipe
