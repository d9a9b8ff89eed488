// `viewpipe open`: the app on a scene, or a screenshot of it.

#include "command.hpp"
#include "drawing_commands.hpp"
#include "app/OpenCommand.h"
#include "viewpipe/report/style.hpp"

namespace viewpipe::commands {
namespace {

struct OpenCommandOptions {
    gui::OpenOptions open;
    std::string size, theme;
    int textScale = -1; // not given
};

int runOpen(int argc, char** argv, OpenCommandOptions& options)
{
    gui::OpenOptions& open = options.open;
    return guarded(open.scene.empty() ? std::string("viewpipe open") : open.scene, "viewpipe: internal error", [&] {
        if (open.scene.empty())
            open.scene = defaultScene();
        if (!options.size.empty()) {
            std::tie(open.width, open.height) = parseSize(options.size, "--size");
            if (open.width < 200 || open.height < 150 || open.width > 8192 || open.height > 8192)
                throw InputError("--size", "must be WxH with 200 <= W <= 8192 and 150 <= H <= 8192");
        }
        if (options.textScale != -1) {
            report::checkTextScale(options.textScale, "--text-scale");
            open.textScale = options.textScale;
        }
        if (!options.theme.empty())
            open.theme = options.theme;
        return gui::runOpen(argc, argv, open);
    });
}

} // namespace

void addOpenCommand(CLI::App& app, int argc, char** argv)
{
    auto options = std::make_shared<OpenCommandOptions>();
    gui::OpenOptions& open = options->open;
    CLI::App* command = app.add_subcommand("open", "Open the app on a scene (default: the house from its front-right corner, where every stage moves)");
    command->add_option("SCENE", open.scene, "Scene file (JSON)");
    command->add_option("--stage", open.stage, "Stage to show: 0 is the world, K after the K-th matrix");
    command->add_option("--screenshot", open.screenshot, "Save a PNG of the whole window and exit");
    command->add_option("--size", options->size,
                        "Window size WxH (default: 1600x950 for a screenshot, else fitted to the screen)");
    command->add_option("--text-scale", options->textScale,
                        "Text size in percent of the default, as View > Larger Text sets it (" + std::to_string(report::kMinTextScale) +
                            " to " + std::to_string(report::kMaxTextScale) + ")");
    command->add_option("--theme", options->theme, "dark or light")->check(CLI::IsMember({"dark", "light"}));
    command->add_option("--panel", open.panel, "Dock in front: stages, matrices, parameters, code (below the parameters), accuracy (measured) or depth")
        ->check(CLI::IsMember({"stages", "matrices", "parameters", "code", "accuracy", "depth"}));
    command->add_option("--lesson", open.lesson, "A lesson to open (JSON, docs/lesson-format.md), in the Lesson panel");
    command->add_option("--step", open.step, "The lesson's step to show, from 1")->needs("--lesson");
    command->add_flag("--reveal", open.reveal, "Show the step's answer, as Show Answer does")->needs("--lesson");
    command->add_flag("--present", open.present, "Full screen, as View > Present (F5)");
    command->add_option("--layout", open.layout,
                        "stages: the world view beside what the camera sees;\n"
                        "storyboard: every stage at once, as View > Storyboard (S)")
        ->check(CLI::IsMember({"stages", "storyboard"}))
        ->capture_default_str();
    setRun(command, [options, argc, argv] { return runOpen(argc, argv, *options); });
}

} // namespace viewpipe::commands
