#include "Waiting.h"

#include <QEventLoop>
#include <QProgressDialog>
#include <QTimer>

#include <exception>
#include <thread>

namespace viewpipe::gui {
namespace {

constexpr int kQuietMilliseconds = 500; // work this short is not announced

} // namespace

void waitShowingProgress(QWidget* window, const QString& what, const std::function<void()>& work)
{
    QProgressDialog progress(what, QString(), 0, 0, window); // no cancel button; a busy bar
    progress.setObjectName("waitingProgress");
    progress.setWindowModality(Qt::WindowModal);
    progress.reset(); // stops the dialog's own timer: the one below shows it
    QTimer announce;
    announce.setSingleShot(true);
    QObject::connect(&announce, &QTimer::timeout, &progress, &QProgressDialog::show);
    announce.start(kQuietMilliseconds);

    QEventLoop loop;
    std::exception_ptr failure;
    std::thread worker([&] {
        try {
            work();
        } catch (...) {
            failure = std::current_exception();
        }
        QMetaObject::invokeMethod(&loop, "quit", Qt::QueuedConnection);
    });
    try {
        loop.exec(QEventLoop::ExcludeUserInputEvents);
    } catch (...) { // an event handler threw: the worker still holds the loop
        worker.join();
        throw;
    }
    worker.join();
    if (progress.isVisible()) { // keys go back to the window, not to wherever the dialog left them
        progress.hide();
        if (window)
            window->activateWindow();
    }
    if (failure)
        std::rethrow_exception(failure);
}

} // namespace viewpipe::gui
