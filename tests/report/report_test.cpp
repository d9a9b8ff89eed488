// The report library in process: LaTeX with exact fractions, the JSON objects
// scripts rely on (docs/cli.md), and the one number format of the tables.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include <unistd.h>

#include "build_paths.h"
#include "viewpipe/format.hpp"
#include "viewpipe/report/bench.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/lesson_latex.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/evaluated_scene.hpp"

namespace viewpipe {
namespace {

using Json = nlohmann::json;

const std::filesystem::path kScenes = std::filesystem::path(viewpipe::build::dataDir) / "scenes";

Scene sceneFrom(const std::string& json)
{
    return parseScene(json, std::filesystem::temp_directory_path());
}

// The LaTeX from `begin` on.
std::string after(const std::string& latex, const std::string& begin)
{
    const std::size_t at = latex.find(begin);
    EXPECT_NE(at, std::string::npos) << begin << " not in\n" << latex;
    return at == std::string::npos ? std::string() : latex.substr(at);
}

std::vector<std::string> keys(const Json& object)
{
    std::vector<std::string> out;
    for (const auto& item : object.items())
        out.push_back(item.key());
    return out;
}

// The seeds' glOrtho example (seed 001): l, r = -20, 30; b, t = 10, 50;
// n, f = 15, -25. P's entries 2/(r-l) = 1/25, -(r+l)/(r-l) = -1/5,
// 2/(t-b) = 1/20, -(t+b)/(t-b) = -3/2, -2/(f-n) = 1/20, -(f+n)/(f-n) = -1/4.
TEST(Latex, GlOrthoSeedPrintsExactFractions)
{
    const Scene scene = sceneFrom(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1],
        "up": [0, 1, 0]}, "projection": {"type": "ortho", "left": -20, "right": 30, "bottom": 10, "top": 50,
        "near": 15, "far": -25}}})");
    const std::string projection = after(report::matricesLatex(scene, 4), "P =\n\\begin{bmatrix}");
    EXPECT_NE(projection.find("\\frac{1}{25} & 0 & 0 & -\\frac{1}{5} \\\\\n"), std::string::npos) << projection;
    EXPECT_NE(projection.find("0 & \\frac{1}{20} & 0 & -\\frac{3}{2} \\\\\n"), std::string::npos) << projection;
    EXPECT_NE(projection.find("0 & 0 & \\frac{1}{20} & -\\frac{1}{4} \\\\\n"), std::string::npos) << projection;
    EXPECT_NE(projection.find("0 & 0 & 0 & 1\n\\end{bmatrix}"), std::string::npos) << projection;
}

// data/scenes/opengl-ortho.json: l, r = -20, 20; b, t = -15, 15; n, f = 10, 80:
// 1/20, 1/15, -2/70 = -1/35 and -(f+n)/(f-n) = -9/7.
TEST(Latex, OpenGlOrthoSceneProjectionIsExact)
{
    const std::string projection =
        after(report::matricesLatex(loadScene(kScenes / "opengl-ortho.json"), 4), "P =\n\\begin{bmatrix}");
    EXPECT_NE(projection.find("\\frac{1}{20} & 0 & 0 & 0 \\\\\n"), std::string::npos) << projection;
    EXPECT_NE(projection.find("0 & \\frac{1}{15} & 0 & 0 \\\\\n"), std::string::npos) << projection;
    EXPECT_NE(projection.find("0 & 0 & -\\frac{1}{35} & -\\frac{9}{7} \\\\\n"), std::string::npos) << projection;
}

// Foley's house: PRP (8, 6, 84), window centered on the VRP, B = 25, so
// DOP = (-8, -6, -84), SH_per's shx = -dopx/dopz = -2/21, shy = -1/14, and
// S_per = diag(2 vrp'z / (100 (vrp'z + B)), ..., -1 / (vrp'z + B)) with
// vrp'z = -84: 42/1475 and 1/59.
TEST(Latex, HouseStagesAreExact)
{
    const Scene house = loadScene(kScenes / "house.json");
    const std::string shear = report::stageLatex(house, 4, 4);
    EXPECT_EQ(shear.substr(0, shear.find('\n')), "\\mathit{SH}_{\\mathrm{per}} =");
    EXPECT_NE(shear.find("  1 & 0 & -\\frac{2}{21} & 0 \\\\\n  0 & 1 & -\\frac{1}{14} & 0 \\\\\n"),
              std::string::npos)
        << shear;
    const std::string scale = report::stageLatex(house, 5, 4);
    EXPECT_NE(scale.find("  \\frac{42}{1475} & 0 & 0 & 0 \\\\\n  0 & \\frac{42}{1475} & 0 & 0 \\\\\n"
                         "  0 & 0 & \\frac{1}{59} & 0 \\\\\n"),
              std::string::npos)
        << scale;
    const std::string all = report::matricesLatex(house, 4);
    EXPECT_NE(all.find("N_{\\mathrm{per}} &= S_{\\mathrm{per}} \\, \\mathit{SH}_{\\mathrm{per}} \\, "
                       "T(-\\mathit{PRP}) \\, R \\, T(-\\mathit{VRP}) \\\\\n&="),
              std::string::npos)
        << all;
}

// Each stage as the Matrices panel shows it, in symbols (defined by its notes) and in numbers; the product so
// far, M_k = (stage k) M_{k-1}; the composite, which is M_5, written once; and Foley's z_min, exact.
TEST(Latex, HouseMatricesHaveSymbolsNumbersProductsAndZMin)
{
    const std::string all = report::matricesLatex(loadScene(kScenes / "house.json"), 4);
    EXPECT_NE(all.find("\\mathit{SH}_{\\mathrm{per}} = \\begin{bmatrix}\n1 & 0 & \\mathit{sh}_x & 0 \\\\\n"), std::string::npos) << all;
    EXPECT_NE(all.find("\\mathit{sh}_x = -\\mathit{DOP}_x / \\mathit{DOP}_z"), std::string::npos);
    EXPECT_NE(all.find("M_{3} = T(-\\mathit{PRP}) \\, M_{2} =\n\\begin{bmatrix}\n  1 & 0 & 0 & -8 \\\\\n"), std::string::npos) << all;
    EXPECT_NE(all.find("M_{4} = \\mathit{SH}_{\\mathrm{per}} \\, M_{3} ="), std::string::npos);
    EXPECT_EQ(all.find("M_{5} = S_{\\mathrm{per}}"), std::string::npos); // the composite
    EXPECT_NE(all.find("&= M_{5} = \n\\begin{bmatrix}"), std::string::npos);
    // z_min = -(vrp'_z + F) / (vrp'_z + B) = -24/59, exact (pipeline --json's zmin, -0.40678).
    EXPECT_NE(all.find("z_{\\min} = -\\frac{\\mathit{vrp}'_z + F}{\\mathit{vrp}'_z + B} = -\\frac{24}{59}"), std::string::npos);
}

// Stage names are math: Vulkan's reversed depth stage is NDC sub "Vulkan, reversed", in the comments too.
TEST(Latex, StageNamesAreMath)
{
    const std::string all = report::matricesDocument(loadScene(kScenes / "apis/vulkan-reversed-infinite.json"), 4);
    EXPECT_NE(all.find("\\mathit{NDC}_{\\text{Vulkan, reversed}}"), std::string::npos);
    EXPECT_NE(all.find("% 5. NDC_(Vulkan, reversed): "), std::string::npos) << all;
    EXPECT_EQ(all.find("vulkan_reversed"), std::string::npos);
    EXPECT_EQ(all.find("vulkan\\_reversed"), std::string::npos);
}

// matrices.tex of every built-in scene \input (as the standalone package
// lets it) into a 12 cm column (a lecture's notes): no display wider than the
// text, every font at its size. The house's also on its own: one page.
TEST(Latex, EveryBuiltInScenesMatricesFitATwelveCentimetreColumn)
{
    ASSERT_EQ(std::system("pdflatex --version > /dev/null 2>&1"), 0)
        << "pdflatex is missing: scripts/install-deps.sh --test installs TeX Live";
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("viewpipe-latex-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::string document = "\\documentclass[a4paper]{article}\n\\usepackage[textwidth=12cm]{geometry}\n"
                           "\\usepackage{amsmath}\n\\usepackage{standalone}\n\\begin{document}\n";
    int scenes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes)) {
        if (entry.path().extension() != ".json")
            continue;
        const std::string name = "m" + std::to_string(scenes++) + ".tex";
        std::ofstream(dir / name) << report::matricesDocument(loadScene(entry.path()), 4);
        document += "% " + entry.path().filename().string() + "\n\\input{" + name + "}\n\\clearpage\n";
    }
    std::ofstream(dir / "all.tex") << document << "\\end{document}\n";
    const std::string run = "cd '" + dir.string() + "' && pdflatex -interaction=nonstopmode -halt-on-error all.tex > /dev/null 2>&1";
    EXPECT_EQ(std::system(run.c_str()), 0) << "see " << (dir / "all.log");
    std::ifstream log(dir / "all.log");
    const std::string text((std::istreambuf_iterator<char>(log)), {});
    EXPECT_EQ(text.find("Overfull \\hbox"), std::string::npos) << text.substr(text.find("Overfull"), 400);
    EXPECT_EQ(text.find("Font Warning"), std::string::npos) << text.substr(text.find("Font Warning"), 400);
    EXPECT_GT(scenes, 15);
    std::ofstream(dir / "house.tex") << report::matricesDocument(loadScene(kScenes / "house.json"), 4);
    const std::string alone = "cd '" + dir.string() + "' && pdflatex -interaction=nonstopmode -halt-on-error house.tex > /dev/null 2>&1";
    EXPECT_EQ(std::system(alone.c_str()), 0) << "see " << (dir / "house.log");
    const std::string pages = "pdfinfo '" + (dir / "house.pdf").string() + "' | grep -q '^Pages: *1$'";
    EXPECT_EQ(std::system(pages.c_str()), 0) << "house.pdf is not one page";
    if (!HasFailure())
        std::filesystem::remove_all(dir);
}

TEST(Latex, OneEntryIsExactWhereItIsAFraction)
{
    // Foley's SH_per for the house: shx = -DOPx/DOPz = -8/84 = -2/21.
    const Scene house = loadScene(kScenes / "house.json");
    EXPECT_EQ(report::entryLatex(house, 4, 1, 3, 6), "-\\frac{2}{21}");
    EXPECT_EQ(report::entryLatex(house, 4, 1, 1, 6), "1");
}

// Foley's R for VPN (1, 0, 1): u = (sqrt2/2, 0, -sqrt2/2), n = (sqrt2/2, 0, sqrt2/2), as the book writes it.
TEST(Latex, RootsAreWrittenAsTheTextbookDoes)
{
    const Scene oblique = sceneFrom(R"({"view": {"projection": "parallel", "vrp": [0, 0, 0], "vpn": [1, 0, 1],
        "vup": [0, 1, 0], "prp": [0, 0, 10], "window": [-1, 1, -1, 1], "front": 1, "back": -1}})");
    EXPECT_NE(report::stageLatex(oblique, 2, 4).find("\\frac{\\sqrt{2}}{2} & 0 & -\\frac{\\sqrt{2}}{2} & 0"),
              std::string::npos) << report::stageLatex(oblique, 2, 4);
    // Roots no one reads exactly (vup x n for an eye at (30, 25, 80)) are decimals to the digits asked.
    const Scene gl = loadScene(kScenes / "opengl-ortho.json");
    EXPECT_EQ(report::entryLatex(gl, 2, 2, 1, 4), "-0.1809");
    EXPECT_EQ(report::entryLatex(gl, 2, 1, 1, 4), "\\frac{19\\sqrt{482}}{482}");
}

// A lesson's answer as the app, the page and the handout state it: exactly where that reads well, the decimal
// beside. The house from its corner (VPN (1, 0, 1)): R's entry (1, 1) is sqrt(2)/2, SH_per's (2, 3) -13/36;
// R takes (1, 0, 0) to its first column, (sqrt(2)/2, 0, sqrt(2)/2), with the VRP at the origin.
TEST(Latex, LessonAnswersAreStatedExactly)
{
    const auto answer = [](const std::string& scene, const std::string& question) {
        const Lesson lesson = parseLesson(R"({"title": "t", "steps": [{"scene": )" + scene +
                                              R"(, "caption": "c", "question": )" + question + "}]}", kScenes);
        return report::answerText(lesson.steps[0]);
    };
    const std::string corner = "\"house-corner.json\"";
    EXPECT_EQ(answer(corner, R"({"kind": "entry", "prompt": "p", "stage": 2, "row": 1, "column": 1})"),
              "$\\frac{\\sqrt{2}}{2}$ ($0.707107$)");
    EXPECT_EQ(answer(corner, R"({"kind": "entry", "prompt": "p", "stage": 4, "row": 2, "column": 3})"),
              "$-\\frac{13}{36}$ ($-0.361111$)");
    EXPECT_EQ(answer(R"({"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [1, 0, 1], "vup": [0, 1, 0],
                         "prp": [0, 0, 10], "window": [-1, 1, -1, 1], "front": 5, "back": -5}})",
                     R"({"kind": "where", "prompt": "p", "point": [1, 0, 0], "after": 2})"),
              "$(\\frac{\\sqrt{2}}{2}, 0, \\frac{\\sqrt{2}}{2})$ ($\\approx (0.707107, 0, 0.707107)$)");
}

// A question's point typed as expressions is stated and traced exactly: gluPerspective(60, 1, 1, 10) takes
// (3 sqrt(3), sqrt(3), -9) to (9, 3, 79/9, 9) in clip coordinates, (1, 1/3, 79/81) after the divide.
TEST(Latex, AQuestionsPointIsStatedAndTracedExactly)
{
    const Lesson lesson = parseLesson(R"j({"title": "t", "steps": [{"scene": {"camera": {
        "look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": 10}}}, "caption": "c",
        "question": {"kind": "where", "prompt": "p", "point": ["3*sqrt(3)", "√3", -9], "after": 4}}]})j", kScenes);
    const LessonStep& step = lesson.steps[0];
    EXPECT_NE(report::questionContext(step).find("The point $(3\\sqrt{3}, \\sqrt{3}, -9)$."), std::string::npos)
        << report::questionContext(step);
    EXPECT_EQ(report::answerText(step), "$(1, \\frac{1}{3}, \\frac{79}{81})$ ($\\approx (1, 0.333333, 0.975309)$)");
    const std::vector<std::string> traced = report::tracedLatex(step.scene, exactPoint(*step.question), 4, 4);
    ASSERT_EQ(traced.size(), 5u);
    EXPECT_EQ(traced[0], "(3\\sqrt{3}, \\sqrt{3}, -9, 1)");
    EXPECT_EQ(traced[4], "(9, 3, \\frac{79}{9}, 9)");
}

TEST(PipelineJson, HouseHasTheContractedKeys)
{
    const Scene house = loadScene(kScenes / "house.json");
    const Json j = report::pipelineJson(house, report::PrecisionChoice{}, evaluateScene(house)->outcomes);
    EXPECT_EQ(keys(j), (std::vector<std::string>{"composite", "convention", "precision", "projection", "stages",
                                                 "zmin"}));
    EXPECT_EQ(j["convention"], "foley");
    EXPECT_EQ(j["projection"], "perspective");
    EXPECT_EQ(j["precision"], "double");
    ASSERT_EQ(j["stages"].size(), 5u);
    for (const Json& stage : j["stages"])
        EXPECT_EQ(keys(stage), (std::vector<std::string>{"cumulative", "explanation", "matrix", "symbol"}));
    EXPECT_EQ(j["stages"][3]["symbol"], "SH_per");
    EXPECT_NEAR(j["stages"][3]["matrix"][0][2].get<double>(), -2.0 / 21, 1e-16);
    EXPECT_NEAR(j["zmin"].get<double>(), -24.0 / 59, 1e-16);
    EXPECT_EQ(j["stages"][4]["cumulative"], j["composite"]);
}

// OpenGL's divide is written as what it does, not as the identity matrix it leaves in products.
TEST(PipelineJson, DivideStageSaysItDivides)
{
    const Scene scene = sceneFrom(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": 10}},
        "effects": ["divide"]})");
    const Json j = report::pipelineJson(scene, report::PrecisionChoice{}, evaluateScene(scene)->outcomes);
    const Json& divide = j["stages"].back();
    EXPECT_EQ(divide["symbol"], "divide");
    EXPECT_EQ(divide["divides"], "(x, y, z, w) -> (x/w, y/w, z/w, 1)");
    EXPECT_FALSE(j["stages"][0].contains("divides"));
    std::ostringstream text;
    report::printPipeline(text, scene, report::PrecisionChoice{}, evaluateScene(scene)->outcomes);
    EXPECT_NE(text.str().find("(x, y, z, w) -> (x/w, y/w, z/w, 1), not a matrix"), std::string::npos);
    EXPECT_NE(text.str().find("P * V = P_depth * S_fovy * R_eye * T(-eye)\n"), std::string::npos);
    const std::string tex = report::matricesLatex(scene, 4);
    EXPECT_NE(tex.find("(x, y, z, w) \\mapsto \\left(\\frac{x}{w}"), std::string::npos);
    EXPECT_NE(tex.find("P \\, V &= P_{\\mathrm{depth}}"), std::string::npos);
}

TEST(PipelineJson, WidePrecisionsAreStrings)
{
    const Scene house = loadScene(kScenes / "house.json");
    const Json j = report::pipelineJson(house, report::parsePrecision("float128"), {});
    EXPECT_EQ(j["precision"], "float128");
    ASSERT_TRUE(j["zmin"].is_string());
    EXPECT_EQ(j["zmin"].get<std::string>().substr(0, 20), "-4.06779661016949152");
    EXPECT_EQ(report::precisionName(report::parsePrecision("mpfr", 300)), "mpfr-300");
}

TEST(TraceJson, HouseHasTheContractedKeys)
{
    const Scene house = loadScene(kScenes / "house.json");
    const Json j = report::traceJson(house, Vec3<Exact>(16, 10, 54), report::PrecisionChoice{});
    EXPECT_EQ(keys(j), (std::vector<std::string>{"clip", "convention", "divided", "inside", "on_planes", "point",
                                                 "precision", "projection", "stages"}));
    EXPECT_EQ(j["point"], Json({16.0, 10.0, 54.0}));
    // After T(-PRP) the point is (16 - 8, 10 - 6, 54 - 84).
    EXPECT_EQ(j["stages"][2]["point"], Json({8.0, 4.0, -30.0, 1.0}));
}

// glFrustum(-2, 2, -1.5, 1.5, 2, 10): in double the near plane's center came out at z = -1 - 2^-52... and
// "outside" (-3/2 is -1.4999999999999998 there); a verdict is the scene's as typed, in every precision.
TEST(TraceJson, VerdictsAreExactInEveryPrecision)
{
    const Scene frustum = parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 0], "center": [0, 0, -1], "up": [0, 1, 0]},
        "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}}})",
                                     ".");
    struct Case { Vec3<Exact> point; std::vector<std::string> on; bool inside; };
    const Case cases[] = {{{0, 0, -2}, {"near"}, true},
                          {{2, parseExact("1.5"), -2}, {"right", "top", "near"}, true},
                          {{0, 0, -10}, {"far"}, true},
                          {{-10, parseExact("-7.5"), -10}, {"left", "bottom", "far"}, true},
                          {{0, 0, -5}, {}, true},
                          {{0, 0, parseExact("-1.999999999999999999999")}, {}, false},
                          {{parseExact("0.1"), 0, -2}, {"near"}, true}};
    for (const char* precision : {"float", "double", "long-double", "float128", "mpfr", "exact"})
        for (const Case& c : cases) {
            const Json j = report::traceJson(frustum, c.point, report::parsePrecision(precision));
            EXPECT_EQ(j["inside"], c.inside) << precision << " " << c.point.transpose();
            EXPECT_EQ(j["on_planes"], Json(c.on)) << precision << " " << c.point.transpose();
        }
    // 0.1 is no double: the trace says the point was rounded.
    EXPECT_TRUE(report::traceJson(frustum, Vec3<Exact>(parseExact("0.1"), 0, -2), {}).contains("rounded"));
    EXPECT_FALSE(report::traceJson(frustum, Vec3<Exact>(parseExact("0.5"), 0, -2), {}).contains("rounded"));
    const Json exact = report::traceJson(frustum, Vec3<Exact>(2, parseExact("1.5"), -2), report::parsePrecision("exact"));
    EXPECT_EQ(exact["exact"]["divided"], Json({"1", "1", "-1"}));
    EXPECT_EQ(exact["exact"]["point"], Json({"2", "3/2", "-2"}));
}

// Every canonical volume's corners, edges' midpoints, faces' centers and center, taken exactly from the
// view volume as typed (Foley's perspective and parallel volumes, OpenGL's, Direct3D's, Vulkan's, Metal's,
// WebGPU's, reversed depth): inside, on 3, 2, 1 and 0 of its planes, in every precision.
TEST(TraceJson, EveryCanonicalVolumesBoundaryIsClassifiedExactly)
{
    std::vector<Scene> scenes;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenes))
        if (entry.path().extension() == ".json")
            scenes.push_back(loadScene(entry.path()));
    for (const char* api : {"opengl", "direct3d", "vulkan"}) // reversed depth
        scenes.push_back(sceneFrom(std::string(R"({"camera": {"api": ")") + api + R"(", "depth": "reversed",
            "look_at": {"eye": [1, 2, 9], "center": [0, 0, 0], "up": [0, 1, 0]},
            "projection": {"type": "frustum", "left": -2, "right": 2, "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}}})"));
    int checked = 0;
    for (const Scene& scene : scenes) {
        const CameraSpec<Exact> camera = exactCamera(scene);
        if (const auto* gl = std::get_if<gl::Camera<Exact>>(&camera); gl && !gl::hasFarFace(*gl))
            continue; // no far face: no corners
        const std::array<Vec3<Exact>, 8> corners =
            std::visit([](const auto& c) { return viewVolumeCorners(c); }, camera);
        if (!std::all_of(corners.begin(), corners.end(), [](const Vec3<Exact>& p) {
                return p.x().isExact() && p.y().isExact() && p.z().isExact();
            }))
            continue; // gluPerspective at an angle whose cotangent is no root: no exact boundary to stand on
        std::vector<std::pair<Vec3<Exact>, std::size_t>> points; // a point and how many planes it lies on
        for (const Vec3<Exact>& corner : corners)
            points.push_back({corner, 3});
        const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        for (const auto& face : faces) {
            Vec3<Exact> center = Vec3<Exact>::Zero();
            for (int k = 0; k < 4; ++k) {
                center += corners[std::size_t(face[k])];
                points.push_back({Vec3<Exact>((corners[std::size_t(face[k])] + corners[std::size_t(face[(k + 1) % 4])]) / Exact(2)), 2});
            }
            points.push_back({Vec3<Exact>(center / Exact(4)), 1});
        }
        Vec3<Exact> middle = Vec3<Exact>::Zero();
        for (const Vec3<Exact>& corner : corners)
            middle += corner;
        points.push_back({Vec3<Exact>(middle / Exact(8)), 0});
        for (const char* precision : {"float", "double", "long-double", "float128", "mpfr", "exact"})
            for (const auto& [point, planes] : points) {
                const Json j = report::traceJson(scene, point, report::parsePrecision(precision));
                EXPECT_TRUE(j["inside"].get<bool>()) << scene.name << " " << precision << " " << point.transpose();
                EXPECT_EQ(j["on_planes"].size(), planes) << scene.name << " " << precision << " " << point.transpose()
                                                         << " " << j["on_planes"];
            }
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

TEST(PipelineJson, ExactPrecisionGivesEveryEntryExactly)
{
    const Json j = report::pipelineJson(loadScene(kScenes / "house-corner.json"), report::parsePrecision("exact"), {});
    EXPECT_EQ(j["precision"], "exact");
    EXPECT_EQ(j["exact"]["stages"][1]["matrix"][0], Json({"sqrt(2)/2", "0", "-sqrt(2)/2", "0"}));
    EXPECT_EQ(j["exact"]["stages"][3]["matrix"][1][2], "-13/36");
    EXPECT_EQ(j["exact"]["zmin"], "-31/66");
    EXPECT_FALSE(j.contains("inexact"));
    EXPECT_EQ(j["stages"][1]["matrix"][0][0], std::sqrt(0.5)); // the usual numbers, rounded to double
    // gluPerspective at 50 degrees: cot(25 degrees) is no square-root expression.
    const Scene fifty = parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 50, "aspect": 1, "near": 1, "far": 10}}})", ".");
    const Json inexact = report::pipelineJson(fifty, report::parsePrecision("exact"), {})["inexact"];
    ASSERT_FALSE(inexact.empty());
    EXPECT_NE(inexact[0]["reason"].get<std::string>().find("cot(50 degrees / 2)"), std::string::npos) << inexact;
    const std::string sixtyText = R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1, "near": 1, "far": 10}}})";
    const Json sixty = report::pipelineJson(parseScene(sixtyText, "."), report::parsePrecision("exact"), {});
    EXPECT_EQ(sixty["exact"]["composite"][1][1], "sqrt(3)"); // cot 30 degrees
    EXPECT_FALSE(sixty.contains("inexact"));
}

TEST(ClassifyJson, HouseHasTheContractedKeys)
{
    const Json j = report::classifyJson(loadScene(kScenes / "house.json"));
    EXPECT_EQ(keys(j), (std::vector<std::string>{"alpha_deg", "description", "family", "foreshortening", "kind",
                                                 "projection", "vanishing_points"}));
    EXPECT_EQ(j["projection"], "perspective");
    // The view plane is z = 0: only lines along z converge.
    ASSERT_EQ(j["vanishing_points"].size(), 1u);
    EXPECT_EQ(j["vanishing_points"][0]["axis"], "z");
}

BenchResult oneRow()
{
    BenchResult result;
    result.reference = "mpfr-256";
    result.vertices = 10;
    result.viewport = {640, 480};
    BenchRow row;
    row.precision = "float";
    row.bits = 24;
    row.epsilon = std::ldexp(1.0, -23);
    row.buildNs = 123.456;
    row.errors.maxRelativeError = 3 * row.epsilon;
    result.rows.push_back(row);
    return result;
}

TEST(BenchReport, JsonHasTheContractedKeys)
{
    const Json j = report::benchJson(oneRow());
    EXPECT_EQ(keys(j), (std::vector<std::string>{"reference", "rows", "vertices", "viewport", "volume"}));
    EXPECT_EQ(j["viewport"], Json({640, 480}));
    ASSERT_EQ(j["rows"].size(), 1u);
    EXPECT_EQ(keys(j["rows"][0]),
              (std::vector<std::string>{"bits", "build_ns", "corner_error", "determinant_error", "epsilon",
                                        "max_rel_error", "ndc_max_error", "ndc_rms_error", "orthogonality_error",
                                        "pixel_max_error", "pixel_rms_error", "precision", "roundtrip_error",
                                        "vertex_ns"}));
}

TEST(BenchReport, TableGivesErrorsInUnitsOfEpsilon)
{
    std::ostringstream out;
    report::printBench(out, oneRow());
    const std::string table = out.str();
    EXPECT_NE(table.find("Reference: mpfr-256; 10 vertices timed; pixel errors at 640x480."), std::string::npos);
    // 3 * 2^-23 = 3.58e-07, three epsilons; the build time to three digits.
    EXPECT_NE(table.find("3.6e-07 [3]"), std::string::npos) << table;
    EXPECT_NE(table.find("123"), std::string::npos) << table;
    EXPECT_EQ(table.find("123.4"), std::string::npos) << table;
}

TEST(Format, SignificantDigits)
{
    EXPECT_EQ(formatSignificant(-0.0, 6), "0");
    EXPECT_EQ(formatSignificant(2.0 / 3, 3), "0.667");
    EXPECT_EQ(formatSignificant(1.5e-7, 2), "1.5e-07");
    EXPECT_EQ(formatSignificant(-24.0 / 59, 5), "-0.40678");
}

// Written out in full unless that takes more than three zeros after the point
// or five before it; every text reads back as the same double.
TEST(Format, ShortestRoundTrip)
{
    EXPECT_EQ(formatShortest(-0.0), "0");
    EXPECT_EQ(formatShortest(0.1), "0.1");
    EXPECT_EQ(formatShortest(-12.5), "-12.5");
    EXPECT_EQ(formatShortest(1.0 / 3), "0.3333333333333333");
    EXPECT_EQ(formatShortest(0.0001), "0.0001");
    EXPECT_EQ(formatShortest(0.00001), "1e-05");
    EXPECT_EQ(formatShortest(100000), "100000");
    EXPECT_EQ(formatShortest(1000000), "1e+06");
    EXPECT_EQ(formatShortest(1500000), "1500000");
    EXPECT_EQ(formatShortest(15000000), "1.5e+07");
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> mantissa(-10, 10), exponent(-30, 30);
    for (int i = 0; i < 10000; ++i) {
        const double x = mantissa(random) * std::pow(10.0, std::floor(exponent(random)));
        EXPECT_EQ(std::stod(formatShortest(x)), x) << formatShortest(x);
    }
}

// Step k's figure files, named after it: "step-K-asking.pdf" and "step-K.pdf".
std::vector<report::LessonFigures> figureFiles(const Lesson& lesson)
{
    std::vector<report::LessonFigures> figures;
    for (std::size_t k = 0; k < lesson.steps.size(); ++k)
        figures.push_back({"step-" + std::to_string(k) + "-asking.pdf", "step-" + std::to_string(k) + ".pdf"});
    return figures;
}

// The handout sets every figure, the answer key's too, at one width, their labels drawn larger to match: the
// pictures' labels are 2.4 % of their width, 11.6 pt across A4's 17 cm of text, and were 6 pt at 0.55 of it with no
// larger text (a defect found by a reader). At least 9.5 pt on paper.
TEST(LessonLatex, HandoutFiguresKeepTheirLabelsReadable)
{
    const Lesson lesson = loadLesson(std::string(viewpipe::build::dataDir) + "/lessons/foley-nper.json");
    const std::vector<report::LessonFigures> figures = figureFiles(lesson);
    const std::string handout = report::lessonHandoutLatex(lesson, figures);
    ASSERT_NE(handout.find("Answer key"), std::string::npos);
    // Every figure at that width, in a minipage of its own beside the step's text.
    const std::string set =
        "\\begin{minipage}[t]{" + formatShortest(report::kHandoutFigureWidth) + "\\linewidth}\\vspace{0pt}\\includegraphics[width=\\linewidth]{";
    const auto count = [&handout](const std::string& what) {
        std::size_t n = 0;
        for (std::size_t at = handout.find(what); at != std::string::npos; at = handout.find(what, at + 1))
            ++n;
        return n;
    };
    const std::size_t figuresSet = count(set);
    EXPECT_EQ(figuresSet, count("\\includegraphics"));
    const auto questions = std::count_if(lesson.steps.begin(), lesson.steps.end(), [](const LessonStep& step) {
        return step.question.has_value();
    });
    ASSERT_GT(questions, 0);
    EXPECT_EQ(figuresSet, lesson.steps.size() + std::size_t(questions)) << "each step, and each answer in the key";
    const double labelPoints = 0.024 * 17 / 2.54 * 72 * report::kHandoutFigureWidth * report::kHandoutFigureTextScale;
    EXPECT_GE(labelPoints, 9.5);
}

// The problem sheet: the questions with their pictures and the set-up each needs, no answer, then the solutions worked with exact
// numbers: foley-nper's question 7 traces (16, 10, 30) through five stages to S_per, whose entries are fractions.
TEST(LessonLatex, TheProblemSheetAsksThenSolvesExactly)
{
    const Lesson lesson = loadLesson(std::string(viewpipe::build::dataDir) + "/lessons/foley-nper.json");
    const std::vector<report::LessonFigures> figures = figureFiles(lesson);
    const std::string sheet = report::lessonSheetLatex(lesson, figures);
    const std::size_t solutions = sheet.find("\\section*{Solutions}");
    ASSERT_NE(solutions, std::string::npos);
    const std::string problems = sheet.substr(0, solutions), solved = sheet.substr(solutions);
    for (int k = 1; k <= 9; ++k) {
        EXPECT_NE(problems.find("\\textbf{Question " + std::to_string(k) + ".}"), std::string::npos) << k;
        EXPECT_NE(solved.find("\\subsection*{Question " + std::to_string(k) + "}"), std::string::npos) << k;
    }
    EXPECT_EQ(problems.find("Answer"), std::string::npos);
    // Each question beside its picture as it is asked, none of the pictures of the answers.
    for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
        EXPECT_NE(problems.find("{step-" + std::to_string(k) + "-asking.pdf}"), std::string::npos) << k;
        EXPECT_EQ(sheet.find("{step-" + std::to_string(k) + ".pdf}"), std::string::npos) << k;
    }
    // Foley's house view, as typed, once; the questions after on the same view say so.
    EXPECT_NE(problems.find("$\\mathit{PRP} = (8, 6, 84)$"), std::string::npos);
    EXPECT_NE(problems.find("The same set-up as question 2."), std::string::npos);
    // Question 7: the matrices T(-VRP) to S_per and the point after each, exactly.
    const std::size_t seventh = solved.find("\\subsection*{Question 7}"), eighth = solved.find("\\subsection*{Question 8}");
    const std::string worked = solved.substr(seventh, eighth - seventh);
    for (const char* symbol : {"T(-\\mathit{VRP}) =", "R =", "T(-\\mathit{PRP}) =", "\\mathit{SH}_{\\mathrm{per}} =",
                               "S_{\\mathrm{per}} ="})
        EXPECT_NE(worked.find(symbol), std::string::npos) << symbol;
    EXPECT_NE(worked.find("world & $(16, 10, 30, 1)$"), std::string::npos) << worked;
    EXPECT_NE(worked.find("$(8, 4, -54, 1)$"), std::string::npos) << worked; // after T(-PRP): (16-8, 10-6, 30-84)
    EXPECT_NE(worked.find("\\frac{"), std::string::npos); // S_per's entries, and the point after it, as fractions
    // The answer exactly, with its decimals beside it.
    EXPECT_NE(worked.find("\\textbf{Answer:} $(\\frac{552}{1475},\\allowbreak \\frac{66}{295},\\allowbreak -\\frac{54}{59})$ "
                          "($\\approx (0.374237,\\allowbreak 0.223729,\\allowbreak -0.915254)$)"),
              std::string::npos)
        << worked;
}

} // namespace
} // namespace viewpipe
