#pragma once

#include <QString>
#include <QStringList>
#include <array>

namespace viewpipe::gui {

// The symbolic form of a stage's matrix, row by row, as a lecture writes it,
// with notes that define the short names used in the cells.
struct SymbolicForm {
    std::array<QString, 16> cells;
    QStringList notes;
};

// Unknown symbols give empty cells.
SymbolicForm symbolicMatrix(const QString& symbol);

} // namespace viewpipe::gui
