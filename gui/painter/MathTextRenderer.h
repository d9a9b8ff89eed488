#pragma once

// VTK's text actors set math (math_text.hpp) through this: VTK sends any text
// with `$…$` to vtkMathTextUtilities, whose only implementation needs Python
// and matplotlib. This one draws the core's runs with FreeType (italics from
// the font's oblique face, scripts smaller and raised or lowered), so labels,
// captions and their measures all take real subscripts and minus signs.

namespace viewpipe::gui {

// Installs the renderer before VTK makes its text renderer (which asks for
// it once); called by everything that draws or measures text.
void useMathText();

} // namespace viewpipe::gui
