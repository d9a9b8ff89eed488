// viewpipe: the one executable. Subcommands share the core library; bad input
// exits 2 with one line "FILE: field.path: reason", internal errors exit 1.

#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "app/AppPaths.h"
#include "app/OpenCommand.h"
#include "cli/report.hpp"
#include "export/AccuracyPlot.h"
#include "export/Exporter.h"
#include "cli/bench.hpp"
#include "viewpipe/classical.hpp"
#include "export/VirtualDisplay.h"
#include "painter/ScenePainter.h"
#include "viewpipe/version.hpp"

namespace {

using namespace viewpipe;

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

struct Options {
    std::string scene;
    bool json = false;
    std::string precision = "double";
    std::vector<double> point;
    unsigned bits = 256;
};

// Runs a subcommand: bad input (InputError) exits 2 with "PREFIX: field: reason",
// any other failure 1 with "PREFIX: what".
template <class Body> int guarded(const std::string& inputPrefix, const std::string& internalPrefix, Body&& body)
{
    try {
        return body();
    } catch (const InputError& e) {
        std::cerr << e.describe(inputPrefix) << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << internalPrefix << ": " << e.what() << "\n";
        return kExitInternal;
    }
}

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int)
{
    interrupted = true;
}

// "WxH" -> (W, H); throws InputError naming the option.
std::pair<int, int> parseSize(const std::string& text, const std::string& option)
{
    int width = 0, height = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> width >> x >> height) || x != 'x' || !in.eof())
        throw InputError(option, "must be WxH, e.g. 1280x720 (got \"" + text + "\")");
    return {width, height};
}

void addPrecision(CLI::App* command, Options& options)
{
    command->add_option("--precision", options.precision, "float, double, long-double, float128 or mpfr")
        ->check(CLI::IsMember({"float", "double", "long-double", "float128", "mpfr"}))
        ->capture_default_str();
    command->add_option("--bits", options.bits, "Significand bits for --precision mpfr")->capture_default_str();
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"ViewPipe: step through the 3D viewing pipeline (Foley's normalizing transformation and "
                 "the OpenGL forms)."};
    app.set_version_flag("--version", std::string("viewpipe ") + kVersion);
    app.require_subcommand(1);

    Options options;
    CLI::App* pipeline = app.add_subcommand("pipeline", "Print every stage's matrix and the running product");
    pipeline->add_option("SCENE", options.scene, "Scene file (JSON)")->required();
    pipeline->add_flag("--json", options.json, "One JSON object on stdout");
    addPrecision(pipeline, options);

    CLI::App* trace = app.add_subcommand("trace", "Follow one point through every stage and the divide");
    trace->add_option("SCENE", options.scene, "Scene file (JSON)")->required();
    trace->add_option("--point", options.point, "World coordinates X Y Z")->expected(3)->required();
    trace->add_flag("--json", options.json, "One JSON object on stdout");
    addPrecision(trace, options);

    CLI::App* check = app.add_subcommand("check", "Validate a scene file; print nothing and exit 0 if it is valid");
    check->add_option("SCENE", options.scene, "Scene file (JSON)")->required();

    gui::OpenOptions open;
    std::string size;
    std::string theme;
    CLI::App* openCommand = app.add_subcommand("open", "Open the app on a scene (default: the built-in house)");
    openCommand->add_option("SCENE", open.scene, "Scene file (JSON)");
    openCommand->add_option("--stage", open.stage, "Stage to show: 0 is the world, K after the K-th matrix");
    openCommand->add_option("--screenshot", open.screenshot, "Save a PNG of the whole window and exit");
    openCommand->add_option("--size", size, "Window size WxH (default: 1600x950 for a screenshot, else fitted to the screen)");
    openCommand->add_option("--theme", theme, "dark or light")->check(CLI::IsMember({"dark", "light"}));
    openCommand->add_option("--panel", open.panel, "Dock in front: stages, matrices, parameters, accuracy (measured) or depth")
        ->check(CLI::IsMember({"stages", "matrices", "parameters", "accuracy", "depth"}));

    std::string exportOut, exportSize = "1280x720", exportStages = "all", exportTheme = "light",
                                  exportFormats = "png";
    int exportScale = 1, exportFps = 30, exportDigits = 4;
    bool exportTransparent = false, exportAnimate = false, exportQuiet = false;
    std::string exportFraming = "per-stage";
    CLI::App* exportCommand =
        app.add_subcommand("export", "Export every stage as images for slides, the matrices as LaTeX and JSON");
    exportCommand->add_option("SCENE", options.scene, "Scene file (JSON)")->required();
    exportCommand->add_option("--out", exportOut, "Folder for the files (created if missing)")->required();
    exportCommand->add_option("--size", exportSize, "Picture size WxH")->capture_default_str();
    exportCommand->add_option("--scale", exportScale, "Pixels per unit of size, 1 to 4 (2 for high-DPI)")
        ->capture_default_str();
    exportCommand->add_option("--stages", exportStages, "all, or a list such as 0,2,4-5")->capture_default_str();
    exportCommand->add_option("--theme", exportTheme, "light or dark")
        ->check(CLI::IsMember({"light", "dark"}))
        ->capture_default_str();
    exportCommand->add_flag("--transparent", exportTransparent, "Transparent background (PNG)");
    exportCommand->add_option("--format", exportFormats, "png, svg, pdf, comma-separated")->capture_default_str();
    exportCommand->add_flag("--animate", exportAnimate, "Also the animated transition, animation.mp4");
    exportCommand->add_option("--fps", exportFps, "Frames per second of the animation")->capture_default_str();
    exportCommand->add_option("--digits", exportDigits, "Significant digits of inexact entries in matrices.tex")
        ->capture_default_str();
    exportCommand->add_flag("--quiet", exportQuiet, "No progress bar, no list of files");
    exportCommand->add_option("--framing", exportFraming,
                              "per-stage: each picture framed on its stage; fixed: one framing for all")
        ->check(CLI::IsMember({"fixed", "per-stage"}))
        ->capture_default_str();

    CLI::App* classifyCommand =
        app.add_subcommand("classify", "Name the classical projection a scene's view realizes");
    classifyCommand->add_option("SCENE", options.scene, "Scene file (JSON)")->required();
    classifyCommand->add_flag("--json", options.json, "One JSON object on stdout");

    std::string classicalKind, classicalObject = "house", classicalOut, classicalRatios;
    ClassicalParameters classicalParameters;
    double azimuth = 0, elevation = 0;
    CLI::App* classicalCommand = app.add_subcommand(
        "classical", "Print a scene that realizes a classical projection (front, top, side, isometric, dimetric, "
                     "trimetric, cavalier, cabinet, oblique, one-point, two-point, three-point)");
    classicalCommand->add_option("KIND", classicalKind, "The projection")->required();
    classicalCommand->add_option("--object", classicalObject, "house or cube")
        ->check(CLI::IsMember({"house", "cube"}))
        ->capture_default_str();
    CLI::Option* azimuthOption = classicalCommand->add_option("--azimuth", azimuth, "Axonometric: degrees about y");
    CLI::Option* elevationOption = classicalCommand->add_option("--elevation", elevation, "Axonometric: degrees about x");
    classicalCommand->add_option("--foreshortening", classicalRatios, "Axonometric: ratios fx,fy,fz (squares sum to 2)");
    classicalCommand->add_option("--receding", classicalParameters.receding, "Oblique: receding-axis factor")
        ->capture_default_str();
    classicalCommand->add_option("--angle", classicalParameters.angleDegrees, "Oblique: receding axis angle, degrees")
        ->capture_default_str();
    classicalCommand->add_option("--out", classicalOut, "Write the scene here (atomically) instead of stdout");

    std::string sheetOut, sheetSize = "1600x1200", sheetTheme = "light";
    CLI::App* sheetCommand = app.add_subcommand(
        "sheet", "The CAD layout of a scene's objects: top, front, side and isometric views on one PNG");
    sheetCommand->add_option("SCENE", options.scene, "Scene file (JSON)")->required();
    sheetCommand->add_option("--out", sheetOut, "The PNG to write")->required();
    sheetCommand->add_option("--size", sheetSize, "Sheet size WxH")->capture_default_str();
    sheetCommand->add_option("--theme", sheetTheme, "light or dark")
        ->check(CLI::IsMember({"light", "dark"}))
        ->capture_default_str();

    std::size_t benchVertices = 1000000;
    unsigned benchBits = 160;
    std::string benchPlot, benchViewport;
    CLI::App* benchCommand = app.add_subcommand(
        "bench", "What each precision costs in time and buys in accuracy (default scene: the house)");
    benchCommand->add_option("SCENE", options.scene, "Scene file (JSON)");
    benchCommand->add_flag("--json", options.json, "One JSON object on stdout");
    benchCommand->add_option("--plot", benchPlot, "Draw error against time (log-log) to this PNG");
    benchCommand->add_option("--vertices", benchVertices, "Vertices timed per run")->capture_default_str();
    benchCommand->add_option("--bits", benchBits, "Significand bits of the mpfr tier")->capture_default_str();
    benchCommand->add_option("--viewport", benchViewport, "Viewport WxH for pixel errors (default 1920x1080)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }

    if (*openCommand)
        return guarded(open.scene.empty() ? std::string("viewpipe open") : open.scene, "viewpipe: internal error", [&] {
            if (!size.empty()) {
                std::tie(open.width, open.height) = parseSize(size, "--size");
                if (open.width < 200 || open.height < 150 || open.width > 8192 || open.height > 8192)
                    throw InputError("--size", "must be WxH with 200 <= W <= 8192 and 150 <= H <= 8192");
            }
            if (!theme.empty())
                open.theme = theme;
            return gui::runOpen(argc, argv, open);
        });

    if (*sheetCommand)
        return guarded(options.scene, "viewpipe sheet", [&] {
            const Scene scene = loadScene(options.scene);
            const auto [width, height] = parseSize(sheetSize, "--size");
            const gui::VirtualDisplay display;
            gui::exportSheet(*evaluateScene(scene), sheetOut, width, height, sheetTheme == "dark" ? gui::Theme::Dark : gui::Theme::Light);
            return 0;
        });

    if (*classicalCommand)
        return guarded("viewpipe classical", "viewpipe classical", [&] {
            const auto kind = classicalKindNamed(classicalKind);
            if (!kind)
                throw InputError("KIND", "unknown classical projection \"" + classicalKind + "\"");
            if (*azimuthOption)
                classicalParameters.azimuthDegrees = azimuth;
            if (*elevationOption)
                classicalParameters.elevationDegrees = elevation;
            if (!classicalRatios.empty()) {
                std::array<double, 3> f{};
                char comma1 = 0, comma2 = 0;
                std::istringstream in(classicalRatios);
                if (!(in >> f[0] >> comma1 >> f[1] >> comma2 >> f[2]) || comma1 != ',' || comma2 != ',')
                    throw InputError("--foreshortening", "must be three numbers fx,fy,fz");
                classicalParameters.foreshortening = f;
            }
            Scene scene;
            scene.name = classicalObject + ", " + classicalName(*kind);
            SceneObject object;
            if (classicalObject == "cube") {
                object.type = ObjectType::Box;
                object.min = Vec3<double>(-5, -5, -5);
                object.max = Vec3<double>(5, 5, 5);
            }
            scene.objects.push_back(object);
            const Eigen::AlignedBox<double, 3> box = boundsOf(objectMeshes(scene));
            scene.camera = classicalView(*kind, box.min(), box.max(), classicalParameters);
            if (classicalOut.empty())
                std::cout << sceneToJson(scene);
            else
                saveScene(scene, classicalOut);
            return 0;
        });

    if (*benchCommand)
        return guarded(options.scene.empty() ? std::string("viewpipe bench") : options.scene, "viewpipe bench", [&] {
            const std::string file =
                options.scene.empty() ? (gui::scenesDirectory() + "/house.json").toStdString() : options.scene;
            const Scene scene = loadScene(file);
            cli::BenchOptions o;
            o.vertices = benchVertices;
            o.mpfrBits = benchBits;
            if (!benchViewport.empty())
                std::tie(o.viewport.width, o.viewport.height) = parseSize(benchViewport, "--viewport");
            const cli::BenchResult result = cli::runBench(
                scene, evaluateScene(scene)->objectVertices(), o, [&](int done, int total, const std::string& tier) {
                    if (!options.json && !tier.empty())
                        std::cerr << "[" << done + 1 << "/" << total << "] timing and measuring " << tier << "\n";
                    return true;
                });
            if (options.json)
                std::cout << cli::benchJson(result).dump() << "\n";
            else
                cli::printBench(std::cout, result);
            if (!benchPlot.empty()) {
                const gui::VirtualDisplay display;
                gui::writeAccuracyPlot(result, benchPlot, gui::Theme::Light);
                if (!options.json)
                    std::cout << "\nPlot: " << benchPlot << "\n";
            }
            return 0;
        });

    if (*exportCommand) // the leading newline ends the progress bar's line
        return guarded("\n" + options.scene, "\nviewpipe export", [&] {
            const std::shared_ptr<const EvaluatedScene> scene = evaluateScene(loadScene(options.scene));
            gui::ExportOptions o;
            o.out = exportOut;
            std::tie(o.width, o.height) = parseSize(exportSize, "--size");
            o.scale = exportScale;
            o.stages = gui::parseStages(exportStages, int(scene->pipeline.stages.size()));
            o.theme = exportTheme == "dark" ? gui::Theme::Dark : gui::Theme::Light;
            o.transparent = exportTransparent;
            std::istringstream formats(exportFormats);
            o.formats.clear();
            for (std::string f; std::getline(formats, f, ',');)
                o.formats.insert(f);
            o.animate = exportAnimate;
            o.fps = exportFps;
            o.digits = exportDigits;
            o.fixedFraming = exportFraming == "fixed";

            std::signal(SIGINT, onInterrupt);
            std::signal(SIGTERM, onInterrupt);
            const gui::VirtualDisplay display;
            const bool bar = !exportQuiet;
            const auto files = gui::exportStages(
                scene, o,
                [bar](int done, int total, const std::string& what) {
                    if (!bar)
                        return;
                    const int width = 30, filled = width * done / total;
                    std::fprintf(stderr, "\r[%s%s] %3d%%  %-50.50s", std::string(std::size_t(filled), '#').c_str(),
                                 std::string(std::size_t(width - filled), ' ').c_str(), 100 * done / total,
                                 what.c_str());
                    std::fflush(stderr);
                },
                interrupted);
            if (bar)
                std::fprintf(stderr, "\n");
            if (interrupted) {
                std::cerr << "viewpipe export: interrupted; nothing was written\n";
                return 130;
            }
            if (!exportQuiet)
                for (const auto& file : files)
                    std::cout << file.string() << "\n";
            return 0;
        });

    return guarded(options.scene, "viewpipe: internal error", [&] {
        const Scene scene = loadScene(options.scene);
        const std::shared_ptr<const EvaluatedScene> evaluated = evaluateScene(scene); // reads the meshes
        const cli::PrecisionChoice precision = cli::parsePrecision(options.precision, options.bits);
        if (*pipeline) {
            const EffectOutcomes& outcomes = evaluated->outcomes;
            if (options.json)
                std::cout << cli::pipelineJson(scene, precision, outcomes).dump() << "\n";
            else
                cli::printPipeline(std::cout, scene, precision, outcomes);
        } else if (*classifyCommand) {
            if (options.json)
                std::cout << cli::classifyJson(scene).dump() << "\n";
            else
                cli::printClassification(std::cout, scene);
        } else if (*trace) {
            const Vec3<double> point(options.point[0], options.point[1], options.point[2]);
            if (options.json)
                std::cout << cli::traceJson(scene, point, precision).dump() << "\n";
            else
                cli::printTrace(std::cout, scene, point, precision);
        }
        return 0;
    });
}
