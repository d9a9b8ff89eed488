// Foley & van Dam's normalizing transformations (CGPP 2nd ed., sec. 6.5).
//
// Seed 004 (the lecture slides on Foley's pipeline) has slips that these
// tests do not copy: it lists the perspective canonical planes as
// "z = -z_min" (Foley: z = z_min, with z_min < 0), and its uniform scale
// "1 / (-PRP_n + B)" has the wrong sign (Foley: -1 / (vrp'_z + B) with
// vrp'_z = -PRP_n, i.e. 1 / (PRP_n - B) > 0, which takes the back plane to
// z = -1). The hand computations below follow Foley's eqs. 6.31-6.48.

#include "build_paths.h"
#include "support.hpp"
#include "viewpipe/scene.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace viewpipe {
namespace {

using test::eps;
using test::expectRefused;

foley::ViewSpec<double> houseView()
{
    return {foley::Projection::Perspective, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {8, 6, 84}, {-50, 50, -50, 50}, 60, 25};
}

Mat4<double> rows(std::initializer_list<std::initializer_list<double>> values)
{
    Mat4<double> m;
    int r = 0;
    for (const auto& row : values) {
        int c = 0;
        for (double x : row)
            m(r, c++) = x;
        ++r;
    }
    return m;
}

// By hand: DOP = CW - PRP = (-8, -6, -84), so shx = -DOP_x / DOP_z = -2/21 and
// shy = -1/14; vrp'_z = -84, S_per = S(2*84 / (100*59), 2*84 / (100*59), 1/59)
// = S(42/1475, 42/1475, 1/59); SH_per * T(-PRP) takes the PRP... to the origin
// and the window center onto the z axis, so the translation is (0, 0, -84/59).
TEST(FoleyHouse, StagesMatchHandComputation)
{
    const std::vector<Stage<double>> stages = foley::perspectiveStages(houseView());
    ASSERT_EQ(stages.size(), 5u);
    EXPECT_EQ(stages[0].symbol(), "T(-VRP)");
    EXPECT_EQ(stages[1].symbol(), "R");
    EXPECT_EQ(stages[2].symbol(), "T(-PRP)");
    EXPECT_EQ(stages[3].symbol(), "SH_per");
    EXPECT_EQ(stages[4].symbol(), "S_per");
    const double tol = 4 * eps<double>();
    EXPECT_TRUE(stages[0].matrix.isApprox(Mat4<double>::Identity(), tol));
    EXPECT_TRUE(stages[1].matrix.isApprox(Mat4<double>::Identity(), tol));
    EXPECT_TRUE(stages[2].matrix.isApprox(rows({{1, 0, 0, -8}, {0, 1, 0, -6}, {0, 0, 1, -84}, {0, 0, 0, 1}}), tol));
    EXPECT_TRUE(
        stages[3].matrix.isApprox(rows({{1, 0, -2.0 / 21, 0}, {0, 1, -1.0 / 14, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}), tol));
    EXPECT_TRUE(stages[4].matrix.isApprox(
        rows({{42.0 / 1475, 0, 0, 0}, {0, 42.0 / 1475, 0, 0}, {0, 0, 1.0 / 59, 0}, {0, 0, 0, 1}}), tol));
}

// The texts that name a stage: the world before any stage, then each stage by its symbol.
TEST(FoleyHouse, StagesAreNamedForPeople)
{
    const std::vector<Stage<double>> stages = foley::perspectiveStages(houseView());
    EXPECT_EQ(stageText(stages, 0, StageText::ListEntry), "0. World — the scene in world coordinates");
    EXPECT_EQ(stageText(stages, 0, StageText::Caption), "World coordinates");
    EXPECT_EQ(stageText(stages, 0, StageText::Heading), "0. World coordinates");
    EXPECT_EQ(stageText(stages, 2, StageText::ListEntry), "2. $R$ — " + stages[1].explanation);
    EXPECT_EQ(stageText(stages, 2, StageText::Caption), "After $R$");
    EXPECT_EQ(stageText(stages, 5, StageText::Heading), "5. $S_{\\mathrm{per}}$ – " + stages[4].explanation);
    EXPECT_EQ(mathPlainText(stageText(stages, 5, StageText::Heading)), "5. S_per – " + mathPlainText(stages[4].explanation));
}

TEST(FoleyHouse, NperAndZminMatchHandComputation)
{
    const Pipeline<double> p = buildPipeline(houseView());
    const Mat4<double> expected = rows({{42.0 / 1475, 0, -4.0 / 1475, 0},
                                        {0, 42.0 / 1475, -3.0 / 1475, 0},
                                        {0, 0, 1.0 / 59, -84.0 / 59},
                                        {0, 0, 0, 1}});
    EXPECT_TRUE(p.composite.isApprox(expected, 8 * eps<double>())) << p.composite;
    ASSERT_TRUE(p.zmin.has_value());
    EXPECT_NEAR(*p.zmin, -24.0 / 59, 4 * eps<double>());
}

TEST(FoleyHouse, HouseLiesInsideTheCanonicalVolume)
{
    const Pipeline<double> p = buildPipeline(houseView());
    for (double z : {30.0, 54.0})
        for (const auto& xy : {std::pair{0.0, 0.0}, {16.0, 0.0}, {16.0, 10.0}, {8.0, 16.0}, {0.0, 10.0}})
            EXPECT_TRUE(tracePoint(p, Vec3<double>(xy.first, xy.second, z)).inside) << xy.first << " " << z;
    EXPECT_FALSE(tracePoint(p, Vec3<double>(0, 0, 70)).inside);  // in front of F = 60
    EXPECT_FALSE(tracePoint(p, Vec3<double>(0, 0, 20)).inside);  // behind B = 25
    EXPECT_FALSE(tracePoint(p, Vec3<double>(90, 0, 40)).inside); // beside the window
    EXPECT_FALSE(tracePoint(p, Vec3<double>(8, 6, 84)).inside);  // the PRP itself: w = 0 after M
    EXPECT_FALSE(tracePoint(p, Vec3<double>(8, 6, 100)).inside); // behind the eye: w < 0
}

// The default scene (data/scenes/house-corner.json), where no stage is the identity. By hand:
// VRP (16, 0, 54); n = (1, 0, 1)/sqrt2, u = VUP x n = (1, 0, -1)/sqrt2, v = n x u = (0, 1, 0).
// CW = (3, 7, 0), DOP = CW - PRP = (9, -13, -36): shx = -DOP_x / DOP_z = 1/4, shy = -13/36.
// vrp'_z = -36, B = -30: S_per = S(2*36 / (34*66), 2*36 / (22*66), 1/66) = S(6/187, 6/121, 1/66);
// z_min = -(vrp'_z + F) / (vrp'_z + B) = -31/66.
TEST(FoleyHouseCorner, DefaultSceneMovesAtEveryStageAsComputedByHand)
{
    const Scene scene = loadScene(std::filesystem::path(viewpipe::build::dataDir) / "scenes" / "house-corner.json");
    const Pipeline<double> p = buildPipeline(scene.camera);
    ASSERT_EQ(p.stages.size(), 5u);
    const double s = 1 / std::sqrt(2.0);
    const std::array<Mat4<double>, 5> expected = {
        rows({{1, 0, 0, -16}, {0, 1, 0, 0}, {0, 0, 1, -54}, {0, 0, 0, 1}}),
        rows({{s, 0, -s, 0}, {0, 1, 0, 0}, {s, 0, s, 0}, {0, 0, 0, 1}}),
        rows({{1, 0, 0, 6}, {0, 1, 0, -20}, {0, 0, 1, -36}, {0, 0, 0, 1}}),
        rows({{1, 0, 0.25, 0}, {0, 1, -13.0 / 36, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}),
        rows({{6.0 / 187, 0, 0, 0}, {0, 6.0 / 121, 0, 0}, {0, 0, 1.0 / 66, 0}, {0, 0, 0, 1}})};
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_TRUE(p.stages[k].matrix.isApprox(expected[k], 4 * eps<double>())) << p.stages[k].symbol();
        EXPECT_FALSE(p.stages[k].matrix.isApprox(Mat4<double>::Identity(), 1e-3)) << p.stages[k].symbol() << " does not move";
    }
    ASSERT_TRUE(p.zmin.has_value());
    EXPECT_NEAR(*p.zmin, -31.0 / 66, 4 * eps<double>());
    // The whole house lies inside the view volume.
    for (double z : {30.0, 54.0})
        for (const auto& xy : {std::pair{0.0, 0.0}, {16.0, 0.0}, {16.0, 10.0}, {8.0, 16.0}, {0.0, 10.0}})
            EXPECT_TRUE(tracePoint(p, Vec3<double>(xy.first, xy.second, z)).inside) << xy.first << " " << z;
}

TEST(FoleyM, MapsPerspectiveCornersToParallelCorners)
{
    const foley::ViewSpec<double> spec = houseView();
    const Mat4<double> m = foley::perspectiveToParallel(spec);
    const std::array<Vec3<double>, 8> perspective = foley::canonicalCorners(spec);
    foley::ViewSpec<double> parallel = spec;
    parallel.projection = foley::Projection::Parallel;
    const std::array<Vec3<double>, 8> expected = foley::canonicalCorners(parallel);
    for (std::size_t i = 0; i < 8; ++i) {
        const Vec4<double> h = m * perspective[i].homogeneous();
        const Vec3<double> q = h.head<3>() / h.w();
        EXPECT_TRUE((q - expected[i]).cwiseAbs().maxCoeff() <= 8 * eps<double>()) << i << ": " << q.transpose();
    }
}

// The Foley house's "oblique" parallel variant: DOP not parallel to VPN.
TEST(FoleyParallel, ObliqueShearMatchesHandComputation)
{
    foley::ViewSpec<double> spec = houseView();
    spec.projection = foley::Projection::Parallel;
    spec.prp = {8, 6, 84};
    spec.window = {0, 20, 0, 10};
    // CW = (10, 5, 0); DOP = (2, -1, -84): shx = 2/84, shy = -1/84.
    const std::vector<Stage<double>> stages = foley::parallelStages(spec);
    ASSERT_EQ(stages.size(), 5u);
    EXPECT_EQ(stages[2].symbol(), "SH_par");
    EXPECT_EQ(stages[3].symbol(), "T_par");
    EXPECT_EQ(stages[4].symbol(), "S_par");
    EXPECT_NEAR(stages[2].matrix(0, 2), 2.0 / 84, 2 * eps<double>());
    EXPECT_NEAR(stages[2].matrix(1, 2), -1.0 / 84, 2 * eps<double>());
    EXPECT_TRUE(stages[3].matrix.col(3).isApprox(Vec4<double>(-10, -5, -60, 1)));
    EXPECT_TRUE(stages[4].matrix.diagonal().isApprox(Vec4<double>(0.1, 0.2, 1.0 / 35, 1)));
}

template <class T> class FoleyInvariants : public ::testing::Test {};
TYPED_TEST_SUITE(FoleyInvariants, test::ScalarTypes);

// Over thousands of seeded random valid specifications, in every scalar type.
TYPED_TEST(FoleyInvariants, HoldForRandomSpecifications)
{
    using T = TypeParam;
    test::SpecGenerator generator(20261123);
    for (int i = 0; i < 4000; ++i) {
        const auto projection = i % 2 ? foley::Projection::Parallel : foley::Projection::Perspective;
        const foley::ViewSpec<T> spec = generator.foleySpec(projection).template cast<T>();
        SCOPED_TRACE(testing::Message() << "specification " << i);
        const std::vector<Stage<T>> stages = foley::stages(spec);
        const Pipeline<T> p = buildPipeline(spec);

        // R is orthonormal with det +1.
        const Eigen::Matrix<long double, 3, 3> r = stages[1].matrix.template topLeftCorner<3, 3>().template cast<long double>();
        const long double orthogonality =
            (r * r.transpose() - Eigen::Matrix<long double, 3, 3>::Identity()).cwiseAbs().maxCoeff();
        ASSERT_LE(orthogonality, 8 * eps<T>());
        ASSERT_LE(std::abs(r.determinant() - 1), 8 * eps<T>());

        // T(-VRP) takes the VRP to the origin, exactly.
        ASSERT_TRUE((stages[0].matrix * spec.vrp.homogeneous()).template head<3>().isZero(T(0)));

        // Perspective: after SH_per the window center lies on the n (z) axis.
        // Parallel: SH_par makes the DOP parallel to z, and after T_par the
        // window center lies on the axis (the shear keeps the view plane fixed).
        const bool perspective = projection == foley::Projection::Perspective;
        const std::vector<Mat4<T>> cumulative = cumulativeProducts(stages);
        const Mat4<T>& centered = cumulative[3]; // through SH_per, or through T_par
        const Basis<T> basis = foley::vrcBasis(spec);
        const Vec4<T> cw = foley::vrcToWorld(spec, basis, foley::windowCenter(spec)).homogeneous();
        const Vec4<T> onAxis = centered * cw;
        const Vec4<T> bound = test::productBound(centered, cw, T(64));
        ASSERT_LE(std::abs(onAxis.x()), bound.x());
        ASSERT_LE(std::abs(onAxis.y()), bound.y());
        if (!perspective) {
            Vec4<T> dop = Vec4<T>::Zero();
            dop.template head<3>() = foley::directionOfProjection(spec);
            const Vec4<T> sheared = stages[2].matrix * dop;
            const Vec4<T> dopBound = test::productBound(stages[2].matrix, dop, T(8));
            ASSERT_LE(std::abs(sheared.x()), dopBound.x());
            ASSERT_LE(std::abs(sheared.y()), dopBound.y());
        }

        // The product of the stages equals the closed-form composite.
        const Mat4<T>& product = cumulative.back();
        const Mat4<T> scale = product.cwiseAbs().cwiseMax(p.composite.cwiseAbs()).cwiseMax(T(1));
        ASSERT_LE(((product - p.composite).cwiseAbs().array() / scale.array()).maxCoeff(), 64 * eps<T>())
            << product << "\n\n" << p.composite;

        // The view volume's 8 corners land on the canonical volume's corners.
        const auto corners = foley::viewVolumeCorners(spec);
        const auto canonical = foley::canonicalCorners(spec);
        for (std::size_t c = 0; c < 8; ++c) {
            const Vec4<T> world = corners[c].homogeneous();
            const Vec4<T> image = p.composite * world;
            const Vec4<T> cornerBound = test::productBound(p.composite, world, T(64));
            for (int a = 0; a < 3; ++a)
                ASSERT_LE(std::abs(image[a] - canonical[c][a]), cornerBound[a] + 8 * eps<T>())
                    << "corner " << c << " axis " << a;
        }
    }
}

// VUP nearly parallel to VPN, not axis-aligned: u stays accurate and R
// orthonormal to a few ulps, which a plain cross product does not achieve.
template <class T> class FoleyNearlyParallelUp : public ::testing::Test {};
TYPED_TEST_SUITE(FoleyNearlyParallelUp, test::ScalarTypes);

TYPED_TEST(FoleyNearlyParallelUp, BasisStaysOrthonormalAndAccurate)
{
    using T = TypeParam;
    using Ref = long double;
    const Vec3<T> up = Vec3<T>(1, 2, 3).normalized();
    const Vec3<T> axis = up.cross(Vec3<T>(0, 0, 1)).normalized();
    for (double theta = 1e-2; theta >= 1e-12; theta /= 10) {
        SCOPED_TRACE(testing::Message() << "theta " << theta);
        const Vec3<T> vpn = Eigen::AngleAxis<T>(T(theta), axis) * up;
        if (theta < double(minUpAngle<T>())) {
            expectRefused([&] { orthonormalBasis<T>(vpn, up, "view.vpn", "view.vup"); }, "view.vup", "parallel");
            continue;
        }
        const Basis<T> b = orthonormalBasis<T>(vpn, up, "view.vpn", "view.vup");
        const Mat3<Ref> r = b.rotation().template cast<Ref>();
        EXPECT_LE((r * r.transpose() - Mat3<Ref>::Identity()).cwiseAbs().maxCoeff(), 4 * eps<T>());
        // Reference: the same (rounded) inputs, in 50-digit arithmetic.
        using Big = boost::multiprecision::cpp_bin_float_50;
        std::array<Big, 3> a, c;
        for (int k = 0; k < 3; ++k) {
            a[k] = Big(up[k]);
            c[k] = Big(vpn[k]);
        }
        const std::array<Big, 3> cross = {a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2],
                                          a[0] * c[1] - a[1] * c[0]};
        const Big length = sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
        for (int k = 0; k < 3; ++k)
            EXPECT_LE(abs(Big(b.u[k]) - cross[k] / length), 4 * eps<T>()) << "u[" << k << "]";
    }
}

TEST(FoleyRefusals, NameTheFieldAndTheReason)
{
    auto refuse = [](auto edit, const std::string& field, const std::string& reason) {
        foley::ViewSpec<double> spec = houseView();
        edit(spec);
        expectRefused([&] { foley::validate(spec); }, field, reason);
        expectRefused([&] { buildPipeline(spec); }, field, reason);
    };
    using Spec = foley::ViewSpec<double>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    refuse([](Spec& s) { s.vpn = {0, 0, 0}; }, "view.vpn", "zero vector");
    refuse([](Spec& s) { s.vup = {0, 0, 0}; }, "view.vup", "zero vector");
    refuse([&](Spec& s) { s.vpn = {nan, 0, 1}; }, "view.vpn", "finite");
    refuse([&](Spec& s) { s.vrp = {0, inf, 0}; }, "view.vrp", "finite");
    refuse([&](Spec& s) { s.prp = {0, 0, nan}; }, "view.prp", "finite");
    refuse([&](Spec& s) { s.front = inf; }, "view.front", "finite");
    refuse([&](Spec& s) { s.window.vmax = nan; }, "view.window[3]", "finite");
    refuse([](Spec& s) { s.vup = {0, 0, 2}; }, "view.vup", "parallel to view.vpn (angle 0 degrees");
    refuse([](Spec& s) { s.vup = {0, 0, -3}; }, "view.vup", "parallel to view.vpn (angle 0 degrees");
    refuse([](Spec& s) { s.window = {5, 5, -1, 1}; }, "view.window", "umin (5) must be less than umax (5)");
    refuse([](Spec& s) { s.window = {-1, 1, 2, -2}; }, "view.window", "vmin (2) must be less than vmax (-2)");
    refuse([](Spec& s) { s.front = 25; }, "view.front", "F (25) must be greater than B (25)");
    refuse([](Spec& s) { s.back = 70; }, "view.front", "must be greater than B");
    refuse([](Spec& s) { s.prp = {8, 6, 0}; }, "view.prp", "view plane");
    refuse([](Spec& s) { s.prp = {8, 6, 60}; }, "view.prp", "must exceed the front plane F (60)");
    refuse([](Spec& s) { s.prp = {8, 6, 40}; }, "view.prp", "must exceed the front plane");
    // A parallel view takes a PRP on either side of the view plane, but not on it.
    foley::ViewSpec<double> parallel = houseView();
    parallel.projection = foley::Projection::Parallel;
    parallel.prp = {8, 6, -40};
    EXPECT_NO_THROW(buildPipeline(parallel));
    parallel.prp = {8, 6, 0};
    expectRefused([&] { buildPipeline(parallel); }, "view.prp", "view plane");
}

} // namespace
} // namespace viewpipe
