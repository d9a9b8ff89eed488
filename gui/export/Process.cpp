#include "Process.h"

#include <cerrno>
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
    pid_t child = -1;
    const int spawned = posix_spawnp(&child, argv[0], &actions, nullptr, argv.data(), environ);
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

int runProgram(const std::vector<std::string>& arguments, const ChildStreams& given)
{
    ChildStreams streams = given;
    streams.stdinFromNull = true;
    const pid_t child = startProgram(arguments, streams);
    return child < 0 ? -1 : waitForProgram(child);
}

} // namespace viewpipe::gui
