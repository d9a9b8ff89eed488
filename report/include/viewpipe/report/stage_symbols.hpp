#pragma once

// Each stage's matrix in symbols, row by row, as a lecture writes it (each
// cell math, math_text.hpp's subset, without its $ signs), with notes that
// define the short names in the cells (text with math). No Qt.

#include <array>
#include <string>
#include <vector>

#include "viewpipe/stage_kind.hpp"

namespace viewpipe::report {

struct SymbolicForm {
    std::array<std::string, 16> cells;
    std::vector<std::string> notes;
};

// Empty cells for a kind with no matrix of its own (M, the divide).
SymbolicForm symbolicMatrix(StageKind kind);

// The symbolic form as a LaTeX display: "\mathit{SH}_{\mathrm{per}} = \begin{bmatrix}...\end{bmatrix}";
// empty where the form is.
std::string symbolicLatex(StageKind kind);

} // namespace viewpipe::report
