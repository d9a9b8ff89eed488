#pragma once

class QComboBox;

namespace viewpipe::gui {

// A combo box as wide as its panel's row gives it, not as its longest option:
// at larger text one long option ("standard: near -> -1, far -> 1") widened a
// whole dock's content past the dock. The option shown is elided where the row
// is narrower; the list opens as wide as its longest option.
void fitComboToItsRow(QComboBox* combo);

} // namespace viewpipe::gui
