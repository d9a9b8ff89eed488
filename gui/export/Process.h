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
    std::vector<std::string> environment; // "NAME=value" set for the child over the parent's
};

// runProgram's status for a program stopped at its deadline.
constexpr int kTimedOut = -2;

// Starts arguments[0], looked up in PATH; returns its pid, or -1 if it could not be started.
pid_t startProgram(const std::vector<std::string>& arguments, const ChildStreams& streams);

// Waits for a child to end; returns its exit status, or 128 + the signal that ended it.
int waitForProgram(pid_t child);

// Runs a program to its end (stdin always from /dev/null), or kills it after
// `timeoutSeconds` (0: no deadline); returns its exit status, -1 if it could
// not be started, kTimedOut if it was killed.
int runProgram(const std::vector<std::string>& arguments, const ChildStreams& streams = {}, int timeoutSeconds = 0);

} // namespace viewpipe::gui
