#pragma once

#include "viewpipe/report/style.hpp"

namespace viewpipe::gui {

// Qt's side of a theme: a dark palette for the screen, the light default for slides.
void applyTheme(report::Theme theme);

} // namespace viewpipe::gui
