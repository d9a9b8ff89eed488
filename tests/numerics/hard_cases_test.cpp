// Hard cases, table-driven: each states its expected behaviour, accurate
// within a bound in units of the type's epsilon (measured against MPFR-256),
// or refused with a named reason. The figures are printed for
// docs/numerics.md.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <tuple>

#include "support.hpp"
#include "viewpipe/accuracy.hpp"

namespace viewpipe {
namespace {

using test::eps;

foley::ViewSpec<double> house()
{
    return {foley::Projection::Perspective, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {8, 6, 84}, {-50, 50, -50, 50}, 60, 25};
}

template <class T> const char* typeName()
{
    return std::is_same_v<T, float> ? "float" : std::is_same_v<T, double> ? "double" : "long double";
}

struct Measured {
    AccuracyMetrics errors;
    double epsilon;
};

template <class T> Measured measure(const CameraSpec<double>& camera, const std::vector<Vec3<double>>& vertices = {})
{
    const ReferenceSolution ref = makeReference(camera, 256, 64);
    return {measureAccuracy<T>(camera, vertices, ref, {}), double(eps<T>())};
}

void report(const char* label, const Measured& m)
{
    std::printf("[figure] %-58s corner %.2g eps, entries %.2g eps, |RR^T-I| %.2g eps, round trip %.2g eps, NDC %.2g\n",
                label, m.errors.cornerError / m.epsilon, m.errors.maxRelativeError / m.epsilon,
                m.errors.orthogonalityError / m.epsilon, m.errors.roundtripError / m.epsilon, m.errors.ndcMaxError);
}

// A case: a camera, and either the bound its canonical corners must meet (in
// units of epsilon, in double) or the field and reason of its refusal.
struct Case {
    const char* name;
    std::function<CameraSpec<double>()> camera;
    double cornerBoundEps;      // accurate: canonical-corner error bound, units of double's epsilon
    const char* refusedField;   // refused: the field named
    const char* refusedReason;  // and part of the reason
};

foley::ViewSpec<double> with(std::function<void(foley::ViewSpec<double>&)> edit)
{
    foley::ViewSpec<double> s = house();
    edit(s);
    return s;
}

// The scene data/scenes/apis/vulkan-reversed-infinite.json's camera.
gl::Camera<double> reversedInfinite()
{
    return {{{40, 30, 100}, {8, 8, 42}, {0, 1, 0}},
            gl::Perspective<double>{40, 1.5, 30, std::numeric_limits<double>::infinity()},
            gl::Api::Vulkan,
            gl::Handedness::Right,
            gl::DepthMode::Reversed};
}

const std::vector<Case>& cases()
{
    using S = foley::ViewSpec<double>;
    static const std::vector<Case> table = {
        {"1. VUP exactly parallel to VPN", [] { return CameraSpec<double>(with([](S& s) { s.vup = {0, 0, 5}; })); }, 0,
         "view.vup", "is parallel to view.vpn (angle 0 degrees"},
        {"1. VUP exactly anti-parallel to VPN (tilted VPN)",
         [] { return CameraSpec<double>(with([](S& s) { s.vpn = {1, 2, 3}, s.vup = {-2, -4, -6}; })); }, 0, "view.vup",
         "is parallel to view.vpn (angle 0 degrees"},
        {"4. back/front distance ratio 1e4",
         [] { return CameraSpec<double>(with([](S& s) { s.prp = {0, 0, 1}, s.front = 0, s.back = -1e4 + 1; })); }, 8,
         nullptr, nullptr},
        {"4. back/front distance ratio 1e8",
         [] { return CameraSpec<double>(with([](S& s) { s.prp = {0, 0, 1}, s.front = 0, s.back = -1e8 + 1; })); }, 8,
         nullptr, nullptr},
        {"5. PRP 1e-12 from the view plane",
         [] { return CameraSpec<double>(with([](S& s) { s.prp = {0, 0, 1e-12}, s.front = 0, s.back = -1; })); }, 8,
         nullptr, nullptr},
        {"5. F within 1e-12 (relative) of PRP_n",
         [] { return CameraSpec<double>(with([](S& s) { s.prp = {0, 0, 1}, s.front = 1 - 1e-12, s.back = -1; })); },
         8, nullptr, nullptr},
        {"5. F within 1e-12 of B (z_min near -1)",
         [] { return CameraSpec<double>(with([](S& s) { s.front = 25 + 1e-12; })); }, 8, nullptr, nullptr},
        {"5. F = B", [] { return CameraSpec<double>(with([](S& s) { s.front = 25; })); }, 0, "view.front",
         "must be greater than B"},
        {"5. PRP on the view plane", [] { return CameraSpec<double>(with([](S& s) { s.prp = {8, 6, 0}; })); }, 0,
         "view.prp", "lies on the view plane"},
        {"5. PRP not beyond F", [] { return CameraSpec<double>(with([](S& s) { s.prp = {8, 6, 60}; })); }, 0,
         "view.prp", "must exceed the front plane"},
        {"6. extreme oblique shear: window [-1,1]^2, PRP (1e3, -1e3, 1)",
         [] {
             return CameraSpec<double>(with([](S& s) { s.window = {-1, 1, -1, 1}, s.prp = {1e3, -1e3, 1}, s.front = 0.5, s.back = -1; }));
         },
         8, nullptr, nullptr},
        {"9. GL near = far",
         [] { return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, gl::Frustum<double>{-1, 1, -1, 1, 2, 2}}); },
         0, "camera.projection.far", "equals near"},
        {"9. GL near <= 0",
         [] { return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, gl::Perspective<double>{60, 1, 0, 10}}); },
         0, "camera.projection.near", "greater than 0"},
        {"9. GL aspect 0",
         [] { return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, gl::Perspective<double>{60, 0, 1, 10}}); },
         0, "camera.projection.aspect", "greater than 0"},
        {"9. GL aspect negative",
         [] { return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, gl::Perspective<double>{60, -2, 1, 10}}); },
         0, "camera.projection.aspect", "greater than 0"},
        {"9. GL aspect NaN",
         [] {
             return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}},
                                                          gl::Perspective<double>{60, std::nan(""), 1, 10}});
         },
         0, "camera.projection.aspect", "finite"},
        {"9. GL fovy 1e-9 degrees",
         [] { return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}}, gl::Perspective<double>{1e-9, 1.5, 1, 10}}); },
         8, nullptr, nullptr},
        {"9. GL far at infinity, Vulkan reversed depth (measured up to far = 1000 near)",
         [] { return CameraSpec<double>(reversedInfinite()); }, 8, nullptr, nullptr},
        {"9. GL fovy 180 - 1e-9 degrees",
         [] {
             return CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}},
                                                          gl::Perspective<double>{180 - 1e-9, 1.5, 1, 10}});
         },
         8, nullptr, nullptr},
    };
    return table;
}

class HardCase : public ::testing::TestWithParam<std::size_t> {};

TEST_P(HardCase, BehavesAsStated)
{
    const Case& c = cases()[GetParam()];
    SCOPED_TRACE(c.name);
    if (c.refusedField) {
        test::expectRefused([&] { buildPipeline(c.camera()); }, c.refusedField, c.refusedReason);
        try {
            buildPipeline(c.camera());
        } catch (const InputError& e) {
            std::printf("[figure] %-58s refused: %s\n", c.name, e.what());
        }
        return;
    }
    const Measured m = measure<double>(c.camera());
    report(c.name, m);
    EXPECT_LE(m.errors.cornerError / m.epsilon, c.cornerBoundEps);
    EXPECT_LE(m.errors.orthogonalityError / m.epsilon, 4);
    const Pipeline<double> p = buildPipeline(c.camera());
    EXPECT_TRUE(p.composite.allFinite());
}

INSTANTIATE_TEST_SUITE_P(Table, HardCase, ::testing::Range<std::size_t>(0, cases().size()));

// 9. No far face: the volume measured ends at 1000 times near. Its near corners
// go to the API's near depth, its stand-in far ones to the depth an infinite
// far plane gives at distance d = 1000 n: Vulkan reversed, n / d = 1/1000;
// OpenGL, 1 - 2n / d = 0.998 (gluPerspective's limit: C = -1, D = -2n).
TEST(InfiniteFar, MeasuredUpToAStandInFarPlane)
{
    gl::Camera<double> opengl = reversedInfinite();
    opengl.api = gl::Api::OpenGL;
    opengl.depth = gl::DepthMode::Standard;
    for (const auto& [camera, nearDepth, standInDepth] :
         {std::tuple{reversedInfinite(), 1.0, 1e-3}, std::tuple{opengl, -1.0, 0.998}}) {
        const ReferenceSolution ref = makeReference(CameraSpec<double>(camera), 256, 16);
        EXPECT_TRUE(ref.farStandIn);
        for (std::size_t k = 0; k < 8; ++k) {
            SCOPED_TRACE(k);
            EXPECT_NEAR(static_cast<double>(ref.canonical[k].z()), k < 4 ? nearDepth : standInDepth, 1e-15);
            EXPECT_NEAR(std::abs(static_cast<double>(ref.canonical[k].x())), 1.0, 1e-15); // on the frustum's sides
            EXPECT_NEAR(std::abs(static_cast<double>(ref.canonical[k].y())), 1.0, 1e-15);
        }
    }
    EXPECT_FALSE(makeReference(CameraSpec<double>(gl::Camera<double>{{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}},
                                                                     gl::Perspective<double>{60, 1, 1, 10}}),
                               256, 16)
                     .farStandIn);
}

// 2. VUP nearly parallel to VPN, not axis-aligned: R orthonormal within 4 eps at
// every angle accepted; refused below 16 eps radians.
template <class T> class NearlyParallelUp : public ::testing::Test {};
TYPED_TEST_SUITE(NearlyParallelUp, test::ScalarTypes);

TYPED_TEST(NearlyParallelUp, OrthonormalOrRefused)
{
    using T = TypeParam;
    const Vec3<double> up = Vec3<double>(1, 2, 3).normalized();
    const Vec3<double> axis = up.cross(Vec3<double>(0, 0, 1)).normalized();
    for (double theta = 1e-2; theta >= 1e-12; theta /= 10) {
        foley::ViewSpec<double> s = house();
        s.vup = up;
        s.vpn = Eigen::AngleAxis<double>(theta, axis) * up;
        const foley::ViewSpec<T> typed = s.template cast<T>();
        const T angle = angleBetweenLines(typed.vup, typed.vpn);
        if (angle < minUpAngle<T>()) {
            test::expectRefused([&] { buildPipeline(typed); }, "view.vup", "is parallel to view.vpn");
            std::printf("[figure] 2. theta %-8.0e in %-12s refused (below 16 eps = %.2g rad)\n", theta,
                        typeName<T>(), double(minUpAngle<T>()));
            continue;
        }
        const Measured m = measure<T>(CameraSpec<double>(s));
        char label[96];
        std::snprintf(label, sizeof label, "2. theta %.0e, %s", theta, typeName<T>());
        report(label, m);
        EXPECT_LE(m.errors.orthogonalityError / m.epsilon, 4) << theta;
        EXPECT_LE(m.errors.determinantError / m.epsilon, 4) << theta;
    }
}

// 3. VRP far from the origin with the scene within 1 unit of it: double is
// accurate; float is not when evaluated naively in world coordinates, and is
// when the view is made camera-relative (the translation applied in double).
TEST(FarFromOrigin, DoubleAccurateFloatNeedsCameraRelative)
{
    foley::ViewSpec<double> s;
    s.projection = foley::Projection::Perspective;
    s.vrp = {6.4e6, -2e7, 3e6};
    s.vpn = {0.3, 0.4, 0.866};
    s.vup = {0, 1, 0};
    s.prp = {0, 0, 4};
    s.window = {-1, 1, -1, 1};
    s.front = 0.5;
    s.back = -2;
    std::vector<Vec3<double>> vertices;
    test::SpecGenerator random(5);
    for (int i = 0; i < 200; ++i)
        vertices.push_back(s.vrp + Vec3<double>(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)) *
                                       0.3);
    const CameraSpec<double> camera = s;
    const ReferenceSolution ref = makeReference(camera, 256, 16);
    const AccuracyMetrics d = measureAccuracy<double>(camera, vertices, ref, {});
    const AccuracyMetrics naive = measureAccuracy<float>(camera, vertices, ref, {});

    // Camera-relative float: N = N_rest * T(-VRP); N_rest = N * T(VRP) and
    // p - VRP formed in double, the rest in float.
    const Pipeline<double> p = buildPipeline(camera);
    const Mat4<double> clip = p.clipMatrix() * translation<double>(s.vrp);
    const Mat4<float> rest = clip.cast<float>();
    std::vector<float> in, out(3 * vertices.size());
    for (const Vec3<double>& v : vertices) {
        const Vec3<double> r = v - s.vrp;
        in.insert(in.end(), {float(r.x()), float(r.y()), float(r.z())});
    }
    transformPoints(rest, in.data(), out.data(), vertices.size());
    setReferenceBits(256);
    double relative = 0;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec4<Reference> h = ref.clip * Vec4<Reference>(Reference(vertices[i].x()), Reference(vertices[i].y()),
                                                             Reference(vertices[i].z()), 1);
        for (int a = 0; a < 2; ++a)
            relative = std::max(relative, std::abs(double(out[3 * i + std::size_t(a)]) - static_cast<double>(h[a] / h.w())));
    }
    std::printf("[figure] 3. far VRP: NDC error double %.2g, float naive %.2g, float camera-relative %.2g\n",
                d.ndcMaxError, naive.ndcMaxError, relative);
    EXPECT_LE(d.ndcMaxError, 1e-8);
    EXPECT_GT(naive.ndcMaxError, 1e-2); // naive float loses the scene entirely
    EXPECT_LE(relative, 1e-5);          // camera-relative float keeps it to a few float eps
}

// 7. Scale invariance: the whole scene scaled by 1e+-20 in float or 1e+-150 in
// double gives the same canonical corners (no overflow or underflow in norms).
template <class T> void expectScaleInvariant(double factor)
{
    foley::ViewSpec<double> s = house();
    s.vpn = {0.3, -0.2, 1};
    s.vup = {0.1, 1, 0.2};
    s.vrp = {3, 4, 5};
    auto scaled = s;
    scaled.vrp *= factor;
    scaled.prp *= factor;
    scaled.window = {s.window.umin * factor, s.window.umax * factor, s.window.vmin * factor, s.window.vmax * factor};
    scaled.front *= factor;
    scaled.back *= factor;
    const foley::ViewSpec<T> typed = scaled.cast<T>();
    const Pipeline<T> p = buildPipeline(typed);
    const auto corners = foley::viewVolumeCorners(typed);
    const auto canonical = foley::canonicalCorners(typed);
    double worst = 0;
    for (std::size_t k = 0; k < 8; ++k) {
        const Vec4<T> image = p.composite * corners[k].homogeneous();
        for (int a = 0; a < 3; ++a)
            worst = std::max(worst, double(std::abs(image[a] - canonical[k][a])));
    }
    std::printf("[figure] 7. scale %-8.0e %-12s corner error %.2g eps\n", factor, typeName<T>(),
                worst / double(eps<T>()));
    EXPECT_TRUE(p.composite.allFinite());
    EXPECT_LE(worst, 64 * double(eps<T>())) << factor;
}

TEST(ScaleInvariance, FloatAt1ePlusMinus20)
{
    expectScaleInvariant<float>(1e20);
    expectScaleInvariant<float>(1e-20);
}

TEST(ScaleInvariance, DoubleAt1ePlusMinus150)
{
    expectScaleInvariant<double>(1e150);
    expectScaleInvariant<double>(1e-150);
}

// 8. Points behind the eye (w < 0) and on the eye plane (w = 0) are outside,
// decided without dividing.
TEST(BehindTheEye, ClassifiedOutsideWithoutDividing)
{
    const Pipeline<double> p = buildPipeline(house());
    const PointTrace<double> onPlane = tracePoint(p, Vec3<double>(8, 6, 84)); // the PRP: w = 0
    EXPECT_EQ(onPlane.clip.w(), 0);
    EXPECT_FALSE(onPlane.inside);
    EXPECT_FALSE(onPlane.divided.has_value());
    // Mirror of an inside point through the PRP: x/w, y/w would look inside.
    const PointTrace<double> behind = tracePoint(p, Vec3<double>(2 * 8 - 8, 2 * 6 - 6, 2 * 84 - 40));
    EXPECT_LT(behind.clip.w(), 0);
    EXPECT_FALSE(behind.inside);
    const gl::Camera<double> camera{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{90, 1, 1, 10}};
    const PointTrace<double> glBehind = tracePoint(buildPipeline(camera), Vec3<double>(0, 0, 5));
    EXPECT_LT(glBehind.clip.w(), 0);
    EXPECT_FALSE(glBehind.inside);
}

// 9. far = infinity: the infinite projection's exact limit, no NaN, and the
// limit of far -> infinity.
TEST(InfiniteFar, ExactLimit)
{
    const double inf = std::numeric_limits<double>::infinity();
    const Mat4<double> m = gl::perspective<double>({60, 1.5, 0.1, inf});
    EXPECT_TRUE(m.allFinite());
    EXPECT_EQ(m(2, 2), -1);
    EXPECT_EQ(m(2, 3), -0.2);
    const Mat4<double> far = gl::perspective<double>({60, 1.5, 0.1, 1e300});
    EXPECT_TRUE(far.isApprox(m, 1e-15));
    const PointTrace<double> t =
        tracePoint(buildPipeline(gl::Camera<double>{{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}, gl::Perspective<double>{60, 1.5, 0.1, inf}}),
                   Vec3<double>(0, 0, -1e12));
    EXPECT_TRUE(t.inside);
    EXPECT_LT(t.divided->z(), 1);
}

} // namespace
} // namespace viewpipe
