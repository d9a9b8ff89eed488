#pragma once

// `viewpipe open`: the desktop app, or, with a screenshot file, one rendered
// picture of the whole window at a given stage.

#include <optional>
#include <string>

namespace viewpipe::gui {

struct OpenOptions {
    std::string scene;          // the scene file
    int stage = 0;
    std::string screenshot;     // empty: interactive
    int width = 0, height = 0;  // 0: 1600x950 for a screenshot, else as large as that fits the screen
    std::optional<std::string> theme; // "dark" or "light"; default: the user's setting
    std::string panel;                // "matrices", "parameters" or "accuracy" (measured first): shown in front
    std::string lesson;               // a lesson to open, at `step` (from 1), its question revealed or not
    int step = 1;
    bool reveal = false;
    bool present = false;             // full screen, as View > Present
    std::string layout = "stages";    // or "storyboard": every stage at once, as View > Storyboard
    int textScale = 0;                // percent of the default text size; 0: the user's setting (100 for a screenshot)
};

// Returns the process exit code. Throws InputError for bad input.
int runOpen(int argc, char** argv, const OpenOptions& options);

} // namespace viewpipe::gui
