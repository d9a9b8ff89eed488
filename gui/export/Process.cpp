#include "Process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace viewpipe::gui {

pid_t startProgram(const std::vector<std::string>& arguments, const ChildStreams& streams)
{
    std::vector<char*> argv;
    for (const std::string& a : arguments)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (streams.closeInChild >= 0)
        posix_spawn_file_actions_addclose(&actions, streams.closeInChild);
    if (streams.stdinFromNull)
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    if (streams.stdoutToNull)
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    if (streams.stderrToNull)
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    if (!streams.workingDirectory.empty())
        posix_spawn_file_actions_addchdir_np(&actions, streams.workingDirectory.c_str());
    // The parent's environment with the child's own settings over it.
    std::vector<std::string> settings;
    for (char** e = environ; *e; ++e) {
        const std::string setting = *e;
        const std::string name = setting.substr(0, setting.find('=') + 1);
        if (std::none_of(streams.environment.begin(), streams.environment.end(),
                         [&](const std::string& own) { return own.rfind(name, 0) == 0; }))
            settings.push_back(setting);
    }
    settings.insert(settings.end(), streams.environment.begin(), streams.environment.end());
    std::vector<char*> envp;
    for (std::string& setting : settings)
        envp.push_back(setting.data());
    envp.push_back(nullptr);
    pid_t child = -1;
    const int spawned = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    return spawned == 0 ? child : -1;
}

int waitForProgram(pid_t child)
{
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int runProgram(const std::vector<std::string>& arguments, const ChildStreams& given, int timeoutSeconds)
{
    ChildStreams streams = given;
    streams.stdinFromNull = true;
    const pid_t child = startProgram(arguments, streams);
    if (child < 0)
        return -1;
    if (timeoutSeconds <= 0)
        return waitForProgram(child);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    int status = 0;
    while (true) {
        const pid_t ended = ::waitpid(child, &status, WNOHANG);
        if (ended == child)
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        if (ended < 0 && errno != EINTR)
            return -1;
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(child, SIGKILL);
            waitForProgram(child);
            return kTimedOut;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
}

} // namespace viewpipe::gui
