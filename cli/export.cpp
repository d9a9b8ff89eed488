// `viewpipe export`: every stage as images for slides, the matrices as LaTeX and JSON.

#include <atomic>
#include <csignal>
#include <cstdio>

#include "command.hpp"
#include "drawing_commands.hpp"
#include "export/Exporter.h"
#include "export/VirtualDisplay.h"

namespace viewpipe::commands {
namespace {

struct ExportCommandOptions {
    std::string scene, out, size = "1280x720", stages = "all", theme = "light", formats = "png";
    int scale = 1, textScale = 100, fps = 30, digits = 4;
    bool transparent = false, animate = false, quiet = false;
    std::string framing = "together", legend = "best", layout = "stages";
    std::vector<std::string> hide;
    double zoom = 1;
};

std::atomic<bool> interrupted{false};

extern "C" void onInterrupt(int)
{
    interrupted = true;
}

int runExport(const ExportCommandOptions& options)
{
    return guarded(options.scene, "viewpipe export", [&] {
        const std::shared_ptr<const EvaluatedScene> scene = evaluateScene(loadScene(options.scene));
        gui::ExportOptions o;
        o.out = options.out;
        std::tie(o.width, o.height) = parseSize(options.size, "--size");
        o.scale = options.scale;
        o.textScale = options.textScale;
        o.stages = gui::parseStages(options.stages, int(scene->pipeline.stages.size()));
        o.theme = options.theme == "dark" ? report::Theme::Dark : report::Theme::Light;
        o.transparent = options.transparent;
        o.formats = gui::parseFormats(options.formats);
        o.animate = options.animate;
        o.fps = options.fps;
        o.digits = options.digits;
        o.framing = *report::framingModeNamed(options.framing);
        o.legend = *report::legendPlaceNamed(options.legend);
        o.hidden.insert(options.hide.begin(), options.hide.end());
        o.zoom = options.zoom;
        o.storyboard = options.layout == "storyboard";
        o.presets = scenesDirectory();
        o.notice = [bar = !options.quiet](const std::string& what) {
            std::cerr << (bar ? "\n" : "") << "viewpipe export: " << what << "\n"; // the newline ends the bar's line
        };

        std::signal(SIGINT, onInterrupt);
        std::signal(SIGTERM, onInterrupt);
        const gui::VirtualDisplay display;
        const bool bar = !options.quiet;
        // A message after the bar starts on a line of its own; one before it, on the first line.
        bool barLineOpen = false;
        const auto endBarLine = [&barLineOpen] {
            if (barLineOpen)
                std::fputc('\n', stderr);
            barLineOpen = false;
        };
        std::vector<std::filesystem::path> files;
        try {
            files = gui::exportStages(
                scene, o,
                [bar, &barLineOpen](int done, int total, const std::string& what) {
                    if (!bar)
                        return;
                    barLineOpen = true;
                    const int width = 30, filled = width * done / total;
                    std::fprintf(stderr, "\r[%s%s] %3d%%  %-50.50s", std::string(std::size_t(filled), '#').c_str(),
                                 std::string(std::size_t(width - filled), ' ').c_str(), 100 * done / total,
                                 what.c_str());
                    std::fflush(stderr);
                },
                interrupted);
        } catch (...) {
            endBarLine();
            throw;
        }
        endBarLine();
        if (interrupted) {
            std::cerr << "viewpipe export: interrupted; nothing was written\n";
            return 130;
        }
        if (!options.quiet)
            for (const auto& file : files)
                std::cout << file.string() << "\n";
        return 0;
    });
}

} // namespace

void addExportCommand(CLI::App& app)
{
    auto options = std::make_shared<ExportCommandOptions>();
    CLI::App* command =
        app.add_subcommand("export", "Export every stage as images for slides, the matrices as LaTeX and JSON");
    command->add_option("SCENE", options->scene, "Scene file (JSON)")->required();
    command->add_option("--out", options->out, "Folder for the files (created if missing)")->required();
    command->add_option("--size", options->size, "Picture size WxH")->capture_default_str();
    command->add_option("--scale", options->scale, "Pixels per unit of size, 1 to 4 (2 for high-DPI)")
        ->capture_default_str();
    command->add_option("--text-scale", options->textScale,
                        "Text size in percent, " + std::to_string(report::kMinTextScale) + " to " + std::to_string(report::kMaxTextScale) +
                            " (labels at least 2.4 % of the width at 100)")
        ->capture_default_str();
    command->add_option("--stages", options->stages, "all, or a list such as 0,2,4-5")->capture_default_str();
    command->add_option("--theme", options->theme, "light or dark")
        ->check(CLI::IsMember({"light", "dark"}))
        ->capture_default_str();
    command->add_flag("--transparent", options->transparent, "Transparent background (PNG)");
    std::string formats = "Comma-separated:";
    for (const gui::ExportFormat& format : gui::exportFormats())
        formats += "\n  " + format.name + ": " + format.description;
    command->add_option("--format", options->formats, formats)->capture_default_str();
    command->add_flag("--animate", options->animate, "Also the animated transition, animation.mp4");
    command->add_option("--fps", options->fps, "Frames per second of the animation")->capture_default_str();
    command->add_option("--digits", options->digits, "Significant digits of inexact entries in matrices.tex")
        ->capture_default_str();
    command->add_flag("--quiet", options->quiet, "No progress bar, no list of files");
    command->add_option("--framing", options->framing,
                        "together: the stages that keep sizes share a framing, so that their motion shows;\n"
                        "per-stage: each picture framed on its own stage, as large as it goes;\n"
                        "fixed: one framing for all, to compare sizes")
        ->check(CLI::IsMember({"together", "per-stage", "fixed"}))
        ->capture_default_str();
    std::string hidden;
    for (const std::string& name : hideNames())
        hidden += (hidden.empty() ? "" : ", ") + name;
    command->add_option("--hide", options->hide, "What the pictures leave out, comma-separated: " + hidden)
        ->delimiter(',');
    command->add_option("--legend", options->legend,
                        "Where the legend goes: best (where it costs the subject least), beside, below, inside (in a "
                        "corner the subject leaves free), none")
        ->check(CLI::IsMember({"best", "beside", "below", "inside", "none"}))
        ->capture_default_str();
    command->add_option("--zoom", options->zoom, "The subject this many times larger than framed, 0.1 to 10")
        ->capture_default_str();
    command->add_option("--layout", options->layout,
                        "stages: a file of each stage per format;\n"
                        "storyboard: every stage at once, one file per format (storyboard.png, .svg, .pdf, "
                        "storyboard-tikz.tex)")
        ->check(CLI::IsMember({"stages", "storyboard"}))
        ->capture_default_str();
    setRun(command, [options] { return runExport(*options); });
}

} // namespace viewpipe::commands
