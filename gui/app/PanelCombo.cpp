#include "PanelCombo.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QEvent>
#include <QStyle>

namespace viewpipe::gui {
namespace {

// The list as wide as its longest option, set before it opens (the list's
// container takes the list's minimum width): again when the options are
// renamed and when the font changes.
void widenListToItsOptions(QAbstractItemView* view)
{
    view->setMinimumWidth(view->sizeHintForColumn(0) + 2 * view->frameWidth() +
                          view->style()->pixelMetric(QStyle::PM_ScrollBarExtent));
}

class ListFontWatch : public QObject {
public:
    using QObject::QObject;

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() == QEvent::FontChange)
            if (auto* view = qobject_cast<QAbstractItemView*>(watched))
                widenListToItsOptions(view);
        return false;
    }
};

} // namespace

void fitComboToItsRow(QComboBox* combo)
{
    combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    combo->setMinimumContentsLength(6);
    QAbstractItemView* view = combo->view();
    view->setTextElideMode(Qt::ElideNone);
    view->installEventFilter(new ListFontWatch(combo));
    QAbstractItemModel* model = combo->model();
    auto widen = [view] { widenListToItsOptions(view); };
    QObject::connect(model, &QAbstractItemModel::rowsInserted, combo, widen);
    QObject::connect(model, &QAbstractItemModel::dataChanged, combo, widen);
    QObject::connect(model, &QAbstractItemModel::modelReset, combo, widen);
    widen();
}

} // namespace viewpipe::gui
