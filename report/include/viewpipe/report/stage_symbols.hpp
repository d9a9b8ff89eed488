#pragma once

// Each stage's matrix in symbols, row by row, as a lecture writes it, with
// notes that define the short names in the cells (UTF-8 text). No Qt.

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

} // namespace viewpipe
