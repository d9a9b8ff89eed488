#include "VirtualDisplay.h"

#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace viewpipe::gui {

VirtualDisplay::VirtualDisplay()
{
    const char* display = std::getenv("DISPLAY");
    if (display && *display)
        return;
    int fds[2];
    if (::pipe(fds) != 0)
        throw std::runtime_error("cannot start a virtual display: pipe failed");
    // Xvfb picks a free display number and writes it to the pipe (-displayfd).
    const std::string fd = std::to_string(fds[1]);
    const char* argv[] = {"Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1080x24", "-nolisten", "tcp", nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    const int spawned = posix_spawnp(&server_, "Xvfb", &actions, nullptr, const_cast<char**>(argv), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (spawned != 0) {
        ::close(fds[0]);
        server_ = -1;
        throw std::runtime_error("no display, and Xvfb could not be started (install the xvfb package)");
    }
    std::string number;
    pollfd wait{fds[0], POLLIN, 0};
    char c;
    while (::poll(&wait, 1, 10000) > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n')
        number += c;
    ::close(fds[0]);
    if (number.empty()) {
        ::kill(server_, SIGTERM);
        ::waitpid(server_, nullptr, 0);
        server_ = -1;
        throw std::runtime_error("no display, and Xvfb did not start in time");
    }
    ::setenv("DISPLAY", (":" + number).c_str(), 1);
}

VirtualDisplay::~VirtualDisplay()
{
    if (server_ <= 0)
        return;
    ::kill(server_, SIGTERM);
    ::waitpid(server_, nullptr, 0);
    ::unsetenv("DISPLAY");
}

} // namespace viewpipe::gui
