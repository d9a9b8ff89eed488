// The OpenGL forms against the reference pages, the seeds' worked examples
// and independently published matrices.

#include "support.hpp"

namespace viewpipe {
namespace {

using test::eps;
using test::expectRefused;

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

// Published matrices listed column-major (glGetDoublev order).
Mat4<double> columnMajor(std::initializer_list<double> values)
{
    Mat4<double> m;
    int i = 0;
    for (double x : values) {
        m(i % 4, i / 4) = x;
        ++i;
    }
    return m;
}

void expectMatrixNear(const Mat4<double>& actual, const Mat4<double>& expected, double tolerance)
{
    EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance) << "actual\n" << actual << "\nexpected\n"
                                                                    << expected;
}

// Seed 001, "glFrustum Matrix": glFrustum(-4, 4, -3, 3, 5, 80).
TEST(GlSeeds, FrustumExamples)
{
    expectMatrixNear(gl::frustum<double>({-4, 4, -3, 3, 5, 80}),
                     rows({{5.0 / 4, 0, 0, 0}, {0, 5.0 / 3, 0, 0}, {0, 0, -85.0 / 75, -800.0 / 75}, {0, 0, -1, 0}}),
                     4 * eps<double>());
    // Seed 001, "glFrustum Example": glFrustum(-30, 30, -20, 20, 1, 1000).
    expectMatrixNear(
        gl::frustum<double>({-30, 30, -20, 20, 1, 1000}),
        rows({{1.0 / 30, 0, 0, 0}, {0, 1.0 / 20, 0, 0}, {0, 0, -1001.0 / 999, -2000.0 / 999}, {0, 0, -1, 0}}),
        4 * eps<double>());
}

// Seed 001, "glOrtho Example". The slide calls glOrtho(-20, 30, 10, 60, 15, -25)
// but then lists top = 50, and its matrix (2/(t-b) = 1/20, -(t+b)/(t-b) = -3/2)
// is that of top = 50: the 60 is a typo. Near > far is legal for glOrtho.
TEST(GlSeeds, OrthoExample)
{
    expectMatrixNear(
        gl::ortho<double>({-20, 30, 10, 50, 15, -25}),
        rows({{1.0 / 25, 0, 0, -1.0 / 5}, {0, 1.0 / 20, 0, -3.0 / 2}, {0, 0, 1.0 / 20, -1.0 / 4}, {0, 0, 0, 1}}),
        4 * eps<double>());
}

// Seed 003's worked example: P = [1/3 0 0 0; 0 1/3 0 0; 0 0 -1/2 -2; 0 0 0 1],
// V = T(0, 0, -4), PV C = (-1/3, -1/3, -1/2) for C = (-1, -1, 1). Its P is
// glOrtho(-3, 3, -3, 3, 2, 6). (The slide's general formula writes the z
// translation as +(near+far)/(far-near): a sign slip; its example uses -2.)
TEST(GlSeeds, Seed003OrthoExample)
{
    const Mat4<double> p = gl::ortho<double>({-3, 3, -3, 3, 2, 6});
    expectMatrixNear(p, rows({{1.0 / 3, 0, 0, 0}, {0, 1.0 / 3, 0, 0}, {0, 0, -0.5, -2}, {0, 0, 0, 1}}),
                     4 * eps<double>());
    const Mat4<double> v = gl::lookAt<double>({{0, 0, 4}, {0, 0, 0}, {0, 1, 0}});
    const Vec4<double> c = p * v * Vec4<double>(-1, -1, 1, 1);
    EXPECT_TRUE(c.isApprox(Vec4<double>(-1.0 / 3, -1.0 / 3, -0.5, 1), 4 * eps<double>())) << c.transpose();
}

// Seed 000's forms with screen width w, height h and distances d_n, d_f are
// glOrtho(-w/2, w/2, -h/2, h/2, d_n, d_f) and glFrustum with the same box.
TEST(GlSeeds, Seed000FormsAreSpecialCases)
{
    test::SpecGenerator generator(7);
    for (int i = 0; i < 200; ++i) {
        const double w = generator.uniform(0.1, 50), h = generator.uniform(0.1, 50);
        const double dn = generator.uniform(0.1, 20), df = dn + generator.uniform(0.1, 200);
        const Mat4<double> seedOrtho =
            rows({{2 / w, 0, 0, 0}, {0, 2 / h, 0, 0}, {0, 0, -2 / (df - dn), -(df + dn) / (df - dn)}, {0, 0, 0, 1}});
        const Mat4<double> seedPerspective = rows({{2 * dn / w, 0, 0, 0},
                                                   {0, 2 * dn / h, 0, 0},
                                                   {0, 0, (dn + df) / (dn - df), 2 * dn * df / (dn - df)},
                                                   {0, 0, -1, 0}});
        const double tol = 16 * eps<double>() * std::max(1.0, seedPerspective.cwiseAbs().maxCoeff());
        expectMatrixNear(gl::ortho<double>({-w / 2, w / 2, -h / 2, h / 2, dn, df}), seedOrtho, tol);
        expectMatrixNear(gl::frustum<double>({-w / 2, w / 2, -h / 2, h / 2, dn, df}), seedPerspective, tol);
    }
}

// nrdvana/perl-Math-3Space, t/40-4space-projection.t: matrices captured from a
// real OpenGL implementation with glGetDouble (column-major, 10 digits).
TEST(GlPublished, PerlMath3SpaceCapturedFromOpenGL)
{
    expectMatrixNear(gl::frustum<double>({-1, 1, -1, 1, 1, 1000}),
                     columnMajor({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.002002002, -1, 0, 0, -2.002002002, 0}), 1e-9);
    expectMatrixNear(gl::frustum<double>({-.5, 1.5, -.5, 1.5, 1, 101}),
                     columnMajor({1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0.5, -1.02, -1, 0, 0, -2.02, 0}), 1e-12);
    expectMatrixNear(gl::perspective<double>({90, 1, 1, 1000}),
                     columnMajor({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.002002002, -1, 0, 0, -2.002002002, 0}), 1e-9);
    expectMatrixNear(gl::perspective<double>({90, 4.0 / 3, .1, 1000}),
                     columnMajor({0.74999999, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.00020002, -1, 0, 0, -0.200020002, 0}),
                     2e-8); // 0.74999999: 0.75 rounded to float, then truncated to 8 digits
}

// io7m/jcanephora, io7m-jcanephora-tests/.../ViewMatrixTest.java testLookAt and
// ProjectionMatrixTest.java testFrustumSimple / testOrthographic (row-major).
TEST(GlPublished, Jcanephora)
{
    expectMatrixNear(gl::lookAt<double>({{10, 10, -10}, {10, 10, 0}, {0, 1, 0}}),
                     rows({{-1, 0, 0, 10}, {0, 1, 0, -10}, {0, 0, -1, -10}, {0, 0, 0, 1}}), 4 * eps<double>());
    expectMatrixNear(gl::frustum<double>({-1, 1, -1, 1, 5, 100}),
                     rows({{5, 0, 0, 0}, {0, 5, 0, 0}, {0, 0, -1.105263113975525, -10.526315689086914}, {0, 0, -1, 0}}),
                     1e-6); // the published values are single precision
    expectMatrixNear(gl::ortho<double>({0, 10, 0, 10, 1, 10}),
                     rows({{0.2, 0, 0, -1}, {0, 0.2, 0, -1}, {0, 0, -0.22222222, -1.2222222}, {0, 0, 0, 1}}), 1e-7);
}

// go-gl/mathgl, mgl32/project_test.go TestLookAtV (column-major).
TEST(GlPublished, MathglLookAtRotations)
{
    expectMatrixNear(gl::lookAt<double>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}),
                     columnMajor({0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1}), 4 * eps<double>());
    expectMatrixNear(gl::lookAt<double>({{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}),
                     columnMajor({-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1}), 4 * eps<double>());
    expectMatrixNear(gl::lookAt<double>({{0, 0, 0}, {0, 0, -1}, {1, 0, 0}}),
                     columnMajor({0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}), 4 * eps<double>());
    expectMatrixNear(gl::lookAt<double>({{0, 0, 0}, {0, -1, 0}, {0, 0, -1}}),
                     columnMajor({1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1}), 4 * eps<double>());
}

// Dav1dde/gl3n, gl3n/linalg.d: mat4.perspective(600, 900, 60, 1, 100), i.e.
// gluPerspective(60, 600/900, 1, 100), asserted entry ranges (row-major).
TEST(GlPublished, Gl3nPerspective)
{
    const Mat4<double> m = gl::perspective<double>({60, 600.0 / 900, 1, 100});
    EXPECT_NEAR(m(0, 0), 2.598076, 1e-6);
    EXPECT_NEAR(m(1, 1), 1.732051, 1e-6);
    EXPECT_NEAR(m(2, 2), -1.020202, 1e-6);
    EXPECT_NEAR(m(2, 3), -2.020202, 1e-6);
    EXPECT_EQ(m(3, 2), -1);
    EXPECT_EQ(m(3, 3), 0);
}

TEST(GlForms, InfiniteFarIsTheExactLimit)
{
    const double inf = std::numeric_limits<double>::infinity();
    const Mat4<double> m = gl::frustum<double>({-1, 1, -1, 1, 0.5, inf});
    EXPECT_EQ(m(2, 2), -1);
    EXPECT_EQ(m(2, 3), -1);
    EXPECT_TRUE(m.allFinite());
    const Mat4<double> p = gl::perspective<double>({60, 1.5, 2, inf});
    EXPECT_EQ(p(2, 2), -1);
    EXPECT_EQ(p(2, 3), -4);
}

TEST(GlForms, PerspectiveEqualsTheMatchingFrustum)
{
    for (double fovy : {1e-6, 1.0, 45.0, 90.0, 135.0, 179.0}) {
        const double top = 2 * std::tan(fovy * M_PI / 360);
        const Mat4<double> f = gl::frustum<double>({-1.5 * top, 1.5 * top, -top, top, 2, 40});
        const Mat4<double> p = gl::perspective<double>({fovy, 1.5, 2, 40});
        EXPECT_TRUE(p.isApprox(f, 1e-12)) << fovy;
    }
}

template <class T> class GlInvariants : public ::testing::Test {};
TYPED_TEST_SUITE(GlInvariants, test::ScalarTypes);

// The view volume's corners land on the NDC cube's corners; the stages'
// product equals P * V from the reference formulas.
TYPED_TEST(GlInvariants, HoldForRandomCameras)
{
    using T = TypeParam;
    test::SpecGenerator generator(42);
    for (int i = 0; i < 3000; ++i) {
        const gl::Camera<T> camera = generator.glCamera(i % 3).template cast<T>();
        SCOPED_TRACE(testing::Message() << "camera " << i);
        const Pipeline<T> p = buildPipeline(camera);
        const Mat4<T> product = cumulativeProducts(p.stages).back();
        const Mat4<T> scale = product.cwiseAbs().cwiseMax(p.composite.cwiseAbs()).cwiseMax(T(1));
        ASSERT_LE(((product - p.composite).cwiseAbs().array() / scale.array()).maxCoeff(), 256 * eps<T>());

        const auto corners = gl::viewVolumeCorners(camera);
        for (std::size_t c = 0; c < 8; ++c) {
            const Vec4<T> world = corners[c].homogeneous();
            const Vec4<T> clip = p.composite * world;
            const Vec4<T> bound = test::productBound(p.composite, world, T(64));
            const Vec3<T> expected((c % 4 == 1 || c % 4 == 2) ? 1 : -1, c % 4 >= 2 ? 1 : -1, c < 4 ? -1 : 1);
            for (int a = 0; a < 3; ++a)
                ASSERT_LE(std::abs(clip[a] - expected[a] * clip.w()), bound[a] + bound.w()) << c << " " << a;
        }
    }
}

TEST(GlRefusals, NameTheFieldAndTheReason)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectRefused([] { gl::frustum<double>({-1, 1, -1, 1, 0, 10}); }, "camera.projection.near", "greater than 0");
    expectRefused([] { gl::frustum<double>({-1, 1, -1, 1, -1, 10}); }, "camera.projection.near", "greater than 0");
    expectRefused([] { gl::frustum<double>({-1, 1, -1, 1, 2, 2}); }, "camera.projection.far", "equals near");
    expectRefused([] { gl::frustum<double>({1, 1, -1, 1, 1, 2}); }, "camera.projection.right", "left = right");
    expectRefused([] { gl::ortho<double>({-1, 1, 3, 3, 1, 2}); }, "camera.projection.top", "bottom = top");
    expectRefused([] { gl::ortho<double>({-1, 1, -1, 1, 4, 4}); }, "camera.projection.far", "near = far");
    expectRefused([] { gl::perspective<double>({0, 1, 1, 2}); }, "camera.projection.fovy_deg", "between 0 and 180");
    expectRefused([] { gl::perspective<double>({180, 1, 1, 2}); }, "camera.projection.fovy_deg", "between 0 and 180");
    expectRefused([] { gl::perspective<double>({60, 0, 1, 2}); }, "camera.projection.aspect", "greater than 0");
    expectRefused([] { gl::perspective<double>({60, -1, 1, 2}); }, "camera.projection.aspect", "greater than 0");
    expectRefused([&] { gl::perspective<double>({60, nan, 1, 2}); }, "camera.projection.aspect", "finite");
    expectRefused([] { gl::lookAt<double>({{1, 2, 3}, {1, 2, 3}, {0, 1, 0}}); }, "camera.look_at.center",
                  "no view direction");
    expectRefused([] { gl::lookAt<double>({{0, 0, 0}, {0, 5, 0}, {0, 1, 0}}); }, "camera.look_at.up", "parallel");
    expectRefused([] { gl::lookAt<double>({{0, 0, 0}, {0, 0, -1}, {0, 0, 0}}); }, "camera.look_at.up", "zero vector");
}

} // namespace
} // namespace viewpipe
