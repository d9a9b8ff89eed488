#pragma once

// Text with inline math (math_text.hpp) as Qt rich text: the core's runs set
// with HTML's italics, sub- and superscripts, as KaTeX sets them on the page.

#include <QString>
#include <QStyledItemDelegate>

#include <string>

namespace viewpipe::gui {

QString mathHtml(const std::string& text);

// Draws a list's items from their math text (kMathRole) as mathHtml sets it,
// wrapped to the list's width; the display text stays plain for screen readers.
class MathItemDelegate : public QStyledItemDelegate {
public:
    static constexpr int kMathRole = Qt::UserRole + 1;
    using QStyledItemDelegate::QStyledItemDelegate;
    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override;
    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override;
};

} // namespace viewpipe::gui
