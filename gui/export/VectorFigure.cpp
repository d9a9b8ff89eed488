#include "VectorFigure.h"

#include "painter/VtkGeometry.h"

#include <QBuffer>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QSvgGenerator>

#include <algorithm>
#include <cmath>
#include <memory>

namespace viewpipe::gui {
namespace {

// Qt draws text only with a GUI application; the CLI has none: make one that needs no display.
void ensureGuiApplication()
{
    if (QCoreApplication::instance())
        return;
    static int argc = 3;
    static char name[] = "viewpipe", option[] = "-platform", platform[] = "offscreen";
    static char* argv[] = {name, option, platform, nullptr};
    static std::unique_ptr<QGuiApplication> application = std::make_unique<QGuiApplication>(argc, argv);
}

QColor qtColor(const Rgb& c, double opacity = 1)
{
    return QColor::fromRgbF(c.r, c.g, c.b, opacity);
}

QFont font(double pixels, bool bold)
{
    QFont f("DejaVu Sans");
    f.setPixelSize(std::max(1, int(std::lround(pixels))));
    f.setBold(bold);
    return f;
}

// The legend's text is two thirds of the caption's size, as in the PNG.
double legendSize(double fontSize)
{
    return std::max(8.0, std::floor(fontSize * 2 / 3));
}

// The effects' note is three quarters of the caption's size, as in the PNG.
double noteSize(double fontSize)
{
    return std::max(8.0, fontSize * 3 / 4);
}

// The legend's entries and sizes, and where the caption, the legend and the note go: as in the PNG.
struct Layout {
    PictureLayout picture;
    std::vector<const LegendEntry*> entries;
    double rowHeight = 0, swatchWidth = 0, padding = 0;
};

Layout layoutOf(const VectorFigure& f)
{
    Layout layout;
    const FigureView& v = f.view;
    for (const LegendEntry& entry : f.stage->scene->worldLegend)
        if (entry.element != Element::Canonical || f.stage->canonicalOpacity > 0)
            layout.entries.push_back(&entry);
    // Sized as the PNG's legend (gui/painter/Legend.cpp) sizes itself.
    double textWidth = 0, textHeight = 0;
    for (const LegendEntry* entry : layout.entries) {
        const Vec2<double> size = figureTextSize(entry->text, legendSize(v.fontSize), false);
        textWidth = std::max(textWidth, size.x());
        textHeight = std::max(textHeight, size.y());
    }
    layout.rowHeight = std::ceil(1.3 * textHeight);
    layout.swatchWidth = 3 * textHeight;
    layout.padding = std::max(3, int(v.fontSize) / 4);
    const Vec2<double> legend = layout.entries.empty()
                                    ? Vec2<double>::Zero()
                                    : Vec2<double>(textWidth + layout.swatchWidth + 2 * layout.padding + 2,
                                                   double(layout.entries.size()) * layout.rowHeight + 2 * layout.padding);
    layout.picture = layoutPicture(
        v.width, v.height, v.fontSize, legend, f.caption,
        [&](const std::string& t) { return figureTextSize(t, v.fontSize, true); }, f.stage->scene->effectsNote,
        [&](const std::string& t) { return figureTextSize(t, noteSize(v.fontSize), false); });
    return layout;
}

void drawLegend(QPainter& painter, const Layout& layout, const VectorFigure& f)
{
    if (layout.entries.empty())
        return;
    const Box2& box = layout.picture.legend;
    const QRectF frame(box.min.x(), box.min.y(), box.max.x() - box.min.x(), box.max.y() - box.min.y());
    painter.setPen(QPen(qtColor(elementColor(Element::Frame, f.theme)), 1));
    painter.setBrush(qtColor(backgroundColor(f.theme, false), 0.85));
    painter.drawRect(frame);
    painter.setFont(font(legendSize(f.view.fontSize), false));
    const double h = layout.rowHeight;
    for (std::size_t k = 0; k < layout.entries.size(); ++k) {
        const LegendEntry& entry = *layout.entries[k];
        const double top = box.min.y() + layout.padding + double(k) * h;
        const QRectF swatch(box.min.x() + layout.padding, top + 0.1 * h, layout.swatchWidth, 0.8 * h);
        const bool face = entry.swatch == LegendEntry::Swatch::Face;
        const QColor c = qtColor(styledColor(entry.element, face, f.theme), entry.opacity);
        painter.setPen(Qt::NoPen);
        auto stripes = [&](const auto& colors) {
            const double w = swatch.width() / double(colors.size());
            for (std::size_t j = 0; j < colors.size(); ++j)
                painter.fillRect(QRectF(swatch.left() + double(j) * w, swatch.top(), w, swatch.height()), qtColor(colors[j]));
        };
        switch (entry.swatch) {
        case LegendEntry::Swatch::Line:
            painter.fillRect(QRectF(swatch.left(), swatch.center().y() - 0.12 * h, swatch.width(), 0.24 * h), c);
            break;
        case LegendEntry::Swatch::Face: painter.fillRect(swatch, c); break;
        case LegendEntry::Swatch::Dot:
            painter.setBrush(c);
            painter.drawEllipse(swatch.center(), 0.3 * h, 0.3 * h);
            break;
        case LegendEntry::Swatch::Bands: stripes(kBandRamp); break;
        case LegendEntry::Swatch::Pixels: stripes(kRasterPalette); break;
        }
        painter.setPen(qtColor(elementColor(Element::Objects, f.theme)));
        painter.drawText(QRectF(swatch.right() + layout.padding, top, box.max.x() - swatch.right(), h),
                         Qt::AlignLeft | Qt::AlignVCenter, QString::fromStdString(entry.text));
    }
}

void paint(QPainter& painter, const Figure& figure, const Layout& layout, const VectorFigure& f)
{
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF page(0, 0, figure.width, figure.height);
    painter.fillRect(page, qtColor(backgroundColor(f.theme, false)));
    painter.setClipRect(page);
    for (const FigureShape& s : figure.shapes) {
        QPolygonF polygon;
        for (const Vec2<double>& p : s.points)
            polygon << QPointF(p.x(), p.y());
        const QColor c = qtColor(styledColor(s.element, s.surface, f.theme), s.opacity);
        if (s.surface) {
            painter.setPen(Qt::NoPen);
            painter.setBrush(c);
            painter.drawPolygon(polygon);
        } else {
            painter.setPen(QPen(c, s.lineWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
            painter.setBrush(Qt::NoBrush);
            painter.drawPolyline(polygon);
        }
    }
    const QFont labelFont = font(f.view.fontSize, true), minorFont = font(noteSize(f.view.fontSize), false);
    for (const PlacedLabel& l : figure.labels) {
        painter.setFont(l.minor ? minorFont : labelFont);
        const QFontMetricsF metrics(painter.font());
        const QColor c = qtColor(elementColor(l.element, f.theme));
        if (l.leader) {
            const Vec2<double> end = l.box.nearest(l.anchor);
            painter.setPen(QPen(c, 1.5 * f.view.lineScale));
            painter.drawLine(QPointF(l.anchor.x(), l.anchor.y()), QPointF(end.x(), end.y()));
        }
        painter.setPen(c);
        // The box is the text's from the lowest descender up, as VTK measures it.
        painter.drawText(QPointF(l.box.min.x(), l.box.max.y() - metrics.descent()), QString::fromStdString(l.text));
    }
    painter.setPen(qtColor(elementColor(Element::Objects, f.theme)));
    auto drawLines = [&](const std::vector<std::string>& lines, const QFont& qfont, const Box2& box, double line) {
        if (lines.empty())
            return;
        // On the background, as in the PNG: lines behind do not cross the text.
        painter.fillRect(QRectF(box.min.x(), box.min.y(), box.max.x() - box.min.x(), box.max.y() - box.min.y()),
                         qtColor(backgroundColor(f.theme, false), 0.85));
        painter.setFont(qfont);
        const QFontMetricsF metrics(qfont);
        // Lines as VTK sets them: the last one's descent at the box's bottom, `line` apart.
        for (std::size_t k = 0; k < lines.size(); ++k)
            painter.drawText(QPointF(box.min.x(), box.max.y() - double(lines.size() - 1 - k) * line - metrics.descent()),
                             QString::fromStdString(lines[k]));
    };
    const PictureLayout& p = layout.picture;
    drawLines(p.captionLines, font(f.view.fontSize, true), p.caption, p.captionLine);
    drawLines(p.noteLines, font(noteSize(f.view.fontSize), false), p.note, p.noteLine);
    drawLegend(painter, layout, f);
}

} // namespace

Figure flatFigure(const VectorFigure& f)
{
    ensureGuiApplication();
    const Layout layout = layoutOf(f);
    // Measured as the PNG's painter measures them: both pictures place their labels alike.
    const LabelMeasure measure = [&](const Label& label) {
        return label.minor ? figureTextSize(label.text, noteSize(f.view.fontSize), false)
                           : figureTextSize(label.text, f.view.fontSize, true);
    };
    std::vector<Box2> reserved = {layout.picture.caption, layout.picture.note};
    if (!layout.entries.empty())
        reserved.push_back(layout.picture.legend);
    return drawFigure(*f.stage, f.view, measure, reserved);
}

void writeVectorFigure(const VectorFigure& f, const std::string& format, const std::filesystem::path& file)
{
    ensureGuiApplication();
    const Figure figure = flatFigure(f);
    const Layout layout = layoutOf(f);
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    if (format == "svg") {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(QSize(figure.width, figure.height));
        svg.setViewBox(QRectF(0, 0, figure.width, figure.height));
        svg.setResolution(72);
        svg.setTitle(QString::fromStdString(f.caption));
        QPainter painter;
        if (!painter.begin(&svg))
            throw std::runtime_error("cannot draw " + file.string());
        paint(painter, figure, layout, f);
        painter.end();
    } else {
        QPdfWriter pdf(&buffer);
        pdf.setResolution(72); // one pixel of the figure is one point of the page
        pdf.setPageSize(QPageSize(QSizeF(figure.width, figure.height), QPageSize::Point));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setTitle(QString::fromStdString(f.caption));
        pdf.setCreator("ViewPipe");
        QPainter painter;
        if (!painter.begin(&pdf))
            throw std::runtime_error("cannot draw " + file.string());
        paint(painter, figure, layout, f);
        painter.end();
    }
    writeFileAtomically(file, buffer.data().toStdString());
}

} // namespace viewpipe::gui
