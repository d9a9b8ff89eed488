#pragma once

// Debian's VTK renders through X only. Where there is no display, this starts
// a private Xvfb for the life of the object and points DISPLAY at it, so that
// headless commands need nothing set up by the user.

#include <sys/types.h>

namespace viewpipe::gui {

class VirtualDisplay {
public:
    // Does nothing when DISPLAY is already set. Throws std::runtime_error when
    // a display is needed and Xvfb cannot be started.
    VirtualDisplay();
    ~VirtualDisplay();
    VirtualDisplay(const VirtualDisplay&) = delete;
    VirtualDisplay& operator=(const VirtualDisplay&) = delete;

private:
    pid_t server_ = -1;
};

} // namespace viewpipe::gui
