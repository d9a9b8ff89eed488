#include "MathText.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QPainter>
#include <QTextDocument>

#include <cmath>

#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

namespace viewpipe::gui {

QString mathHtml(const std::string& text)
{
    std::vector<MathRun> runs;
    try {
        runs = mathRuns(text);
    } catch (const InputError&) {
        return QString::fromStdString(text).toHtmlEscaped(); // read files are checked: only a program's slip gets here
    }
    QString html;
    for (const MathRun& run : runs) {
        QString piece = QString::fromStdString(run.text).toHtmlEscaped();
        if (run.italic)
            piece = "<i>" + piece + "</i>";
        for (int k = 0; k < std::abs(run.level); ++k)
            piece = (run.level < 0 ? "<sub>" : "<sup>") + piece + (run.level < 0 ? "</sub>" : "</sup>");
        html += piece;
    }
    return html;
}

namespace {

// The item's text laid out as the list shows it: wrapped to the width left beside its margins.
void layOut(QTextDocument& document, const QStyleOptionViewItem& option, const QModelIndex& index, const QColor& ink = {})
{
    document.setDefaultFont(option.font);
    document.setDocumentMargin(2);
    if (ink.isValid())
        document.setDefaultStyleSheet(QString("body { color: %1; }").arg(ink.name()));
    document.setHtml(mathHtml(index.data(MathItemDelegate::kMathRole).toString().toStdString()));
    const auto* view = qobject_cast<const QAbstractItemView*>(option.widget);
    const int width = view ? view->viewport()->width() : option.rect.width();
    document.setTextWidth(std::max(40, width - 4));
}

} // namespace

void MathItemDelegate::paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const
{
    QStyleOptionViewItem item = option;
    initStyleOption(&item, index);
    item.text.clear(); // the background, focus and selection as the style draws them; the text set here
    QStyle* style = item.widget ? item.widget->style() : QApplication::style();
    style->drawControl(QStyle::CE_ItemViewItem, &item, painter, item.widget);
    const bool selected = option.state & QStyle::State_Selected;
    QTextDocument document;
    layOut(document, option, index, option.palette.color(selected ? QPalette::HighlightedText : QPalette::Text));
    painter->save();
    painter->translate(option.rect.topLeft());
    document.drawContents(painter, QRectF(0, 0, option.rect.width(), option.rect.height()));
    painter->restore();
}

QSize MathItemDelegate::sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const
{
    QTextDocument document;
    layOut(document, option, index);
    return QSize(int(std::ceil(document.idealWidth())), int(std::ceil(document.size().height())));
}

} // namespace viewpipe::gui
