#pragma once

// Debian's VTK renders through X only. Where there is no display (or one that
// does not answer), this starts
// a private Xvfb for the life of the object and points DISPLAY at it, so that
// headless commands need nothing set up by the user.

#include <sys/types.h>

namespace viewpipe::gui {

// Whether DISPLAY names an X server that is there (a local one's socket; a
// remote one is taken on trust): where it is not, Qt would abort.
bool displayReachable();

class VirtualDisplay {
public:
    // Does nothing when DISPLAY names a display that answers; otherwise points
    // DISPLAY at a private Xvfb. Throws std::runtime_error when Xvfb cannot be started.
    VirtualDisplay();
    ~VirtualDisplay();
    VirtualDisplay(const VirtualDisplay&) = delete;
    VirtualDisplay& operator=(const VirtualDisplay&) = delete;

private:
    pid_t server_ = -1;
};

} // namespace viewpipe::gui
