#include "VirtualDisplay.h"

#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include "Process.h"

namespace viewpipe::gui {

bool displayReachable()
{
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
        return false;
    // A local display ":N" (or ":N.S") has its server's socket; any other is taken on trust. The socket
    // is looked at, not connected to: a connection dropped unannounced made Xvfb refuse the next one now and then.
    const std::string name = display;
    if (name[0] != ':')
        return true;
    struct stat socket;
    return ::stat(("/tmp/.X11-unix/X" + name.substr(1, name.find('.') - 1)).c_str(), &socket) == 0 && S_ISSOCK(socket.st_mode);
}

VirtualDisplay::VirtualDisplay()
{
    if (displayReachable())
        return;
    int fds[2];
    if (::pipe(fds) != 0)
        throw std::runtime_error("cannot start a virtual display: pipe failed");
    // Xvfb picks a free display number and writes it to the pipe (-displayfd).
    const std::string fd = std::to_string(fds[1]);
    ChildStreams streams;
    streams.closeInChild = fds[0];
    streams.stderrToNull = true;
    server_ = startProgram({"Xvfb", "-displayfd", fd, "-screen", "0", "1920x1080x24", "-nolisten", "tcp"}, streams);
    ::close(fds[1]);
    if (server_ < 0) {
        ::close(fds[0]);
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
        waitForProgram(server_);
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
    waitForProgram(server_);
    ::unsetenv("DISPLAY");
}

} // namespace viewpipe::gui
