// The viewpipe CLI as scripts use it: subcommands, JSON shape, exit codes and
// the one-line error "FILE: field.path: reason".

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "build_paths.h"

namespace {

using Json = nlohmann::json;

struct Result {
    int exitCode = -1;
    std::string out;
    std::string err;
};

const std::string kHouse = std::string(viewpipe::build::dataDir) + "/scenes/house.json";

Result run(const std::string& arguments)
{
    const std::string errFile = std::filesystem::temp_directory_path() / ("viewpipe-cli-" + std::to_string(::getpid()));
    // A bounded run: a command that hangs fails the test instead of stopping the suite.
    const std::string command = "timeout 120 " + std::string(viewpipe::build::viewpipeExe) + " " + arguments + " 2>" + errFile;
    Result result;
    FILE* pipe = ::popen(command.c_str(), "r");
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        result.out.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(errFile);
    result.err.assign(std::istreambuf_iterator<char>(err), {});
    std::filesystem::remove(errFile);
    return result;
}

std::string writeScene(const std::string& name, const std::string& text)
{
    const std::filesystem::path file = std::filesystem::temp_directory_path() / name;
    std::ofstream(file) << text;
    return file.string();
}

TEST(Cli, PipelinePrintsTheFiveStagesAndNper)
{
    const Result r = run("pipeline " + kHouse);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* symbol : {"1. T(-VRP)", "2. R", "3. T(-PRP)", "4. SH_per", "5. S_per"})
        EXPECT_NE(r.out.find(symbol), std::string::npos) << symbol;
    EXPECT_NE(r.out.find("N_per = S_per * SH_per * T(-PRP) * R * T(-VRP)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("z_min = -0.40678"), std::string::npos) << r.out;
}

TEST(Cli, PipelineJsonHasTheContractedShape)
{
    const Result r = run("pipeline " + kHouse + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["convention"], "foley");
    EXPECT_EQ(j["projection"], "perspective");
    EXPECT_EQ(j["precision"], "double");
    ASSERT_EQ(j["stages"].size(), 5u);
    const std::array<std::string, 5> symbols = {"T(-VRP)", "R", "T(-PRP)", "SH_per", "S_per"};
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_EQ(j["stages"][k]["symbol"], symbols[k]);
        ASSERT_EQ(j["stages"][k]["matrix"].size(), 4u);
        ASSERT_EQ(j["stages"][k]["cumulative"][3].size(), 4u);
    }
    EXPECT_EQ(j["stages"][4]["cumulative"], j["composite"]);
    EXPECT_NEAR(j["composite"][0][2].get<double>(), -4.0 / 1475, 1e-15);
    EXPECT_NEAR(j["composite"][2][3].get<double>(), -84.0 / 59, 1e-15);
    EXPECT_NEAR(j["zmin"].get<double>(), -24.0 / 59, 1e-15);
    EXPECT_FALSE(j.contains("view"));
}

TEST(Cli, PipelineJsonForParallelAndOpenGl)
{
    const std::string parallel = writeScene("viewpipe-parallel.json", R"({"view": {"projection": "parallel",
        "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [0, 0, 10], "window": [-1, 1, -1, 1],
        "front": 1, "back": -1}})");
    Json j = Json::parse(run("pipeline " + parallel + " --json").out);
    ASSERT_EQ(j["stages"].size(), 5u);
    EXPECT_EQ(j["stages"][2]["symbol"], "SH_par");
    EXPECT_EQ(j["stages"][3]["symbol"], "T_par");
    EXPECT_EQ(j["stages"][4]["symbol"], "S_par");
    EXPECT_FALSE(j.contains("zmin"));

    const std::string camera = writeScene("viewpipe-gl.json", R"({"camera": {"look_at": {"eye": [0, 0, 5],
        "center": [0, 0, 0], "up": [0, 1, 0]}, "projection": {"type": "frustum", "left": -4, "right": 4,
        "bottom": -3, "top": 3, "near": 5, "far": 80}}})");
    j = Json::parse(run("pipeline " + camera + " --json").out);
    EXPECT_EQ(j["convention"], "opengl");
    EXPECT_EQ(j["projection"], "frustum");
    EXPECT_NEAR(j["projection_matrix"][2][2].get<double>(), -85.0 / 75, 1e-15);
    EXPECT_EQ(j["view"][2][3], -5.0);
    EXPECT_EQ(j["stages"][0]["symbol"], "T(-eye)");
}

TEST(Cli, PrecisionsAgreeAndLongDoubleKeepsItsDigits)
{
    const Json f = Json::parse(run("pipeline " + kHouse + " --json --precision float").out);
    const Json d = Json::parse(run("pipeline " + kHouse + " --json --precision double").out);
    const Json l = Json::parse(run("pipeline " + kHouse + " --json --precision long-double").out);
    EXPECT_EQ(f["precision"], "float");
    EXPECT_NEAR(f["zmin"].get<double>(), d["zmin"].get<double>(), 1e-7);
    ASSERT_TRUE(l["zmin"].is_string());
    EXPECT_EQ(l["zmin"].get<std::string>().substr(0, 19), "-0.4067796610169491");
}

TEST(Cli, TraceFollowsAPoint)
{
    Result r = run("trace " + kHouse + " --point 16 10 54 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Json j = Json::parse(r.out);
    ASSERT_EQ(j["stages"].size(), 5u);
    EXPECT_EQ(j["stages"][2]["symbol"], "T(-PRP)");
    EXPECT_EQ(j["stages"][2]["point"], Json::parse("[8.0, 4.0, -30.0, 1.0]"));
    EXPECT_TRUE(j["inside"].get<bool>());
    // Behind the eye: outside, never divided into a false image.
    j = Json::parse(run("trace " + kHouse + " --point 8 6 84 --json").out);
    EXPECT_FALSE(j["inside"].get<bool>());
    EXPECT_TRUE(j["divided"].is_null());
    r = run("trace " + kHouse + " --point -100 0 40");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("outside the canonical view volume"), std::string::npos) << r.out;
}

TEST(Cli, CheckAndExitCodes)
{
    Result r = run("check " + kHouse);
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_TRUE(r.out.empty());

    const std::string bad = writeScene("viewpipe-bad.json", R"({"view": {"projection": "perspective",
        "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 0, 1], "prp": [8, 6, 84], "window": [-50, 50, -50, 50],
        "front": 60, "back": 25}})");
    for (const std::string command : {"check ", "pipeline ", "trace "}) {
        r = run(command + bad + (command == "trace " ? " --point 0 0 0" : ""));
        EXPECT_EQ(r.exitCode, 2) << command;
        EXPECT_EQ(r.err.rfind(bad + ": view.vup: is parallel to view.vpn (angle 0 degrees", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    // A file that is no mesh is bad input too.
    writeScene("viewpipe-junk.stl", "this is not a mesh");
    const std::string junk = writeScene("viewpipe-junk-mesh.json", R"({"view": {"projection": "perspective",
        "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50],
        "front": 60, "back": 25}, "objects": [{"type": "mesh", "path": "viewpipe-junk.stl"}]})");
    r = run("check " + junk);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(junk + ": objects[0].path: the file is too short for a binary STL"), std::string::npos) << r.err;

    // A point that is not three finite numbers is refused, in every form of trace.
    for (const std::string point : {"1 2 nan", "1 2 1e400", "inf 0 0"})
        for (const std::string form : {"", " --json", " --api all"}) {
            r = run("trace " + kHouse + " --point " + point + form);
            EXPECT_EQ(r.exitCode, 2) << point << form;
            EXPECT_NE(r.err.find("--point: must be three finite numbers"), std::string::npos) << r.err;
        }

    // Lessons are checked as scenes are: one line, the field's path, exit 2.
    const std::string lesson = writeScene("viewpipe-bad-lesson.json", R"({"title": "t", "steps": [
        {"scene": ")" + kHouse + R"(", "caption": "c", "question": {"kind": "where", "prompt": "p",
         "point": [8, 6, 84], "after": 3, "answer": [1, 2, 3]}}]})");
    r = run("lesson check " + lesson);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, lesson + ": steps[0].question.answer: is (1, 2, 3) but the scene gives (0, 0, 0)\n");
    EXPECT_EQ(run("lesson export " + lesson + " --out /tmp/viewpipe-no-lesson").exitCode, 2);
    // Math outside the subset every renderer sets is refused before anything shows it raw.
    const std::string unknownMath = writeScene("viewpipe-unknown-math-lesson.json", R"({"title": "t", "steps": [
        {"scene": ")" + kHouse + R"(", "caption": "see $\\foo{x}$"}]})");
    r = run("lesson check " + unknownMath);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind(unknownMath + ": steps[0].caption: has math with \\foo, which ViewPipe does not set", 0), 0u) << r.err;

    r = run("check /nonexistent/scene.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "/nonexistent/scene.json: $: cannot read the scene file: No such file or directory\n");

    EXPECT_EQ(run("pipeline").exitCode, 2);                             // missing SCENE
    EXPECT_EQ(run("frobnicate " + kHouse).exitCode, 2);                 // unknown subcommand
    EXPECT_EQ(run("pipeline " + kHouse + " --precision half").exitCode, 2);
    EXPECT_EQ(run("trace " + kHouse + " --point 1 2").exitCode, 2);
    r = run("--help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("pipeline"), std::string::npos);
    r = run("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out.rfind("viewpipe ", 0), 0u);
}

} // namespace

namespace {

// export's and open's --text-scale take one range, the app's Larger and Smaller Text's.
TEST(Cli, TextScaleIsOneRangeForExportAndOpen)
{
    const std::string out = (std::filesystem::temp_directory_path() / "viewpipe-text-scale").string();
    for (const std::string scale : {"49", "401"})
        for (const std::string& command : {"export " + kHouse + " --out " + out + " --text-scale ", "open " + kHouse + " --text-scale "}) {
            const Result r = run(command + scale);
            EXPECT_EQ(r.exitCode, 2) << command << scale;
            EXPECT_NE(r.err.find("--text-scale: must be a whole percent from 50 to 400 (got " + scale + ")"), std::string::npos)
                << r.err;
        }
    EXPECT_FALSE(std::filesystem::exists(out));
}

// What export leaves out: the names a lesson step's hide takes and the picture's own parts; a name it does not
// take is refused naming those it does, and nothing is written.
TEST(Cli, ExportLeavesOutWhatItIsAsked)
{
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "viewpipe-hide";
    std::filesystem::remove_all(out);
    Result r = run("export " + kHouse + " --out " + out.string() + " --hide legend,plate --quiet");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--hide: \"plate\" is not one of objects, world_axes"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    for (const std::string option : {"--zoom 0", "--legend left", "--framing loose"})
        EXPECT_EQ(run("export " + kHouse + " --out " + out.string() + " " + option + " --quiet").exitCode, 2) << option;

    // The export process ends with blocks VTK 9.1 never frees (rendering_tests says so too): under the
    // sanitizers its memory errors are still caught, its leaks not reported.
    const std::string asan = std::getenv("ASAN_OPTIONS") ? std::getenv("ASAN_OPTIONS") : "";
    ::setenv("ASAN_OPTIONS", (asan + (asan.empty() ? "" : ":") + "detect_leaks=0").c_str(), 1);
    const auto restore = [&] { ::setenv("ASAN_OPTIONS", asan.c_str(), 1); };
    auto svgOf = [&](const std::string& options) {
        std::filesystem::remove_all(out);
        const Result made = run("export " + kHouse + " --out " + out.string() + " --stages 4 --format svg --quiet " + options);
        EXPECT_EQ(made.exitCode, 0) << options << made.err;
        std::ifstream in(out / "04-sh-per.svg");
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    const std::string whole = svgOf(""), bare = svgOf("--hide legend,caption,labels,ticks,notes --legend beside --zoom 1.5");
    // A legend's line, the caption, a label, a tick number, the notice of labels left out.
    for (const char* text : {"projectors", "shear so that", "PRP", "\u221220", "left out"}) {
        EXPECT_NE(whole.find(text), std::string::npos) << text;
        EXPECT_EQ(bare.find(text), std::string::npos) << text;
    }
    restore();
    std::filesystem::remove_all(out);
}

// A window 1e300 wide: the PNG at stage 0 lost the volume, window, DOP and projectors while the SVG
// drew them, under the same caption and legend. Refused by its field before any file is written.
TEST(Cli, ExportRefusesWhatThePicturesCannotDraw)
{
    const std::string wide = writeScene("viewpipe-wide-window.json", R"({"view": {"projection": "perspective",
        "vrp": [0, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 1e300, -50, 50],
        "front": 60, "back": 25}, "objects": [{"type": "house"}]})");
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "viewpipe-wide-window";
    std::filesystem::remove_all(out);
    const Result r = run("export " + wide + " --out " + out.string() + " --stages 0 --format png,svg --quiet");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(wide + ": view.window[1]: reaches a coordinate of 1e+300 in world coordinates"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("beyond the 1e+09 the pictures can draw"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out / "00-world.png"));
    EXPECT_EQ(run("check " + wide).exitCode, 2);
    std::filesystem::remove_all(out);
}

// Found crashing `pipeline` and `open` (segmentation faults, double free inside
// VTK's readers): each is refused with its field and reason, exit 2, on one line
// (export's once began with an empty one).
TEST(Cli, HostileMeshesAreRefusedByEveryCommand)
{
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::vector<std::pair<std::string, std::string>> meshes = {
        {"obj-index-high.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
        {"obj-index-zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"},
        {"obj-index-negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n"},
        {"ply-index-high.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"},
        {"ply-list-too-long.ply", header + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n"},
        {"ply-truncated.ply", header + "0 0 0\n1 0"},
        {"ply-binary-index-high.ply",
         std::string("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n") +
             std::string(12, '\0') + std::string("\x03\x00\x00\x00\x00\x05\x00\x00\x00\x09\x00\x00\x00", 13)},
        {"obj-nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
    };
    for (const auto& [name, bytes] : meshes) {
        const std::string mesh = "viewpipe-hostile-" + name;
        std::ofstream(std::filesystem::temp_directory_path() / mesh, std::ios::binary) << bytes;
        const std::string scene = writeScene("viewpipe-hostile-" + name + ".json",
                                             R"({"view": {"projection": "perspective", "vrp": [0, 0, 0], "vpn": [0, 0, 1],
            "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50], "front": 60, "back": 25},
            "objects": [{"type": "mesh", "path": ")" + mesh + R"("}], "effects": ["clip", "cull"]})");
        const std::string out = " --out " + (std::filesystem::temp_directory_path() / "viewpipe-hostile-out").string();
        for (const auto& [command, options] : std::vector<std::pair<std::string, std::string>>{
                 {"check ", ""}, {"pipeline ", ""}, {"open ", ""}, {"export ", out}}) {
            const Result r = run(command + scene + options);
            EXPECT_EQ(r.exitCode, 2) << command << name << ": " << r.err;
            EXPECT_EQ(r.err.rfind(scene + ": objects[0].path: ", 0), 0u) << command << name << ": " << r.err;
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << name << ": " << r.err;
        }
    }
}

// A syntax error names its line and column, the form editors jump to; an overflowing number its field.
TEST(Cli, JsonErrorsNameTheirPlace)
{
    const std::string syntax = writeScene("viewpipe-syntax.json", "{\n \"view\": {\n  \"vrp\": [0, 0,\n  }\n}\n");
    Result r = run("check " + syntax);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind(syntax + ":4:3: ", 0), 0u) << r.err;
    const std::string overflow = writeScene("viewpipe-overflow.json", R"({"view": {"projection": "perspective",
        "vrp": [1e999, 0, 0], "vpn": [0, 0, 1], "vup": [0, 1, 0], "prp": [8, 6, 84], "window": [-50, 50, -50, 50],
        "front": 60, "back": 25}})");
    r = run("pipeline " + overflow);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, overflow + ": view.vrp[0]: not a finite number\n");
}

TEST(Cli, WidePrecisionsPrintAllTheirDigits)
{
    const Json q = Json::parse(run("pipeline " + kHouse + " --json --precision float128").out);
    EXPECT_EQ(q["precision"], "float128");
    ASSERT_TRUE(q["zmin"].is_string());
    // -24/59 = -0.40677966101694915254237288135593220338983050847457627118644...,
    // correct to binary128's 33 digits.
    EXPECT_EQ(q["zmin"].get<std::string>().substr(0, 35), "-4.06779661016949152542372881355932");
    const Json m = Json::parse(run("pipeline " + kHouse + " --json --precision mpfr --bits 512").out);
    EXPECT_EQ(m["precision"], "mpfr-512");
    EXPECT_GT(m["zmin"].get<std::string>().size(), 150u);
    EXPECT_EQ(m["zmin"].get<std::string>().substr(0, 62), "-4.06779661016949152542372881355932203389830508474576271186440");
    EXPECT_EQ(run("pipeline " + kHouse + " --precision mpfr --bits 2").exitCode, 2);
}

TEST(Cli, BenchJsonHasEveryTier)
{
    const Result r = run("bench " + kHouse + " --json --vertices 2000");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["reference"].get<std::string>().rfind("mpfr-256", 0), 0u);
    ASSERT_EQ(j["rows"].size(), 7u);
    const std::array<std::string, 7> tiers = {"float",    "double", "long-double", "double-double",
                                              "float128", "mpfr",   "exact"};
    for (std::size_t i = 0; i < 7; ++i) {
        const Json& row = j["rows"][i];
        EXPECT_EQ(row["precision"], tiers[i]);
        for (const char* key : {"bits", "build_ns", "vertex_ns", "max_rel_error", "corner_error",
                                "orthogonality_error", "roundtrip_error"})
            EXPECT_TRUE(row.contains(key)) << key;
        // Each tier within a few of its own epsilon on the corners.
        EXPECT_LE(row["corner_error"].get<double>(), 4 * row["epsilon"].get<double>()) << tiers[i];
    }
    // Wider is more accurate: double beats float, float128 beats double.
    EXPECT_LT(j["rows"][1]["max_rel_error"].get<double>(), j["rows"][0]["max_rel_error"].get<double>());
    EXPECT_LT(j["rows"][4]["max_rel_error"].get<double>(), 1e-30);
    EXPECT_EQ(j["volume"], "the view volume");
    // The exact end: no error, a cost measured beside the others'; the house's numbers are doubles exactly.
    EXPECT_EQ(j["rows"][6]["max_rel_error"].get<double>(), 0.0);
    EXPECT_GT(j["rows"][6]["vertex_ns"].get<double>(), j["rows"][1]["vertex_ns"].get<double>());
    EXPECT_NE(j["reference"].get<std::string>().find("with the exact composite of the scene as typed to"), std::string::npos);
}

// Found: the Vulkan preset with its far plane at infinity was refused
// ("camera.projection.far: is infinite") instead of measured.
TEST(Cli, BenchMeasuresAViewVolumeWithoutAFarFace)
{
    const std::string scene = std::string(viewpipe::build::dataDir) + "/scenes/apis/vulkan-reversed-infinite.json";
    const Result r = run("bench " + scene + " --json --vertices 2000");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["volume"], "the view volume up to far = 1000 × near (its far plane is infinite)");
    ASSERT_EQ(j["rows"].size(), 7u);
    for (const Json& row : j["rows"]) {
        if (row["precision"] == "exact")
            continue; // no error measured: it is the scene as typed
        EXPECT_LE(row["corner_error"].get<double>(), 8 * row["epsilon"].get<double>()) << row["precision"];
        EXPECT_GT(row["ndc_max_error"].get<double>(), 0.0) << row["precision"]; // the scene's vertices measured
    }
    const Result text = run("bench " + scene + " --vertices 2000");
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("Corners and round trip: the view volume up to far = 1000 × near"), std::string::npos);
}

} // namespace

namespace {

TEST(Cli, ClassifyNamesThePresets)
{
    const std::string dir = std::string(viewpipe::build::dataDir) + "/scenes/classical/";
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"house-front", "parallel, multiview orthographic, front"},
        {"house-top", "parallel, multiview orthographic, top"},
        {"house-side", "parallel, multiview orthographic, side"},
        {"cube-isometric", "parallel, axonometric, isometric"},
        {"cube-dimetric", "parallel, axonometric, dimetric"},
        {"cube-trimetric", "parallel, axonometric, trimetric"},
        {"cube-cavalier", "parallel, oblique, cavalier (alpha = 45.00 deg)"},
        {"house-cabinet", "parallel, oblique, cabinet (alpha = 63.43 deg)"},
        {"cube-oblique", "parallel, oblique, general (alpha = 53.13 deg)"},
        {"cube-one-point", "perspective, one-point"},
        {"cube-two-point", "perspective, two-point"},
        {"house-three-point", "perspective, three-point"}};
    for (const auto& [name, description] : expected) {
        const Result r = run("classify " + dir + name + ".json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out.substr(0, r.out.find('\n')), description) << name;
    }
    const Json j = Json::parse(run("classify " + dir + "cube-two-point.json --json").out);
    EXPECT_EQ(j["kind"], "two-point");
    EXPECT_EQ(j["vanishing_points"].size(), 2u);
    EXPECT_TRUE(j["foreshortening"].is_null());
    const Json iso = Json::parse(run("classify " + dir + "cube-isometric.json --json").out);
    EXPECT_NEAR(iso["foreshortening"][1].get<double>(), std::sqrt(2.0 / 3), 1e-12);
}

// The presets hold their roots as typed expressions: the isometric cube's view has VPN (1, 1, 1)/sqrt(3),
// front and back at +-6 sqrt(3) and a window of half-width 23 sqrt(6)/6, so `pipeline --precision exact`
// prints N_par in roots: S_par scales x and y by sqrt(6)/23 and z by 1/(12 sqrt(3)) = sqrt(3)/36, which
// takes R's rows (1, 0, -1)/sqrt(2), (-1, 2, -1)/sqrt(6) and (1, 1, 1)/sqrt(3) to these.
TEST(Cli, ClassicalPresetsAreExact)
{
    const std::string file = std::string(viewpipe::build::dataDir) + "/scenes/classical/cube-isometric.json";
    const Result r = run("pipeline " + file + " --precision exact --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_FALSE(j.contains("inexact"));
    EXPECT_EQ(j["exact"]["composite"], Json::parse(R"j([["sqrt(3)/23", "0", "-sqrt(3)/23", "0"],
        ["-1/23", "2/23", "-1/23", "0"], ["1/36", "1/36", "1/36", "-1/2"], ["0", "0", "0", "1"]])j"));
}

TEST(Cli, ClassicalPrintsAViewThatClassifiesBack)
{
    const std::string file = (std::filesystem::temp_directory_path() / "viewpipe-classical.json").string();
    Result r = run("classical trimetric --object cube --azimuth 20 --elevation 40 --out " + file);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(run("classify " + file).out.substr(0, 33), "parallel, axonometric, trimetric\n");
    r = run("classical dimetric --foreshortening 0.9,0.9,0.2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("foreshortening: the squares of the three ratios must sum to 2"), std::string::npos) << r.err;
    EXPECT_EQ(run("classical fisheye").exitCode, 2);
}

} // namespace

namespace {

TEST(Cli, EffectsInPipelineAndTrace)
{
    const std::string scene = std::string(viewpipe::build::dataDir) + "/scenes/clipping-eye-plane.json";
    const Json j = Json::parse(run("pipeline " + scene + " --json").out);
    ASSERT_TRUE(j.contains("effects"));
    EXPECT_EQ(j["stages"].back()["symbol"], "divide");
    const Json& clip = j["effects"]["clip"]["segments"];
    EXPECT_EQ(clip["inside"].get<int>() + clip["clipped"].get<int>() + clip["outside"].get<int>(), 27); // 15 + 12 edges
    EXPECT_GT(clip["clipped"].get<int>(), 0);
    EXPECT_EQ(j["effects"]["cull"]["faces"], 13);
    // Foley's house lists no effects: no "effects" key, five stages as before.
    const Json plain = Json::parse(run("pipeline " + kHouse + " --json").out);
    EXPECT_FALSE(plain.contains("effects"));
    EXPECT_EQ(plain["stages"].size(), 5u);
    // Trace reports the clipping of the point.
    const Json behind = Json::parse(run("trace " + scene + " --point 8 6 50 --json").out);
    EXPECT_TRUE(behind["clipping"]["clipped"].get<bool>());
    EXPECT_TRUE(behind["clipping"]["behind_eye"].get<bool>());
    const Json beside = Json::parse(run("trace " + scene + " --point 200 6 20 --json").out);
    EXPECT_FALSE(beside["clipping"]["behind_eye"].get<bool>());
    EXPECT_EQ(beside["clipping"]["outside_planes"], Json::parse(R"(["right"])"));
}

// A lesson packed travels: its folder, moved anywhere and away from the files the
// lesson named, checks; scenes and meshes come along once each under unique names,
// every path relative to the file that names it.
TEST(Cli, ALessonPacksIntoAFolderThatTravels)
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("viewpipe-pack-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "other");
    const std::string data = viewpipe::build::dataDir;
    // Another scene named house.json, and an inline scene with the mesh the letter F's scene uses too.
    std::ifstream house(kHouse);
    Json other = Json::parse(house);
    other["name"] = "Another house";
    std::ofstream(dir / "other" / "house.json") << other.dump(2);
    Json inlineScene = Json::parse(std::ifstream(data + "/scenes/letter-f.json"));
    inlineScene["objects"][0]["path"] = data + "/meshes/letter-f.obj";
    const Json lesson = {{"title", "Packed"},
                         {"steps", {{{"scene", kHouse}, {"caption", "one"}},
                                    {{"scene", (dir / "other" / "house.json").string()}, {"caption", "two"}},
                                    {{"scene", data + "/scenes/letter-f.json"}, {"caption", "three"}},
                                    {{"scene", inlineScene}, {"caption", "four"}},
                                    {{"scene", kHouse}, {"caption", "five"}}}}};
    std::ofstream(dir / "other" / "my-lesson.json") << lesson.dump(2);

    Result r = run("lesson pack " + (dir / "other" / "my-lesson.json").string() + " --out " + (dir / "pack").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("my-lesson.json"), std::string::npos);
    fs::rename(dir / "pack", dir / "moved"); // the folder travels; what the lesson named stays behind, then goes
    fs::remove_all(dir / "other");
    r = run("lesson check " + (dir / "moved" / "my-lesson.json").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;

    const Json packed = Json::parse(std::ifstream(dir / "moved" / "my-lesson.json"));
    EXPECT_EQ(packed["steps"][0]["scene"], "scenes/house.json");
    EXPECT_EQ(packed["steps"][1]["scene"], "scenes/house-2.json");
    EXPECT_EQ(packed["steps"][2]["scene"], "scenes/letter-f.json");
    EXPECT_EQ(packed["steps"][3]["scene"]["objects"][0]["path"], "meshes/letter-f.obj");
    EXPECT_EQ(packed["steps"][4]["scene"], "scenes/house.json");
    EXPECT_EQ(Json::parse(std::ifstream(dir / "moved" / "scenes" / "house-2.json"))["name"], "Another house");
    EXPECT_EQ(Json::parse(std::ifstream(dir / "moved" / "scenes" / "letter-f.json"))["objects"][0]["path"], "../meshes/letter-f.obj");
    EXPECT_EQ(fs::file_size(dir / "moved" / "meshes" / "letter-f.obj"), fs::file_size(data + "/meshes/letter-f.obj"));
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir / "moved"))
        files += entry.is_regular_file();
    EXPECT_EQ(files, 5); // the lesson, three scenes, one mesh

    // Packed again into its own folder: the same files, replaced.
    r = run("lesson pack " + (dir / "moved" / "my-lesson.json").string() + " --out " + (dir / "moved").string() + " --quiet");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(run("lesson check " + (dir / "moved" / "my-lesson.json").string()).exitCode, 0);
    // A folder that cannot be made is bad input, named.
    r = run("lesson pack " + std::string(viewpipe::build::dataDir) + "/lessons/foley-nper.json --out /proc/no-such-folder");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--out: cannot create the folder"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

} // namespace

namespace {

// Python's own arithmetic (math.sqrt) evaluates every exact entry to within 1e-9 of the double computed
// independently by the double pipeline, for every built-in scene: the strings are what docs/cli.md says.
TEST(Cli, ExactEntriesAreExpressionsPythonEvaluates)
{
    const std::string script = (std::filesystem::temp_directory_path() / "viewpipe-exact-check.py").string();
    std::ofstream(script) << R"py(
import json, sys
from math import sqrt
exact, double = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert exact["precision"] == "exact"
for stage, numbers in zip(exact["exact"]["stages"], double["stages"]):
    for row, values in zip(stage["matrix"], numbers["matrix"]):
        for text, value in zip(row, values):
            assert abs(eval(text) - value) <= 1e-9 * max(1, abs(value)), (stage["symbol"], text, value)
for row, values in zip(exact["exact"]["composite"], double["composite"]):
    for text, value in zip(row, values):
        assert abs(eval(text) - value) <= 1e-9 * max(1, abs(value)), ("composite", text, value)
print("checked")
)py";
    int scenes = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(viewpipe::build::dataDir) + "/scenes")) {
        if (entry.path().extension() != ".json")
            continue;
        const Result exact = run("pipeline " + entry.path().string() + " --precision exact --json");
        const Result plain = run("pipeline " + entry.path().string() + " --json");
        ASSERT_EQ(exact.exitCode, 0) << entry.path() << exact.err;
        const std::string exactFile = writeScene("viewpipe-exact.json", exact.out);
        const std::string plainFile = writeScene("viewpipe-double.json", plain.out);
        const std::string command = "python3 " + script + " " + exactFile + " " + plainFile + " 2>&1";
        FILE* pipe = ::popen(command.c_str(), "r");
        std::array<char, 4096> buffer;
        std::string out;
        std::size_t n;
        while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
            out.append(buffer.data(), n);
        EXPECT_EQ(::pclose(pipe), 0) << entry.path() << ": " << out;
        ++scenes;
    }
    EXPECT_GE(scenes, 20);
}

TEST(Cli, TraceSaysWhichFaceExactly)
{
    const std::string frustum = writeScene("viewpipe-frustum.json", R"({"camera": {"look_at": {"eye": [0, 0, 0],
        "center": [0, 0, -1], "up": [0, 1, 0]}, "projection": {"type": "frustum", "left": -2, "right": 2,
        "bottom": -1.5, "top": 1.5, "near": 2, "far": 10}}})");
    Result r = run("trace " + frustum + " --point 0 0 -2");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("on the near face of the canonical view volume (inside)"), std::string::npos) << r.out;
    r = run("trace " + frustum + " --point 2 3/2 -2 --precision exact");
    EXPECT_NE(r.out.find("after the divide: (1, 1, -1)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("on the corner of the right, top and near faces"), std::string::npos) << r.out;
    r = run("trace " + frustum + " --point 0.1 0 -2");
    EXPECT_NE(r.out.find("computed from the nearest double values, (0.10000000000000000555"), std::string::npos) << r.out;
    r = run("trace " + frustum + " --point 'sqrt(-1)' 0 -2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--point: must be three finite numbers or exact expressions (coordinate 1: the square root of -1"),
              std::string::npos) << r.err;
    r = run("pipeline " + kHouse + " --precision exact");
    EXPECT_NE(r.out.find("z_min = -24/59"), std::string::npos) << r.out;
}

// Behind the eye or not is w's sign, not its first term's: Foley's view D (VPN (1, 0, 1), PRP n = 20 sqrt 2)
// takes the house corner (16, 10, 30) to w = -64/5 + 48 sqrt(2)/5 > 0 after M, and (40, 0, 80) to
// w = 2 - 3 sqrt(2)/2 < 0: the first is in front of the eye, the second behind it.
TEST(Cli, ExactTraceReadsTheSignOfW)
{
    const std::string viewD = writeScene("viewpipe-view-d.json", R"json({"view": {"projection": "perspective",
        "vrp": [16, 0, 54], "vpn": [1, 0, 1], "vup": [0, 1, 0], "prp": [0, 25, "20*sqrt(2)"],
        "window": [-20, 20, -5, 35], "front": 10, "back": -30}})json");
    Result r = run("trace " + viewD + " --point 16 10 30 --precision exact");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("48*sqrt(2)/5 - 64/5)"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("behind the eye"), std::string::npos) << r.out;
    // Every precision: the wide ones write their numbers as decimal strings.
    for (const std::string precision : {"exact", "float", "double", "long-double", "float128", "mpfr"}) {
        r = run("trace " + viewD + " --point 40 0 80 --precision " + precision);
        EXPECT_EQ(r.exitCode, 0) << precision << ": " << r.err;
        EXPECT_NE(r.out.find("(w < 0: behind the eye, a false image)"), std::string::npos) << precision << ": " << r.out;
        r = run("trace " + viewD + " --point 16 10 30 --precision " + precision);
        EXPECT_EQ(r.out.find("behind the eye"), std::string::npos) << precision << ": " << r.out;
    }
}

} // namespace
