#pragma once

#include <QString>

class QWidget;

namespace viewpipe::gui {

// The built-in scenes: $VIEWPIPE_DATA/scenes if set, else the source tree's data/scenes.
QString scenesDirectory();
// The built-in lessons: data/lessons, beside the scenes.
QString lessonsDirectory();

// Where a file dialog opens: the folder last chosen in one (kept in the
// settings), else the user's documents, never the program's folder; with a
// file `name` in it when one is given.
QString dialogPath(const QString& name = {});
// Remembers the folder of a file chosen in a dialog, for the next dialog.
void rememberDialogFolder(const QString& chosen);

// A file of the built-in data (a preset scene, a built-in lesson): a starting
// point for the user's own, never a file a save overwrites.
bool isBuiltInFile(const QString& path);

// The file dialogs, opening at dialogPath and remembering the folder chosen;
// empty when cancelled. `suggested` is a file name, or a path kept as it is
// when it lies outside the built-in data (a document's own file).
QString chooseFileToOpen(QWidget* parent, const QString& title, const QString& filter);
QString chooseFileToSave(QWidget* parent, const QString& title, const QString& suggested, const QString& filter);

} // namespace viewpipe::gui
