// viewpipe: the one executable. Each subcommand is a file of cli/;
// those that print need neither VTK nor Qt, those that draw do. Bad input
// exits 2 with one line "FILE: field.path: reason", internal errors exit 1.

#include <CLI/CLI.hpp>

#include <string>

#include "command.hpp"
#include "drawing_commands.hpp"
#include "text_commands.hpp"
#include "viewpipe/version.hpp"

int main(int argc, char** argv)
{
    using namespace viewpipe::commands;
    CLI::App app{"ViewPipe: step through the 3D viewing pipeline (Foley's normalizing transformation and "
                 "the OpenGL forms)."};
    app.set_version_flag("--version", std::string("viewpipe ") + viewpipe::kVersion);
    app.require_subcommand(1);
    addPipelineCommand(app);
    addTraceCommand(app);
    addCheckCommand(app);
    addOpenCommand(app, argc, argv);
    addExportCommand(app);
    addClassifyCommand(app);
    addClassicalCommand(app);
    addConvertCommand(app);
    addCodeCommand(app);
    addSheetCommand(app);
    addLessonCommand(app);
    addBenchCommand(app, writeBenchPlot);
    return runCommandLine(app, argc, argv);
}
