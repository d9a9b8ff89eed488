#include "PresentMode.h"

#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QScreen>
#include <QShortcut>
#include <QStatusBar>
#include <QWindow>

#include "LessonPanel.h"
#include "Look.h"
#include "ViewDeck.h"

namespace viewpipe::gui {

PresentMode::PresentMode(QMainWindow* window, Look& look, ViewDeck* views, LessonPanel* lessonPanel)
    : QObject(window), window_(window), look_(look), views_(views), lessonPanel_(lessonPanel), blackout_(new QWidget(window))
{
    blackout_->setObjectName("blackout");
    blackout_->setStyleSheet("background: black");
    blackout_->setAttribute(Qt::WA_StyledBackground);
    blackout_->hide();
    // Space, Backspace and B would get in the way of typing: only while presenting.
    for (const auto& [key, by] : {std::pair{Qt::Key_Space, 1}, std::pair{Qt::Key_Backspace, -1}}) {
        auto* shortcut = new QShortcut(QKeySequence(key), window);
        connect(shortcut, &QShortcut::activated, this, [this, by = by] { emit stepRequested(by); });
        keys_.append(shortcut);
    }
    auto* black = new QShortcut(QKeySequence(Qt::Key_B), window);
    connect(black, &QShortcut::activated, this, [this] {
        fitBlackout();
        blackout_->setVisible(!blackout_->isVisible());
    });
    auto* leave = new QShortcut(QKeySequence(Qt::Key_Escape), window);
    connect(leave, &QShortcut::activated, this, [this] { setPresenting(false); });
    keys_ << black << leave;
    for (QShortcut* shortcut : keys_)
        shortcut->setEnabled(false);
}

void PresentMode::setPresenting(bool on, QScreen* screen)
{
    if (on == isPresenting())
        return;
    const ViewDeck::RenderHold once(*views_);
    if (on)
        enter(screen);
    else
        leave();
    for (QShortcut* shortcut : keys_)
        shortcut->setEnabled(on);
    // A class sees the lesson, not its editing.
    lessonPanel_->setEditorAvailable(!on);
}

void PresentMode::enter(QScreen* screen)
{
    before_ = Before{window_->saveState(), window_->saveGeometry(), window_->windowState(),
                     look_.theme(),        look_.fontSize(),        QApplication::font()};
    for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
        if (dock->objectName() != "lessonDock") // a lesson's caption and questions stay in view
            dock->hide();
    window_->menuBar()->hide();
    window_->statusBar()->hide();
    look_.setTheme(report::Theme::Light); // black on white carries best on a projector
    look_.setFontSize(std::max(look_.fontSize() * 3 / 2, 16));
    QWindow* handle = window_->windowHandle();
    if (screen && handle)
        handle->setScreen(screen);
    // The whole screen even where no window manager enlarges a full-screen window.
    if (const QScreen* target = screen ? screen : (handle ? handle->screen() : nullptr))
        window_->setGeometry(target->geometry());
    window_->showFullScreen();
}

void PresentMode::leave()
{
    const Before before = *before_;
    before_.reset();
    blackout_->hide();
    window_->menuBar()->show();
    window_->statusBar()->show();
    look_.setTheme(before.theme);
    look_.setFontSize(before.fontSize, false); // as it was, not kept: it may be one run's (open --text-scale)
    QApplication::setFont(before.appFont);
    window_->setWindowState(before.states);
    window_->restoreGeometry(before.geometry);
    window_->restoreState(before.docks);
}

bool PresentMode::isBlackedOut() const
{
    return blackout_->isVisible();
}

void PresentMode::fitBlackout()
{
    blackout_->setGeometry(window_->rect());
    blackout_->raise();
}

} // namespace viewpipe::gui
