#pragma once

#include <QString>

namespace viewpipe::gui {

// The built-in scenes: $VIEWPIPE_DATA/scenes if set, else the source tree's data/scenes.
QString scenesDirectory();

} // namespace viewpipe::gui
