#pragma once

// Work that can take a while (opening a scene with a large mesh) done off the
// GUI thread, with the window kept painted and a word of what is under way.

#include <QString>

#include <functional>

class QWidget;

namespace viewpipe::gui {

// Runs `work` on a worker thread and waits for it. Meanwhile the window keeps
// painting and keys and clicks wait until the work is done (Qt delivers them
// then). If it takes longer than half a second a dialog over `window` says
// `what` is under way, application-modal: while it shows, the window takes no
// keys or clicks (those made before it showed are dropped). Its Cancel stops
// the mesh files being read (MeshReadingStop) and the wait throws InputError
// "reading was stopped", even if the work was done. Rethrows what `work` throws.
void waitShowingProgress(QWidget* window, const QString& what, const std::function<void()>& work);

} // namespace viewpipe::gui
