#pragma once

// Runs a program and reads what it prints. posix_spawn, not fork: a test
// process under AddressSanitizer maps gigabytes, and after each fork every page
// it writes is copied (QProcess forked pdftotext a picture at a time: most of a
// test's time went to those copies).

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <optional>
#include <string>
#include <vector>

extern char** environ;

// The program's standard output, or nothing when it cannot start or exits other than 0.
inline std::optional<std::string> programOutput(const std::vector<std::string>& args)
{
    int pipeEnds[2];
    if (::pipe2(pipeEnds, O_CLOEXEC) != 0)
        return std::nullopt;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], 1);
    std::vector<char*> argv;
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int started = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipeEnds[1]);
    std::string out;
    char buffer[65536];
    for (ssize_t n; started == 0 && (n = ::read(pipeEnds[0], buffer, sizeof buffer)) != 0;)
        if (n > 0)
            out.append(buffer, std::size_t(n));
    ::close(pipeEnds[0]);
    int status = 0;
    if (started != 0 || ::waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return std::nullopt;
    return out;
}
