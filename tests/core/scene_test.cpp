// Scene files: Foley's house, refusals naming the field path, round trips.

#include "build_paths.h"
#include "support.hpp"
#include "viewpipe/scene.hpp"

#include <algorithm>
#include <fstream>

namespace viewpipe {
namespace {

using test::expectRefused;

const std::filesystem::path kData = viewpipe::build::dataDir;

std::string withView(const std::string& view, const std::string& rest = "")
{
    return R"({"name": "t", "view": )" + view + rest + "}";
}

const std::string kHouseView = R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1],
    "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})";

void refused(const std::string& text, const std::string& field, const std::string& reason)
{
    expectRefused([&] { parseScene(text, kData); }, field, reason);
}

TEST(Scene, FoleysHouseHasTheBooksView)
{
    const Scene scene = loadScene(kData / "scenes" / "house.json");
    const auto& spec = std::get<foley::ViewSpec<double>>(scene.camera);
    EXPECT_EQ(spec.projection, foley::Projection::Perspective);
    EXPECT_EQ(spec.prp, Vec3<double>(8, 6, 84));
    EXPECT_EQ(spec.window.umin, -50);
    EXPECT_EQ(spec.front, 60);
    EXPECT_EQ(spec.back, 25);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].type, ObjectType::House);
}

TEST(Scene, OpenGlCamera)
{
    const Scene scene = parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
        "projection": {"type": "perspective", "fovy_deg": 60, "aspect": 1.5, "near": 1, "far": "infinity"}},
        "objects": [{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}]})",
                                   kData);
    const auto& camera = std::get<gl::Camera<double>>(scene.camera);
    const auto& p = std::get<gl::Perspective<double>>(camera.projection);
    EXPECT_EQ(p.fovyDegrees, 60);
    EXPECT_TRUE(std::isinf(p.zFar));
    EXPECT_EQ(scene.objects[0].type, ObjectType::Box);
}

// The page puts mesh files opened with a scene where the scene looks for them, before they are there: the
// mesh paths as written, of each mesh object as parseScene reads it, no file looked for.
TEST(Scene, ListsTheMeshPathsItNamesWithoutTheirFiles)
{
    const std::string scene = withView(kHouseView, R"(, "objects": [{"type": "mesh", "path": "../meshes/letter-f.obj"},
        {"type": "house"}, {"type": "mesh", "path": "not/there.ply"}, {"type": "mesh", "path": "notes.txt"},
        {"type": "mesh"}, {"type": "mesh", "path": "../meshes/letter-f.obj"}])");
    EXPECT_EQ(meshPathsNamed(scene),
              (std::vector<std::string>{"../meshes/letter-f.obj", "not/there.ply", "../meshes/letter-f.obj"}))
        << "not a mesh file's name, nor a mesh without a path";
    EXPECT_TRUE(meshPathsNamed("{").empty());
    EXPECT_TRUE(meshPathsNamed(R"({"objects": {"type": "mesh", "path": "a.obj"}})").empty()) << "objects not a list";
}

TEST(Scene, RefusesWithTheFieldPath)
{
    refused("{", "1:2", "unexpected end of input");
    refused("[]", "$", "must be an object");
    refused(R"({"name": "x"})", "$", "exactly one of");
    refused(withView(kHouseView, R"(, "colour": 1)"), "colour", "unknown key");
    refused(withView(R"({"projection": "perspective"})"), "view.back", "is missing");
    refused(withView(R"({"projection": "fisheye", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.projection", "\"perspective\" or \"parallel\"");
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, "z"],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.vup[2]", "expected a number, sqrt(...) or ( at character 1 of \"z\"");
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.vrp", "array of 3 numbers");
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 0, 1],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.vup", "parallel");
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 1e999, "back": 25})"),
            "view.front", "not a finite number");
    refused(withView(kHouseView, R"(, "objects": [{"type": "teapot"}])"), "objects[0].type", "\"house\", \"box\"");
    refused(withView(kHouseView, R"(, "objects": [{"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]}])"),
            "objects[0].max", "must exceed min");
    refused(withView(kHouseView, R"(, "objects": [{"type": "mesh", "path": "nowhere.obj"}])"), "objects[0].path",
            "cannot read");
    refused(withView(kHouseView, R"(, "objects": [{"type": "mesh", "path": "scenes/house.json"}])"),
            "objects[0].path", ".obj, .ply or .stl");
    refused(withView(kHouseView, R"(, "effects": {})"), "effects", "must be an array");
    refused(withView(kHouseView, R"(, "effects": [{"depth": {"bits": 8}}])"), "effects[0].depth.bits",
            "must be 16, 24 or 32 (got 8)");
    refused(withView(kHouseView, R"(, "effects": [{"depth": {"bits": 4294967312}}])"), "effects[0].depth.bits",
            "must be 16, 24 or 32 (got 4294967312)");
    refused(withView(kHouseView, R"(, "effects": [{"depth": {"bits": "24"}}])"), "effects[0].depth.bits",
            "must be 16, 24 or 32");
    refused(withView(kHouseView, R"(, "effects": ["sparkle"])"), "effects[0]", "unknown effect \"sparkle\"");
    refused(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
        "projection": {"type": "frustum", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": 9}}})",
            "camera.projection.near", "greater than 0");
    refused(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0], "roll": 0},
        "projection": {"type": "ortho", "left": -1, "right": 1, "bottom": -1, "top": 1, "near": 0, "far": 9}}})",
            "camera.look_at.roll", "unknown key");
}

TEST(Scene, SyntaxErrorsNameLineAndColumn)
{
    const std::string text = "{\n  \"name\": \"t\",\n  \"objects\": [{\"type\": \"house\"}\n  }\n";
    try {
        parseScene(text, kData);
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_TRUE(e.isPosition());
        EXPECT_EQ(e.field(), "4:3");
        EXPECT_EQ(e.reason(), "unexpected '}'; expected ']'");
        EXPECT_EQ(e.describe("scene.json"), "scene.json:4:3: unexpected '}'; expected ']'");
    }
    // A field error keeps the "FILE: field: reason" form.
    EXPECT_EQ(InputError("view.vup", "is missing").describe("scene.json"), "scene.json: view.vup: is missing");
    refused("{\"name\": tru}", "1:13", "invalid literal");
    refused("", "1:1", "unexpected end of input");
    refused("{} {}", "1:4", "expected end of input");
}

TEST(Scene, NumberOverflowNamesTheField)
{
    refused(withView(R"({"projection": "perspective", "vrp": [1e999, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.vrp[0]", "not a finite number");
    refused(withView(kHouseView, R"(, "objects": [{"type": "house"},
        {"type": "box", "min": [0, 0, -1e999], "max": [1, 1, 1]}])"),
            "objects[1].min[2]", "not a finite number");
    refused(withView(kHouseView, R"(, "objects": [[[]], [-1E+400]])"), "objects[1][0]", "not a finite number");
    refused("1e999", "$", "not a finite number");
}

// NaN and Infinity, as JavaScript writes them, are named at their field (found: "8:19: invalid literal;
// last read: '6, N'"); a word that is no literal elsewhere keeps the syntax error.
TEST(Scene, NanAndInfinityAreNamedAtTheirField)
{
    const std::string reason = "NaN and Infinity are not JSON numbers: write a finite number";
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, NaN], "window": [-50, 50, -50, 50], "front": 60, "back": 25})"),
            "view.prp[2]", reason);
    refused(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0],
        "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": -Infinity, "back": 25})"),
            "view.front", reason);
    refused("{\"name\": tru}", "1:13", "invalid literal");
}

TEST(Scene, SaveLoadRoundTripIsAtomic)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "viewpipe-scene-test";
    std::filesystem::create_directories(dir);
    Scene scene = loadScene(kData / "scenes" / "house.json");
    scene.objects.push_back({ObjectType::Box, {1, 2, 3}, {4, 5, 6}, "", ""});
    const std::filesystem::path file = dir / "saved.json";
    saveScene(scene, file);
    const Scene again = loadScene(file);
    EXPECT_EQ(sceneToJson(again), sceneToJson(scene));
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "saved.json") << "temporary file left behind";
    // A save into a folder that does not exist fails and leaves nothing behind.
    EXPECT_THROW(saveScene(scene, dir / "missing" / "x.json"), InputError);
    std::filesystem::remove_all(dir);
}

// Found: Save rewrote the whole file (keys sorted, 8 written 8.0, an array a number a line): four edits made a
// 36-line diff. Now each edited value changes in place, and nothing else.
TEST(Scene, SavingChangesOnlyTheValuesEdited)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "viewpipe-scene-style-test";
    std::filesystem::create_directories(dir);
    auto lines = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        std::vector<std::string> all;
        for (std::string line; std::getline(in, line);)
            all.push_back(line);
        return all;
    };
    for (const char* name : {"house.json", "opengl-perspective.json"}) {
        const std::filesystem::path file = dir / name;
        std::filesystem::copy_file(kData / "scenes" / name, file, std::filesystem::copy_options::overwrite_existing);
        Scene scene = loadScene(file);
        if (auto* view = std::get_if<foley::ViewSpec<double>>(&scene.camera)) {
            view->vrp.x() = 1.5;
            view->prp.z() = 90;
            view->front = 61;
            view->back = 24.25;
        } else {
            auto& camera = std::get<gl::Camera<double>>(scene.camera);
            camera.lookAt.eye.y() = 31;
            std::get<gl::Perspective<double>>(camera.projection).fovyDegrees = 45;
        }
        const std::vector<std::string> before = lines(file);
        saveScene(scene, file);
        const std::vector<std::string> after = lines(file);
        ASSERT_EQ(after.size(), before.size()) << name;
        int differ = 0;
        for (std::size_t k = 0; k < after.size(); ++k)
            differ += after[k] != before[k];
        EXPECT_EQ(differ, std::string(name) == "house.json" ? 4 : 2) << name;
        EXPECT_EQ(sceneToJson(loadScene(file)), sceneToJson(scene)) << name;
        if (std::string(name) == "house.json") {
            EXPECT_NE(std::find(after.begin(), after.end(), "    \"vrp\": [1.5, 0, 0],"), after.end());
            EXPECT_NE(std::find(after.begin(), after.end(), "    \"back\": 24.25"), after.end());
        }
        // An object added changes the shape: the file is written anew, its keys still in the author's order.
        scene.objects.push_back({ObjectType::Box, {1, 2, 3}, {4, 5, 6}, "", ""});
        saveScene(scene, file);
        EXPECT_EQ(sceneToJson(loadScene(file)), sceneToJson(scene)) << name;
        EXPECT_EQ(lines(file)[1].rfind("  \"name\": ", 0), 0u) << name;
    }
    std::filesystem::remove_all(dir);
}

// A field typed into the web page's Scene panel: a decimal as people type it is that number in a number's field,
// any other text stays text (an expression the scene reads, or a refusal it names); the scene written as
// sceneToJson writes scenes, its keys in their order.
TEST(Scene, AFieldTypedIsANumberOnlyWhereItIsADecimal)
{
    const std::string house = withView(kHouseView);
    const auto prp = [](const std::string& text) { return parseScene(text, kData).camera; };
    const std::string moved = withTypedField(house, "view.prp[0]", " +20. ", true);
    EXPECT_NE(moved.find(R"("prp": [20, 6, 84])"), std::string::npos) << moved;
    EXPECT_LT(moved.find(R"("name")"), moved.find(R"("view")")) << moved;
    EXPECT_TRUE(prp(moved) == prp(withView(R"({"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1],
        "vup": [0, 1, 0], "prp": [20, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25})")));
    for (const auto& [typed, written] : {std::pair<std::string, std::string>{".5", "0.5"}, {"007", "7"}, {"1e3", "1000"},
                                         {"-2.50", "-2.5"}}) {
        EXPECT_NE(withTypedField(house, "view.front", typed, true).find(R"("front": )" + written + ","), std::string::npos)
            << typed;
    }
    // Text that is no decimal, or a number's text in a text field: text, as typed.
    EXPECT_NE(withTypedField(house, "view.prp[1]", "20*sqrt(2)", true).find(R"x("prp": [8, "20*sqrt(2)", 84])x"), std::string::npos);
    EXPECT_NE(withTypedField(house, "view.front", "inf", true).find(R"("front": "inf")"), std::string::npos);
    EXPECT_NE(withTypedField(house, "view.projection", "5", false).find(R"("projection": "5")"), std::string::npos);
    expectRefused([&] { withTypedField(house, "view.nothing", "1", true); }, "view.nothing", "is not a field");
}

} // namespace
} // namespace viewpipe
