#pragma once

// Each stage's matrix in symbols, row by row, as a lecture writes it (each
// cell math, math_text.hpp's subset, without its $ signs), with notes that
// define the short names in the cells (text with math). No Qt.

#include <array>
#include <string>
#include <vector>

namespace viewpipe {

struct SymbolicForm {
    std::array<std::string, 16> cells;
    std::vector<std::string> notes;
};

// Unknown symbols give empty cells.
SymbolicForm symbolicMatrix(const std::string& symbol);

// The symbolic form as a LaTeX display: "\mathit{SH}_{\mathrm{per}} = \begin{bmatrix}...\end{bmatrix}";
// empty for an unknown symbol.
std::string symbolicLatex(const std::string& symbol);

} // namespace viewpipe
