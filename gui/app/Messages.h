#pragma once

// Where the roles tell the user something: an error or warning (the window's
// status bar, and a message box where popups are on) or a passing note (saved,
// exported, copied). The window is one; a test may give a role its own.

#include <QString>

namespace viewpipe::gui {

class Messages {
public:
    virtual ~Messages() = default;
    virtual void showMessage(const QString& text) = 0;
    // The last error or warning shown.
    virtual QString lastMessage() const = 0;
    // A note that goes after `milliseconds`.
    virtual void showNote(const QString& text, int milliseconds) = 0;
};

} // namespace viewpipe::gui
