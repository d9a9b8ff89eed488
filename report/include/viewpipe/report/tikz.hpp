#pragma once

// Flat figures as TikZ, for lecture notes and slides: one standalone LaTeX
// document per figure, its colors and styles named at the top so that a
// lecturer can restyle them, and a document that shows them all. Compiles
// with pdflatex as written (packages: tikz, standalone), and \input
// into any document that loads tikz and standalone, with no font warnings:
// its text is Helvetica (psnfss) set at 10 pt and scaled, math as the other
// pictures set it (math_text.hpp's runs) in the text's own font.

#include <string>
#include <utility>
#include <vector>

#include "viewpipe/report/figure.hpp"
#include "viewpipe/report/storyboard.hpp"
#include "viewpipe/report/style.hpp"

namespace viewpipe::report {

// A figure as a standalone document; 16 cm wide.
std::string tikzFigure(const Figure& figure, Theme theme);
// A storyboard as one standalone document, 16 cm wide: each cell's figure in its box, then the overlay.
std::string tikzStoryboard(const Storyboard& storyboard, Theme theme);

// An article showing each figure (file name in the same folder, caption) as a
// figure with its caption, through the standalone package.
std::string tikzFiguresDocument(const std::vector<std::pair<std::string, std::string>>& figures);

// Text as LaTeX sets it: its special characters escaped, the signs beyond
// ASCII that pdflatex does not know as text written as math.
std::string texEscaped(const std::string& text);
// Text with inline math between `$` signs (`\$` a dollar sign) as LaTeX: the
// text escaped, the math as written (the subset is LaTeX).
std::string texRichText(const std::string& text);

} // namespace viewpipe::report
