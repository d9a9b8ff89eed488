#pragma once

#include "style/Style.h"

namespace viewpipe::gui {

// Qt's side of a theme: a dark palette for the screen, the light default for slides.
void applyTheme(Theme theme);

} // namespace viewpipe::gui
