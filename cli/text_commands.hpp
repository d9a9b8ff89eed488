#pragma once

// The subcommands that print (no VTK, no Qt): each adds itself to the app with
// its options and its run.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

#include "viewpipe/precision_ladder.hpp"

namespace viewpipe::commands {

void addPipelineCommand(CLI::App& app);
void addTraceCommand(CLI::App& app);
void addCheckCommand(CLI::App& app);
void addClassifyCommand(CLI::App& app);
void addClassicalCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);
void addCodeCommand(CLI::App& app);

// `bench --plot FILE` draws through `writePlot`, given by the drawing commands.
using BenchPlotWriter = std::function<void(const BenchResult& result, const std::string& file)>;
void addBenchCommand(CLI::App& app, BenchPlotWriter writePlot);

} // namespace viewpipe::commands
