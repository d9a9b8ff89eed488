// viewpipe: the one executable. Subcommands share the core library; bad input
// exits 2 with one line "FILE: field.path: reason", internal errors exit 1.

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

#include "app/OpenCommand.h"
#include "cli/report.hpp"
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
};

void addPrecision(CLI::App* command, Options& options)
{
    command->add_option("--precision", options.precision, "float, double or long-double")
        ->check(CLI::IsMember({"float", "double", "long-double"}))
        ->capture_default_str();
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
    openCommand->add_option("--size", size, "Window size WxH (default 1600x950)");
    openCommand->add_option("--theme", theme, "dark or light")->check(CLI::IsMember({"dark", "light"}));

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }

    if (*openCommand) {
        try {
            if (!size.empty()) {
                char x = 0;
                std::istringstream in(size);
                if (!(in >> open.width >> x >> open.height) || x != 'x' || !in.eof() || open.width < 200 ||
                    open.height < 150 || open.width > 8192 || open.height > 8192)
                    throw InputError("--size", "must be WxH with 200 <= W, H <= 8192, e.g. 1600x950 (got \"" + size +
                                                   "\")");
            }
            if (!theme.empty())
                open.theme = theme;
            return gui::runOpen(argc, argv, open);
        } catch (const InputError& e) {
            std::cerr << (open.scene.empty() ? std::string("viewpipe open") : open.scene) << ": " << e.what() << "\n";
            return kExitBadInput;
        } catch (const std::exception& e) {
            std::cerr << "viewpipe: internal error: " << e.what() << "\n";
            return kExitInternal;
        }
    }

    try {
        const Scene scene = loadScene(options.scene);
        if (*check)
            gui::checkMeshes(scene);
        const cli::Precision precision = cli::parsePrecision(options.precision);
        if (*pipeline) {
            if (options.json)
                std::cout << cli::pipelineJson(scene, precision).dump() << "\n";
            else
                cli::printPipeline(std::cout, scene, precision);
        } else if (*trace) {
            const Vec3<double> point(options.point[0], options.point[1], options.point[2]);
            if (options.json)
                std::cout << cli::traceJson(scene, point, precision).dump() << "\n";
            else
                cli::printTrace(std::cout, scene, point, precision);
        }
        return 0;
    } catch (const InputError& e) {
        std::cerr << options.scene << ": " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "viewpipe: internal error: " << e.what() << "\n";
        return kExitInternal;
    }
}
