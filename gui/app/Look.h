#pragma once

// The window's look as Present sets it for the projector and restores it: the
// theme and the text's size.

#include "viewpipe/report/style.hpp"

namespace viewpipe::gui {

class Look {
public:
    virtual ~Look() = default;
    virtual report::Theme theme() const = 0;
    virtual void setTheme(report::Theme theme) = 0;
    virtual int fontSize() const = 0;
    // `remember`: kept in the user's settings for the next start.
    virtual void setFontSize(int points, bool remember = true) = 0;
};

} // namespace viewpipe::gui
