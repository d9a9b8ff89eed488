#pragma once

// The window's actions by id ("file.open", "view.present"), each triggering a
// named handler; menus list ids. One place to find what a command does, and
// tests and shortcuts reach an action by its id, not by its menu text.

#include <QAction>
#include <QKeySequence>
#include <QObject>

#include <functional>
#include <initializer_list>
#include <map>
#include <string>

class QMenu;

namespace viewpipe::gui {

class ActionRegistry : public QObject {
    Q_OBJECT
public:
    explicit ActionRegistry(QWidget* window);

    // A new action `id`; `handler` runs when it is triggered. The action is the
    // window's too, so its shortcut works with the menu bar hidden (presenting).
    QAction* add(const std::string& id, const QString& text, std::function<void()> handler,
                 const QKeySequence& shortcut = {});
    // The same for a checkable action; `handler` gets the new state.
    QAction* addToggle(const std::string& id, const QString& text, std::function<void(bool)> handler,
                       const QKeySequence& shortcut = {});
    // The action `id`; throws std::out_of_range for an id never added.
    QAction* action(const std::string& id) const { return actions_.at(id); }
    // Appends the actions `ids` to `menu` in order; "-" is a separator.
    void fill(QMenu* menu, std::initializer_list<const char*> ids) const;

private:
    QAction* registered(const std::string& id, QAction* action, const QKeySequence& shortcut);

    QWidget* window_;
    std::map<std::string, QAction*> actions_;
};

} // namespace viewpipe::gui
