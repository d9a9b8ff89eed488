#pragma once

#include <QString>

namespace viewpipe::gui {

// The built-in scenes: $VIEWPIPE_DATA/scenes if set, else the source tree's data/scenes.
QString scenesDirectory();
// The built-in lessons: data/lessons, beside the scenes.
QString lessonsDirectory();

} // namespace viewpipe::gui
