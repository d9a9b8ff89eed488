#pragma once

// What every subcommand shares: the exit codes, the guard that turns errors
// into them, and the options several subcommands take.

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <utility>

#include "viewpipe/error.hpp"

namespace viewpipe::commands {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

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

// Makes `run` the subcommand's callback; a nonzero exit code leaves the parse
// as a CLI::RuntimeError carrying it (see runCommandLine).
void setRun(CLI::App* command, std::function<int()> run);

// Parses the command line and runs the chosen subcommand; returns the exit code.
int runCommandLine(CLI::App& app, int argc, char** argv);

// "WxH" -> (W, H); throws InputError naming the option.
std::pair<int, int> parseSize(const std::string& text, const std::string& option);

struct PrecisionOptions {
    std::string precision = "double";
    unsigned bits = 256;
};

void addPrecision(CLI::App* command, PrecisionOptions& options);

// The built-in scenes: $VIEWPIPE_DATA/scenes if set, else the source tree's
// data/scenes (as the app's, gui/app/AppPaths.h, without Qt).
std::string scenesDirectory();
// The scene `open` and `bench` take when none is given: one where every stage moves.
std::string defaultScene();

} // namespace viewpipe::commands
