#include "Waiting.h"

#include <QEventLoop>
#include <QProgressDialog>
#include <QTimer>

#include <atomic>
#include <exception>
#include <thread>

#include "viewpipe/error.hpp"
#include "viewpipe/mesh_io.hpp"

namespace viewpipe::gui {
namespace {

constexpr int kQuietMilliseconds = 500; // work this short is not announced

} // namespace

void waitShowingProgress(QWidget* window, const QString& what, const std::function<void()>& work)
{
    QEventLoop loop;
    std::atomic<bool> stop = false;
    QProgressDialog progress(what, QObject::tr("Cancel"), 0, 0, window); // a busy bar
    progress.setObjectName("waitingProgress");
    progress.setWindowModality(Qt::ApplicationModal); // no other window takes keys or clicks meanwhile
    progress.reset(); // stops the dialog's own timer: the one below shows it
    const auto cancel = [&] {
        stop = true;
        loop.quit(); // the rest of the wait (the reading stops at once) without the dialog, keys and clicks waiting again
    };
    QObject::connect(&progress, &QProgressDialog::canceled, cancel); // its button, its window closed
    QObject::connect(&progress, &QDialog::rejected, cancel);         // Escape

    std::atomic<bool> finished = false;
    std::exception_ptr failure;
    std::thread worker([&] {
        try {
            const MeshReadingStop stoppable(stop);
            work();
        } catch (...) {
            failure = std::current_exception();
        }
        finished = true;
        QMetaObject::invokeMethod(&loop, "quit", Qt::QueuedConnection);
    });
    QTimer announce;
    announce.setSingleShot(true);
    QObject::connect(&announce, &QTimer::timeout, &loop, &QEventLoop::quit);
    announce.start(kQuietMilliseconds);
    bool shown = false;
    try {
        // Keys and clicks wait until the work is done; if it takes long, the dialog says so and
        // takes them (its Cancel) while the window, modal to it, ignores them.
        loop.exec(QEventLoop::ExcludeUserInputEvents);
        if (!finished) {
            progress.show();
            shown = true;
            loop.exec();
        }
        if (!finished)
            loop.exec(QEventLoop::ExcludeUserInputEvents);
    } catch (...) { // an event handler threw: the worker still holds the loop
        stop = true;
        worker.join();
        throw;
    }
    worker.join();
    if (shown) { // keys go back to the window, not to wherever the dialog left them
        progress.hide();
        if (window)
            window->activateWindow();
    }
    if (failure)
        std::rethrow_exception(failure);
    if (stop) // cancelled once nothing was left to read: what was asked for is still not done
        throw InputError("$", "reading was stopped");
}

} // namespace viewpipe::gui
