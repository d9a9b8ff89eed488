#include "ActionRegistry.h"

#include <QMenu>
#include <QWidget>

namespace viewpipe::gui {

ActionRegistry::ActionRegistry(QWidget* window) : QObject(window), window_(window) {}

QAction* ActionRegistry::add(const std::string& id, const QString& text, std::function<void()> handler,
                             const QKeySequence& shortcut)
{
    auto* action = new QAction(text, window_);
    connect(action, &QAction::triggered, this, [handler = std::move(handler)] { handler(); });
    return registered(id, action, shortcut);
}

QAction* ActionRegistry::addToggle(const std::string& id, const QString& text, std::function<void(bool)> handler,
                                   const QKeySequence& shortcut)
{
    auto* action = new QAction(text, window_);
    action->setCheckable(true);
    connect(action, &QAction::triggered, this, std::move(handler));
    return registered(id, action, shortcut);
}

QAction* ActionRegistry::registered(const std::string& id, QAction* action, const QKeySequence& shortcut)
{
    Q_ASSERT(!actions_.count(id));
    action->setObjectName(QString::fromStdString(id));
    if (!shortcut.isEmpty())
        action->setShortcut(shortcut);
    window_->addAction(action);
    actions_.emplace(id, action);
    return action;
}

void ActionRegistry::fill(QMenu* menu, std::initializer_list<const char*> ids) const
{
    for (const char* id : ids) {
        if (std::string(id) == "-")
            menu->addSeparator();
        else
            menu->addAction(action(id));
    }
}

} // namespace viewpipe::gui
