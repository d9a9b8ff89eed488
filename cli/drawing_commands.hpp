#pragma once

// The subcommands that draw (VTK, and Qt for the app): each adds itself to the
// app with its options and its run.

#include <CLI/CLI.hpp>

#include <string>

#include "viewpipe/precision_ladder.hpp"

namespace viewpipe::commands {

// The app's QApplication takes the command line.
void addOpenCommand(CLI::App& app, int argc, char** argv);
void addExportCommand(CLI::App& app);
void addSheetCommand(CLI::App& app);
void addLessonCommand(CLI::App& app);

// `bench --plot`: the error-against-time chart as a PNG, on a virtual display if there is none.
void writeBenchPlot(const BenchResult& result, const std::string& file);

} // namespace viewpipe::commands
