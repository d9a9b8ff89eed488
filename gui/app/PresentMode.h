#pragma once

// View > Present (F5): the two views alone, full screen, in the projector's
// look (light theme, text half as large again); a lesson's dock stays. Space
// steps on and Backspace back (as Page Down and Page Up always do, a
// presenter's clicker sends these); B blacks the screen out and back; Esc
// leaves, restoring the window as it was.

#include <QByteArray>
#include <QFont>
#include <QList>
#include <QObject>

#include <optional>

#include "Theme.h"

class QMainWindow;
class QScreen;
class QShortcut;
class QWidget;

namespace viewpipe::gui {

class LessonPanel;
class Look;
class ViewDeck;

class PresentMode : public QObject {
    Q_OBJECT
public:
    // Presents `window` (its docks, menus and geometry) in the projector's `look`; `views` are drawn once
    // per change; `lessonPanel` offers no editing while presenting.
    PresentMode(QMainWindow* window, Look& look, ViewDeck* views, LessonPanel* lessonPanel);

    // On `screen`, the window's own by default.
    void setPresenting(bool on, QScreen* screen = nullptr);
    bool isPresenting() const { return before_.has_value(); }
    bool isBlackedOut() const;
    // Keeps the blackout over the whole window.
    void fitBlackout();

signals:
    // Space or Backspace: the next step or the one before.
    void stepRequested(int by);

private:
    void enter(QScreen* screen);
    void leave();

    QMainWindow* window_;
    Look& look_;
    ViewDeck* views_;
    LessonPanel* lessonPanel_;
    // What presenting changed, to be restored.
    struct Before {
        QByteArray docks, geometry;
        Qt::WindowStates states;
        report::Theme theme;
        int fontSize;
        QFont appFont; // the widgets' (before any Larger Text, the system's)
    };
    std::optional<Before> before_;
    QWidget* blackout_;
    QList<QShortcut*> keys_; // active only while presenting
};

} // namespace viewpipe::gui
