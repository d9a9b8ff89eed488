#pragma once

// Child processes (Xvfb, ffmpeg): started from PATH without a shell, through
// one posix_spawn call.

#include <sys/types.h>

#include <string>
#include <vector>

namespace viewpipe::gui {

struct ChildStreams {
    bool stdinFromNull = false;  // reads /dev/null
    bool stdoutToNull = false;   // writes to /dev/null
    bool stderrToNull = false;   // writes to /dev/null
    int closeInChild = -1;       // a descriptor the child must not inherit, or -1
    std::string workingDirectory; // where the child starts; empty: here
};

// Starts arguments[0], looked up in PATH; returns its pid, or -1 if it could not be started.
pid_t startProgram(const std::vector<std::string>& arguments, const ChildStreams& streams);

// Waits for a child to end; returns its exit status, or 128 + the signal that ended it.
int waitForProgram(pid_t child);

// Runs a program to its end (stdin always from /dev/null); returns its exit
// status, or -1 if it could not be started.
int runProgram(const std::vector<std::string>& arguments, const ChildStreams& streams = {});

} // namespace viewpipe::gui
