#include <gtest/gtest.h>

#include <stdexcept>

#include "build_paths.h"
#include "viewpipe/exact.hpp"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/scene.hpp"

#include <random>

#include "viewpipe/format.hpp"

namespace viewpipe {
namespace {

Exact e(const char* text)
{
    return parseExact(text);
}

std::string refusal(const char* text)
{
    try {
        parseExact(text);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "";
}

TEST(Exact, TypedDecimalsAreTheRationalsWritten)
{
    EXPECT_EQ(e("0.1").text(), "1/10");
    EXPECT_EQ(double(e("0.1")), 0.1); // rounded once, to the double a person means
    EXPECT_EQ(double(e("1/3")), 1.0 / 3);
    EXPECT_NE(e("0.1"), Exact(0.1)); // the double 0.1 is 3602879701896397/2^55
    EXPECT_EQ(Exact(0.1).text(), "3602879701896397/36028797018963968");
    EXPECT_EQ(e("-1.5e-3").text(), "-3/2000");
    EXPECT_EQ(e("2.50").text(), "5/2");
}

TEST(Exact, SquareRootsAreReducedToSquareFreeRadicands)
{
    EXPECT_EQ(sqrt(Exact(8)).text(), "2*sqrt(2)");
    EXPECT_EQ(sqrt(e("1/2")).text(), "sqrt(2)/2");
    EXPECT_EQ((Exact(1) / sqrt(Exact(2))).text(), "sqrt(2)/2");
    EXPECT_EQ(sqrt(Exact(2)) * sqrt(Exact(6)), 2 * sqrt(Exact(3)));
    EXPECT_EQ(sqrt(Exact(12)).latex(), "2\\sqrt{3}");
    EXPECT_EQ(e("-13/36").latex(), "-\\frac{13}{36}");
    EXPECT_EQ(e("sqrt(2)/2").latex(), "\\frac{\\sqrt{2}}{2}");
    // A large prime radicand (2^61 - 1) stays one root; its square is rational again.
    const Exact big = sqrt(e("2305843009213693951"));
    EXPECT_TRUE(big.isExact());
    EXPECT_EQ(big * big, e("2305843009213693951"));
}

TEST(Exact, QuotientsOfSumsOfRootsAreExact)
{
    const Exact a = Exact(1) + sqrt(Exact(2)) + sqrt(Exact(3));
    EXPECT_EQ(a * (Exact(1) / a), Exact(1));
    EXPECT_EQ((Exact(1) + sqrt(Exact(2))) * (sqrt(Exact(2)) - Exact(1)), Exact(1));
    EXPECT_EQ((Exact(1) / (Exact(1) + sqrt(Exact(2)))).text(), "sqrt(2) - 1"); // a positive term first
}

TEST(Exact, SignsAreDecidedExactly)
{
    // The double nearest sqrt(2) is 1.41421356237309514547..., above sqrt(2) = 1.41421356237309504880...
    EXPECT_LT(sqrt(Exact(2)), Exact(1.4142135623730951));
    EXPECT_GT(sqrt(Exact(2)), Exact(1.4142135623730949));
    // sqrt(5 + 2 sqrt(6)) = sqrt(2) + sqrt(3): denested, so the difference is exactly zero.
    EXPECT_EQ(sqrt(Exact(5) + 2 * sqrt(Exact(6))), sqrt(Exact(2)) + sqrt(Exact(3)));
    EXPECT_EQ((sqrt(Exact(2)) + sqrt(Exact(3)) - sqrt(Exact(5) + 2 * sqrt(Exact(6)))).sign(), 0);
    // 10^-30 apart: no double tells them apart.
    EXPECT_GT(sqrt(Exact(2)) + e("1e-30"), sqrt(Exact(2)));
}

TEST(Exact, ExpressionsAsTyped)
{
    EXPECT_EQ(e("20*sqrt(2)"), 20 * sqrt(Exact(2)));
    EXPECT_EQ(e("20\u221A2"), 20 * sqrt(Exact(2)));
    EXPECT_EQ(e("\u221A2/2"), sqrt(Exact(2)) / 2);
    EXPECT_EQ(e("1/\u221A2"), sqrt(Exact(2)) / 2);
    EXPECT_EQ(e("\u22121/3"), e("-1/3"));
    EXPECT_EQ(e(" ( 1 + 2 ) * -3 "), Exact(-9));
    EXPECT_EQ(e("2 - 3 - 4"), Exact(-5));
    EXPECT_EQ(e("12/2/3"), Exact(2));
    // What text() writes reads back as the same value.
    for (const char* text : {"-13/36", "sqrt(2)/2", "1 + 20*sqrt(2)", "-sqrt(3)/6 + 1/2", "7*sqrt(30)/11"})
        EXPECT_EQ(e(e(text).text().c_str()), e(text)) << text;
}

// What reads exactly is what a textbook writes: short fractions, a short root term, and one after a short
// fraction (Foley's view D: z_min = 11 - 8 sqrt(2)); sums of roots and long numbers read as decimals.
TEST(Exact, ShortFormsReadExactly)
{
    for (const char* shown : {"-13/36", "42/1475", "19*sqrt(482)/482", "11 - 8*sqrt(2)", "1 + sqrt(2)", "-2 - 3*sqrt(5)"})
        EXPECT_TRUE(parseExact(shown).readsExactly()) << shown;
    for (const char* decimal : {"sqrt(2) + sqrt(3)", "1 + 12345*sqrt(2)", "187*sqrt(1068594)/1068594", "1234567891/3",
                                "1/3 + sqrt(2) + sqrt(5)", "23/4 + 23*sqrt(2)/16", "1000 + sqrt(2)"})
        EXPECT_FALSE(parseExact(decimal).readsExactly()) << decimal;
    // In the caption of S_per, as the CLI prints it.
    const auto viewD = evaluateScene(parseScene(R"json({"view": {"projection": "perspective", "vrp": [16, 0, 54],
        "vpn": [1, 0, 1], "vup": [0, 1, 0], "prp": [0, 25, "20*sqrt(2)"], "window": [-20, 20, -5, 35], "front": 10,
        "back": -30}})json", "."));
    EXPECT_NE(viewD->stageClaims.back().find("11 - 8\\sqrt{2}"), std::string::npos) << viewD->stageClaims.back();
}

TEST(Exact, BadExpressionsAreRefusedWithTheReason)
{
    EXPECT_NE(refusal("sqrt(-1)").find("the square root of -1, a negative number"), std::string::npos) << refusal("sqrt(-1)");
    EXPECT_NE(refusal("1/0").find("division by zero at character 3"), std::string::npos) << refusal("1/0");
    EXPECT_NE(refusal("2 +* 3").find("expected a number, sqrt(...) or ( at character 4"), std::string::npos)
        << refusal("2 +* 3");
    EXPECT_NE(refusal("").find("is empty"), std::string::npos);
    EXPECT_NE(refusal("sqrt(2").find("expected )"), std::string::npos);
    EXPECT_NE(refusal("2x").find("unexpected \"x\" at character 2"), std::string::npos);
    EXPECT_NE(refusal("1e99999").find("exponent"), std::string::npos);
    // Hostile input: nesting past 100 levels is refused, not a deep recursion.
    EXPECT_NE(refusal((std::string(5000, '(') + "1" + std::string(5000, ')')).c_str()).find("nested deeper than 100"),
              std::string::npos);
    EXPECT_NE(refusal(std::string(5000, '-').append("1").c_str()).find("nested deeper than 100"), std::string::npos);
    // A product of sums of many roots becomes inexact, with its reason, instead of 2^k terms.
    std::string many = "(1";
    for (int p : {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71})
        many += " + sqrt(" + std::to_string(p) + ")";
    many += ")";
    const Exact big = e((many + "*" + many + "*" + many + "*" + many).c_str());
    EXPECT_FALSE(big.isExact());
    EXPECT_GT(double(big), 1e6);
    EXPECT_FALSE((Exact(1) / e(many.c_str())).isExact()); // 2^20 products of roots: not solved for
}

TEST(Exact, CotangentsOfTheSpecialAnglesAreExact)
{
    EXPECT_EQ(cotOfHalfDegrees(Exact(90)), Exact(1));
    EXPECT_EQ(cotOfHalfDegrees(Exact(60)), sqrt(Exact(3)));
    EXPECT_EQ(cotOfHalfDegrees(Exact(120)), sqrt(Exact(3)) / 3);
    EXPECT_EQ(cotOfHalfDegrees(Exact(45)), Exact(1) + sqrt(Exact(2)));
    EXPECT_EQ(cotOfHalfDegrees(Exact(30)), Exact(2) + sqrt(Exact(3)));
    const Exact fifty = cotOfHalfDegrees(Exact(50));
    EXPECT_FALSE(fifty.isExact());
    EXPECT_NE(fifty.inexactReason().find("cot(50 degrees / 2)"), std::string::npos);
    EXPECT_NEAR(double(fifty), 1 / std::tan(25 * 3.14159265358979323846 / 180), 1e-15);
    // What an inexact value touches is inexact, and says why; but times an exact zero it is zero.
    EXPECT_FALSE((fifty * 2 + 1).isExact());
    EXPECT_EQ(fifty * 0 + 1, Exact(1));
    EXPECT_EQ((Exact(2) * fifty).inexactReason(), fifty.inexactReason());
}

TEST(Exact, InfiniteFarPlanes)
{
    const Exact far(std::numeric_limits<double>::infinity());
    EXPECT_EQ(Exact(2) / far, Exact(0));
    EXPECT_TRUE(isinf(far));
    EXPECT_GT(far, Exact(1000000));
}

TEST(Exact, EigenComputesWithIt)
{
    Mat3<Exact> r;
    const Exact h = sqrt(Exact(2)) / 2;
    r << h, 0, -h, 0, 1, 0, h, 0, h;
    EXPECT_EQ(Mat3<Exact>(r * r.transpose()), Mat3<Exact>::Identity());
    EXPECT_EQ(Mat3<Exact>(r.inverse()), Mat3<Exact>(r.transpose()));
    EXPECT_EQ(Vec3<Exact>(1, 0, 1).normalized(), Vec3<Exact>(h, 0, h));
}

Mat4<Exact> rows(std::initializer_list<std::initializer_list<const char*>> values)
{
    Mat4<Exact> m;
    int r = 0;
    for (const auto& row : values) {
        int c = 0;
        for (const char* x : row)
            m(r, c++) = parseExact(x);
        ++r;
    }
    return m;
}

Scene dataScene(const std::string& name)
{
    return loadScene(std::filesystem::path(viewpipe::build::dataDir) / "scenes" / name);
}

// The default scene by hand (as in foley_test.cpp, after Foley's eqs. 6.31-6.48): n = (1, 0, 1)/sqrt2,
// u = (1, 0, -1)/sqrt2, v = (0, 1, 0); shx = 1/4, shy = -13/36; S_per = S(6/187, 6/121, 1/66); z_min = -31/66.
TEST(ExactPipeline, HouseCornerIsTheHandComputationExactly)
{
    const Pipeline<Exact> p = buildPipeline(exactCamera(dataScene("house-corner.json")));
    ASSERT_EQ(p.stages.size(), 5u);
    EXPECT_EQ(p.stages[0].matrix, rows({{"1", "0", "0", "-16"}, {"0", "1", "0", "0"}, {"0", "0", "1", "-54"}, {"0", "0", "0", "1"}}));
    EXPECT_EQ(p.stages[1].matrix, rows({{"sqrt(2)/2", "0", "-sqrt(2)/2", "0"},
                                        {"0", "1", "0", "0"},
                                        {"sqrt(2)/2", "0", "sqrt(2)/2", "0"},
                                        {"0", "0", "0", "1"}}));
    EXPECT_EQ(p.stages[2].matrix, rows({{"1", "0", "0", "6"}, {"0", "1", "0", "-20"}, {"0", "0", "1", "-36"}, {"0", "0", "0", "1"}}));
    EXPECT_EQ(p.stages[3].matrix, rows({{"1", "0", "1/4", "0"}, {"0", "1", "-13/36", "0"}, {"0", "0", "1", "0"}, {"0", "0", "0", "1"}}));
    EXPECT_EQ(p.stages[4].matrix, rows({{"6/187", "0", "0", "0"}, {"0", "6/121", "0", "0"}, {"0", "0", "1/66", "0"}, {"0", "0", "0", "1"}}));
    ASSERT_TRUE(p.zmin);
    EXPECT_EQ(*p.zmin, parseExact("-31/66"));
    EXPECT_EQ(p.stages[1].matrix(0, 0).latex(), "\\frac{\\sqrt{2}}{2}");
    // N^-1 (N p) = p with no error at all, for points of the house and beyond it.
    const Mat4<Exact> inverse = p.composite.inverse();
    for (const Vec4<Exact>& point : {Vec4<Exact>(0, 0, 54, 1), Vec4<Exact>(16, 10, 30, 1), Vec4<Exact>(parseExact("1/3"), -7, 1000, 1)})
        EXPECT_EQ(Vec4<Exact>(inverse * (p.composite * point)), point);
}

Scene frustumScene(const std::string& near)
{
    return parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
                                     "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5,
                                                    "top": 1.5, "near": )" + near + R"(, "far": 10}}})",
                      ".");
}

// glFrustum(-2, 2, -1.5, 1.5, 2, 10) (the OpenGL reference page's matrix): the near plane's center goes to
// NDC (0, 0, -1), its corner (2, 1.5, -2) to (1, 1, -1), the far plane's center to (0, 0, 1): all on the
// volume's boundary, so inside. In double, -3/2 comes out -1.4999999999999998 and the near center "outside".
TEST(ExactPipeline, TheFrustumsOwnCornersAreInside)
{
    const Pipeline<Exact> p = buildPipeline(exactCamera(frustumScene("2")));
    struct Case { Vec3<Exact> world; Vec3<Exact> ndc; };
    for (const Case& c : {Case{{0, 0, -2}, {0, 0, -1}}, Case{{2, parseExact("1.5"), -2}, {1, 1, -1}},
                          Case{{0, 0, -10}, {0, 0, 1}}, Case{{-10, parseExact("-7.5"), -10}, {-1, -1, 1}}}) {
        const PointTrace<Exact> trace = tracePoint(p, c.world);
        ASSERT_TRUE(trace.divided);
        EXPECT_EQ(*trace.divided, c.ndc) << c.world.transpose();
        EXPECT_TRUE(trace.inside) << c.world.transpose();
    }
    EXPECT_EQ(p.projectionMatrix->row(2), rows({{"0", "0", "-3/2", "-5"}, {"0", "0", "0", "0"}, {"0", "0", "0", "0"}, {"0", "0", "0", "0"}}).row(0));
}

// gluPerspective at 70 degrees: cot(35) is no root, and only the entries it reaches are inexact.
// The eye's translation, the zeros beside the scale and P_depth's -(f + n)/(f - n) = -31/29 and
// -2fn/(f - n) = -120/29 (near 2, far 60; the glFrustum reference page) stay exact through the product
// (found: every entry of the composite marked inexact, 0 as "~0").
TEST(ExactPipeline, AnInexactCotangentTouchesOnlyTheEntriesItReaches)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [8, 6, 40], "center": [8, 6, 0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 70, "aspect": 1.5, "near": 2, "far": 60}}})", ".");
    const Pipeline<Exact> p = exactPipeline(scene);
    const Mat4<Exact>& m = p.composite;
    for (const auto& [row, column] : {std::pair(0, 0), std::pair(0, 3), std::pair(1, 1), std::pair(1, 3)})
        EXPECT_FALSE(m(row, column).isExact()) << row << ", " << column;
    for (const auto& [row, column] : {std::pair(0, 1), std::pair(0, 2), std::pair(1, 0), std::pair(1, 2), std::pair(2, 0),
                                      std::pair(2, 1), std::pair(3, 0), std::pair(3, 1)})
        EXPECT_TRUE(m(row, column).isExactZero()) << row << ", " << column;
    EXPECT_EQ(m(2, 2), parseExact("-31/29"));
    EXPECT_EQ(m(2, 3), parseExact("-31/29*(-40) - 120/29"));
    EXPECT_EQ(m(3, 2), Exact(-1));
    EXPECT_EQ(m(3, 3), Exact(40));
    EXPECT_TRUE((Exact(0) * m(0, 0)).isExactZero());
    EXPECT_TRUE((m(0, 0) * Exact(0) + Exact(0)).isExactZero());
    EXPECT_EQ(Exact(0) + m(0, 0), m(0, 0));
}

TEST(ExactScene, ExpressionsAreReadExactlyAndSavedAsTyped)
{
    const Scene scene = parseScene(R"js({"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [1, 0, 1],
        "vup": [0, 1, 0], "prp": [0, 25, "20*sqrt(2)"], "window": ["-1/3", 1, -1, 1], "front": 5, "back": -5}})js", ".");
    EXPECT_EQ(std::get<foley::ViewSpec<double>>(scene.camera).prp.z(), 20 * std::sqrt(2.0));
    const auto spec = std::get<foley::ViewSpec<Exact>>(exactCamera(scene));
    EXPECT_EQ(spec.prp.z(), 20 * sqrt(Exact(2)));
    EXPECT_EQ(spec.window.umin, parseExact("-1/3"));
    const std::string saved = sceneToJson(scene);
    EXPECT_NE(saved.find("\"20*sqrt(2)\""), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"-1/3\""), std::string::npos) << saved;
    EXPECT_EQ(parseScene(saved, "."), scene);
    // An edit replaces what was typed.
    Scene edited = scene;
    std::get<foley::ViewSpec<double>>(edited.camera).prp.z() = 30;
    EXPECT_EQ(sceneToJson(edited).find("sqrt"), std::string::npos) << sceneToJson(edited);
    // What a save writes as typed: every expression before the edit, the other field's after it.
    EXPECT_EQ(heldExpressions(scene), scene.typedExpressions);
    EXPECT_EQ(heldExpressions(edited), (std::map<std::string, std::string>{{"view.window[0]", "-1/3"}}));
}

TEST(ExactScene, BadExpressionsNameTheField)
{
    auto refusal = [](const std::string& prp2) {
        try {
            parseScene(R"({"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
                "prp": [0, 0, )" + prp2 + R"(], "window": [-1, 1, -1, 1], "front": 5, "back": -5}})", ".");
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_EQ(refusal("\"sqrt(-1)\""), "view.prp[2]: the square root of -1, a negative number, at character 1 of \"sqrt(-1)\"");
    EXPECT_EQ(refusal("\"1/0\""), "view.prp[2]: division by zero at character 3 of \"1/0\"");
    EXPECT_EQ(refusal("\"2 +* 3\""), "view.prp[2]: expected a number, sqrt(...) or ( at character 4 of \"2 +* 3\"");
    EXPECT_EQ(refusal("true"), "view.prp[2]: must be a number or an exact expression such as \"20*sqrt(2)\" (got true)");
}

} // namespace
} // namespace viewpipe

namespace viewpipe {
namespace {

// A box whose near face is glFrustum(-2, 2, -1.5, 1.5, 2, 10)'s own near rectangle: every vertex lies
// in the canonical volume, four of them on its corners. Double's clip matrix puts the near corners just
// past z = -1 (its -3/2 is -1.4999999999999998), so double alone clipped the near face; decided exactly,
// the box is inside.
TEST(ExactVerdicts, AFrustumsOwnNearFaceIsKept)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
        "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}},
        "objects": [{"type": "box", "min": [-2, -1.5, -3], "max": [2, 1.5, -2]}], "effects": ["clip"]})", ".");
    const auto evaluated = evaluateScene(scene);
    ASSERT_TRUE(evaluated->outcomes.clip);
    EXPECT_EQ(evaluated->outcomes.clip->segments.inside, 12);
    EXPECT_EQ(evaluated->outcomes.clip->segments.clipped, 0);
    EXPECT_EQ(evaluated->outcomes.clip->polygons.inside, 6);
    // The same in double alone: a rounding decided it.
    const std::vector<PolygonMesh> box = {boxMesh({-2, -1.5, -3}, {2, 1.5, -2})};
    const EffectOutcomes doubleOnly = runEffects(evaluated->pipeline, box, scene.effects);
    EXPECT_LT(doubleOnly.clip->segments.inside, 12);
}

// Random rational frustums (glFrustum, every number in eighths) and a box whose front face is the near
// rectangle: its four corners lie on the volume's corners. Wherever double's verdict for a vertex differs
// from the exact one, the evaluated scene's counts follow the exact one (every edge is inside).
TEST(ExactVerdicts, RandomRationalScenesFollowTheExactVerdict)
{
    std::mt19937 random(46);
    std::uniform_int_distribution<int> eighths(1, 40);
    auto q = [&] { return eighths(random) / 8.0; };
    int differing = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const double left = -q(), right = q(), bottom = -q(), top = q(), zNear = q(), depth = q();
        auto number = [](double x) { return formatShortest(x); };
        const std::string text = R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
            "projection": {"type": "frustum", "left": )" + number(left) + ", \"right\": " + number(right) +
                                 ", \"bottom\": " + number(bottom) + ", \"top\": " + number(top) +
                                 ", \"near\": " + number(zNear) + ", \"far\": " + number(zNear + 2 * depth) +
                                 R"(}}, "objects": [{"type": "box", "min": [)" + number(left) + "," + number(bottom) +
                                 "," + number(-zNear - depth) + R"(], "max": [)" + number(right) + "," + number(top) +
                                 "," + number(-zNear) + R"(]}], "effects": ["clip"]})";
        const Scene scene = parseScene(text, ".");
        const auto evaluated = evaluateScene(scene);
        const Pipeline<Exact> exact = exactPipeline(scene);
        const PolygonMesh& mesh = *evaluated->meshes[0];
        int exactInside = 0;
        for (const auto& e : meshEdgeIndices(mesh)) {
            bool inside = true;
            for (int i : e) {
                const Vec3<double>& v = mesh.vertices[std::size_t(i)];
                const Vec4<Exact> h = exact.clipMatrix() * Vec4<Exact>(Exact(v.x()), Exact(v.y()), Exact(v.z()), Exact(1));
                const Vec4<double> d = evaluated->pipeline.clipMatrix() * v.homogeneous();
                inside = inside && clipVerdict(h, exact.clipVolume).inside;
                differing += clipVerdict(h, exact.clipVolume).outside != clipVerdict(d, exact.clipVolume).outside;
            }
            exactInside += inside;
        }
        EXPECT_EQ(evaluated->outcomes.clip->segments.inside, exactInside) << text;
    }
    EXPECT_GT(differing, 0) << "no scene where double and exact disagree: the test proves nothing";
}


// Two boxes stacked: the top of the lower and the bottom of the upper are one square, at exactly the same
// depth everywhere, so they never fight (a fight is two depths that differ but are stored alike). Seen
// obliquely, double computes the two planes' depths a rounding apart at some samples and calls them a
// fight; decided exactly, no pair fights, wherever the eye is.
TEST(ExactVerdicts, FacesAtTheSameDepthDoNotFight)
{
    std::mt19937 random(46);
    std::uniform_int_distribution<int> coordinate(-9, 9);
    int doubleFights = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const std::string eye = std::to_string(coordinate(random)) + ", " + std::to_string(coordinate(random)) + ", " +
                                std::to_string(20 + coordinate(random));
        const std::string text = R"({"camera": {"look_at": {"eye": [)" + eye + R"(], "center": [0.5, 0.5, 1], "up": [0, 1, 0]},
            "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": 100}},
            "objects": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]}, {"type": "box", "min": [0, 0, 1], "max": [1, 1, 2]}],
            "effects": [{"depth": {"bits": 16}}]})";
        const Scene scene = parseScene(text, ".");
        const auto evaluated = evaluateScene(scene);
        ASSERT_TRUE(evaluated->outcomes.depth);
        EXPECT_TRUE(evaluated->outcomes.depth->zFighting.empty()) << text;
        std::vector<PolygonMesh> boxes;
        for (const auto& mesh : evaluated->meshes)
            boxes.push_back(*mesh);
        doubleFights += int(runEffects(evaluated->pipeline, boxes, scene.effects).depth->zFighting.size());
    }
    EXPECT_GT(doubleFights, 0) << "double never called them a fight: the test proves nothing";
}


// Two walls of 900 squares each, 1 mm apart 300 units away, seen through a camera whose matrix has roots
// (so double's matrix is not the exact one): a 16-bit buffer cannot order them. Every sample's verdict is
// far from a boundary, so double decides them all, as fast as before, and finds the fights double finds.
TEST(ExactVerdicts, LargeMeshesAreDecidedInDouble)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [3, 2, 10], "center": [0, 0, -300], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 0.1, "far": 1000}},
        "effects": [{"depth": {"bits": 16}}]})", ".");
    auto wall = [](double z, double shift) {
        PolygonMesh mesh;
        const int n = 30;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                mesh.vertices.emplace_back(-20 + shift + 40.0 * i / n, -20 + shift + 40.0 * j / n, z);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const int k = i * (n + 1) + j;
                mesh.faces.push_back(std::vector<int>{k, k + n + 1, k + n + 2, k + 1});
            }
        return mesh;
    };
    const std::vector<PolygonMesh> walls = {wall(-300, 0), wall(-300.001, 0.37)};
    const Pipeline<double> pipeline = buildPipeline(scene.camera, scene.effects);
    const Mat4<Exact> exactClip = exactPipeline(scene).clipMatrix();
    ASSERT_NE(exactClip, pipeline.clipMatrix().cast<Exact>().eval()) << "the double matrix is exact: the test proves nothing";
    const DepthOutcome filtered = *runEffects(pipeline, walls, scene.effects, &exactClip).depth;
    const DepthOutcome inDouble = *runEffects(pipeline, walls, scene.effects).depth;
    EXPECT_GT(filtered.zFighting.size(), 100u);
    EXPECT_EQ(filtered.zFighting, inDouble.zFighting);
    EXPECT_EQ(filtered.decidedExactly, 0);
}


// glOrtho(-1, 1, -1, 1, 0, 131070) and a 16-bit buffer: a square at z = -(2k + 1) has window depth exactly
// (k + 1/2) / 65535, half-way between two levels, and is stored at the even one (round half to even); a
// second square half a unit behind (k odd) or in front (k even) is stored there too, at another depth: a
// fight. The clip matrix's -1/65535 is no double, so double puts the first square on either side of the
// half-way point and misses some fights; decided exactly, every pair fights.
TEST(ExactVerdicts, DepthsHalfwayBetweenLevelsAreStoredAtTheEvenOne)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
        "projection": {"type": "ortho", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": 131070}},
        "effects": [{"depth": {"bits": 16}}]})", ".");
    const Pipeline<double> pipeline = buildPipeline(scene.camera, scene.effects);
    const Mat4<Exact> exactClip = exactPipeline(scene).clipMatrix();
    auto square = [](double z, double size) {
        PolygonMesh mesh;
        mesh.vertices = {{-size, -size, z}, {size, -size, z}, {size, size, z}, {-size, size, z}};
        mesh.faces.push_back(std::vector<int>{0, 1, 2, 3});
        return mesh;
    };
    int missed = 0;
    for (int k = 1; k <= 400; ++k) {
        const double halfway = -(2 * k + 1), other = halfway + (k % 2 ? -0.5 : 0.5);
        const std::vector<PolygonMesh> squares = {square(halfway, 0.5), square(other, 0.7)};
        EXPECT_EQ(runEffects(pipeline, squares, scene.effects, &exactClip).depth->zFighting.size(), 1u) << k;
        missed += runEffects(pipeline, squares, scene.effects).depth->zFighting.empty();
    }
    EXPECT_GT(missed, 0) << "double found every fight: the test proves nothing";
}

} // namespace
} // namespace viewpipe
