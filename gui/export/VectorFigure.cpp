#include "VectorFigure.h"

#include "painter/VtkGeometry.h"
#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QImage>
#include <QGuiApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QRegularExpression>
#include <QSvgGenerator>

#include <algorithm>
#include <functional>
#include <cmath>
#include <memory>

#include <pwd.h>
#include <unistd.h>

namespace viewpipe::gui {
namespace {

// Qt draws text only with a GUI application; the CLI has none: make one that needs no display.
void ensureGuiApplication()
{
    if (QCoreApplication::instance())
        return;
    // Without a session (a console, xvfb-run) Qt warns on stderr that XDG_RUNTIME_DIR is not set and
    // takes /tmp/runtime-USER: the same folder, named before it looks, keeps the command's output clean.
    // Only a folder of our own (not a link someone left in /tmp); else Qt's own checks and warning.
    const passwd* user = ::getpwuid(::geteuid());
    if (!qEnvironmentVariableIsSet("XDG_RUNTIME_DIR") && user) {
        const QString runtime = QDir::tempPath() + "/runtime-" + QString::fromLocal8Bit(user->pw_name);
        QDir().mkdir(runtime);
        const QFileInfo folder(runtime);
        if (folder.isDir() && !folder.isSymLink() && folder.ownerId() == ::geteuid() &&
            QFile::setPermissions(runtime, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner))
            qputenv("XDG_RUNTIME_DIR", runtime.toLocal8Bit());
    }
    static int argc = 3;
    static char name[] = "viewpipe", option[] = "-platform", platform[] = "offscreen";
    static char* argv[] = {name, option, platform, nullptr};
    static std::unique_ptr<QGuiApplication> application = std::make_unique<QGuiApplication>(argc, argv);
}

QColor qtColor(const report::Rgb& c, double opacity = 1)
{
    return QColor::fromRgbF(c.r, c.g, c.b, opacity);
}

QRectF rectOf(const report::Box2& box)
{
    return QRectF(box.min.x(), box.min.y(), box.max.x() - box.min.x(), box.max.y() - box.min.y());
}

QFont font(double pixels, bool bold)
{
    QFont f("DejaVu Sans");
    f.setPixelSize(std::max(1, int(std::lround(pixels))));
    f.setBold(bold);
    return f;
}

// Text with math (math_text.hpp) from its baseline's left end, as the PNG's renderer sets it.
void drawMathText(QPainter& painter, QPointF at, const std::string& text, const QFont& base)
{
    std::vector<MathRun> runs;
    try {
        runs = mathRuns(text);
    } catch (const InputError&) {
        runs = {{text, false, 0}}; // checked where it was read: only a program's slip gets here
    }
    const double size = base.pixelSize();
    for (const MathRun& run : runs) {
        QFont f = base;
        f.setItalic(run.italic);
        if (run.level != 0)
            f.setPixelSize(std::max(1, int(std::lround(size * std::pow(kScriptScale, std::abs(run.level))))));
        const double shift = run.level > 0 ? -kSuperscriptRise * run.level * size : -kSubscriptDrop * run.level * size;
        painter.setFont(f);
        const QString piece = QString::fromStdString(run.text);
        painter.drawText(QPointF(at.x(), at.y() + shift), piece);
        at.rx() += QFontMetricsF(f).horizontalAdvance(piece);
    }
    painter.setFont(base);
}

// The legend's entries, and where the caption, the legend and the note go: as in the PNG.
struct Layout {
    report::PictureLayout picture;
    std::vector<const LegendEntry*> entries; // empty where the legend is left out
};

Layout layoutOf(const VectorFigure& f)
{
    Layout layout;
    const report::FigureView& v = f.view;
    report::PictureText text = report::stagePictureText(*f.stage, f.caption, v.textSize, v.minFontSize, v.subject, v.subjectShown, v.legendPlace);
    text.zoom = v.zoom;
    layout.picture = report::layoutPicture(v.width, v.height, text, figureFontMeasure());
    if (!layout.picture.legend.isEmpty())
        layout.entries = text.legend;
    return layout;
}

void drawLegend(QPainter& painter, const report::Figure& figure, report::Theme theme)
{
    if (figure.legend.empty())
        return;
    const report::Box2& box = figure.layout.legend;
    const report::LegendLayout& rows = figure.layout.legendRows;
    const QRectF frame = rectOf(box);
    painter.setPen(QPen(qtColor(report::elementColor(Element::Frame, theme)), 1));
    painter.setBrush(Qt::NoBrush); // on its backdrop
    painter.drawRect(frame);
    painter.setFont(font(rows.textSize, false));
    const double h = rows.rowHeight;
    for (std::size_t k = 0; k < figure.legend.size(); ++k) {
        const LegendEntry& entry = *figure.legend[k];
        const report::LegendRow at = report::legendRow(figure.layout, k);
        const double top = at.row.min.y(), text = at.textHeight, slotRight = at.textLeft;
        const QPointF middle(at.swatchCenter.x(), at.swatchCenter.y());
        const QRectF swatch(middle.x() - 0.75 * text, middle.y() - 0.2 * text, 1.5 * text, 0.4 * text);
        const bool face = entry.swatch == LegendEntry::Swatch::Face;
        const QColor c = qtColor(report::styledColor(entry.element, face, theme), entry.opacity);
        painter.setPen(Qt::NoPen);
        auto stripes = [&](const auto& colors) {
            const double w = swatch.width() / double(colors.size());
            for (std::size_t j = 0; j < colors.size(); ++j)
                painter.fillRect(QRectF(swatch.left() + double(j) * w, swatch.top(), w, swatch.height()), qtColor(colors[j]));
        };
        switch (entry.swatch) {
        case LegendEntry::Swatch::Line:
            painter.fillRect(QRectF(swatch.left(), middle.y() - 0.06 * text, swatch.width(), 0.12 * text), c);
            break;
        case LegendEntry::Swatch::Face: painter.fillRect(swatch, c); break;
        case LegendEntry::Swatch::Dot:
            painter.setBrush(c);
            painter.drawEllipse(middle, 0.2 * text, 0.2 * text);
            break;
        case LegendEntry::Swatch::Bands: stripes(report::kBandRamp); break;
        case LegendEntry::Swatch::Pixels: stripes(report::kRasterPalette); break;
        }
        painter.setPen(qtColor(report::elementColor(Element::Objects, theme)));
        const QFontMetricsF metrics(painter.font());
        drawMathText(painter, QPointF(slotRight, top + h / 2 + (metrics.ascent() - metrics.descent()) / 2), entry.text,
                     painter.font());
    }
}

} // namespace

void paintFigure(QPainter& painter, const report::Figure& figure, report::Theme theme)
{
    for (const report::FigureShape& s : figure.shapes) {
        QPolygonF polygon;
        for (const Vec2<double>& p : s.points)
            polygon << QPointF(p.x(), p.y());
        const QColor c = qtColor(s.color.value_or(report::styledColor(s.element, s.surface, theme)), s.opacity);
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
    const report::PictureLayout& p = figure.layout;
    for (const report::Box2& box : report::textBackdrops(p, figure.height))
        painter.fillRect(rectOf(box), qtColor(report::backgroundColor(theme, false)));
    const QFont labelFont = font(figure.fontSize, true), minorFont = font(report::smallTextSize(figure.fontSize), false);
    for (const report::PlacedLabel& l : figure.labels) {
        painter.setFont(l.minor ? minorFont : labelFont);
        const QFontMetricsF metrics(painter.font());
        const QColor c = qtColor(report::elementColor(l.element, theme));
        if (l.leader) {
            const Vec2<double> end = l.box.nearest(l.anchor);
            painter.setPen(QPen(c, 1.5 * figure.lineScale));
            painter.drawLine(QPointF(l.anchor.x(), l.anchor.y()), QPointF(end.x(), end.y()));
        }
        painter.fillRect(rectOf(l.box), qtColor(report::backgroundColor(theme, false), report::kLabelBackdropOpacity));
        painter.setPen(c);
        // The box is the text's from the lowest descender up, as VTK measures it.
        drawMathText(painter, QPointF(l.box.min.x(), l.box.max.y() - metrics.descent()), l.text, painter.font());
    }
    painter.setPen(qtColor(report::elementColor(Element::Objects, theme)));
    auto drawLines = [&](const std::vector<std::string>& lines, const QFont& qfont, const report::Box2& box, double line) {
        if (lines.empty())
            return;
        painter.setFont(qfont);
        const QFontMetricsF metrics(qfont);
        // Lines as VTK sets them: the last one's descent at the box's bottom, `line` apart.
        for (std::size_t k = 0; k < lines.size(); ++k)
            drawMathText(painter, QPointF(box.min.x(), box.max.y() - double(lines.size() - 1 - k) * line - metrics.descent()),
                         lines[k], qfont);
    };
    drawLines(p.captionLines, font(p.captionSize, true), p.caption, p.captionLine);
    drawLines(p.noteLines, font(p.noteSize, false), p.note, p.noteLine);
    drawLegend(painter, figure, theme);
}

namespace {

// Writes `file` atomically: a page of `width` by `height` on the theme's background, drawn by `draw`, as
// SVG, PDF or PNG (by `format`); throws std::runtime_error when it cannot.
void writePage(const std::filesystem::path& file, int width, int height, report::Theme theme, const std::string& format,
               const std::string& title, const std::function<void(QPainter&)>& draw)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    std::unique_ptr<QPaintDevice> device;
    if (format == "svg") {
        auto svg = std::make_unique<QSvgGenerator>();
        svg->setOutputDevice(&buffer);
        svg->setSize(QSize(width, height));
        svg->setViewBox(QRectF(0, 0, width, height));
        svg->setResolution(72);
        // A title is plain text, the figure's accessible name: scripts as spoken ("S sub per"), not "S_per".
        svg->setTitle(QString::fromStdString(mathSpokenText(title)));
        device = std::move(svg);
    } else if (format == "pdf") {
        auto pdf = std::make_unique<QPdfWriter>(&buffer);
        pdf->setResolution(72); // one pixel of the figure is one point of the page
        pdf->setPageSize(QPageSize(QSizeF(width, height), QPageSize::Point));
        pdf->setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf->setTitle(QString::fromStdString(mathSpokenText(title)));
        pdf->setCreator("ViewPipe");
        device = std::move(pdf);
    } else if (format == "png") {
        device = std::make_unique<QImage>(width, height, QImage::Format_RGB32);
    } else {
        throw std::logic_error("no page format \"" + format + "\"");
    }
    QPainter painter;
    if (!painter.begin(device.get()))
        throw std::runtime_error("cannot draw " + file.string());
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF page(0, 0, width, height);
    painter.fillRect(page, qtColor(report::backgroundColor(theme, false)));
    painter.setClipRect(page);
    draw(painter);
    painter.end();
    if (format == "png" && !static_cast<QImage*>(device.get())->save(&buffer, "PNG"))
        throw std::runtime_error("cannot encode " + file.string() + " as PNG");
    QByteArray bytes = buffer.data();
    if (format == "svg") {
        // QSvgGenerator states the size in millimetres at its resolution, and a
        // browser opened a 1280-pixel figure 1707 pixels wide: in pixels.
        const QString size = QString(R"(width="%1px" height="%2px")").arg(width).arg(height);
        bytes = QString::fromUtf8(bytes).replace(QRegularExpression(R"re(width="[0-9.]+mm" height="[0-9.]+mm")re"), size).toUtf8();
    }
    writeFileAtomically(file, bytes.toStdString());
}

} // namespace

report::Figure flatFigure(const VectorFigure& f)
{
    ensureGuiApplication();
    const Layout layout = layoutOf(f);
    report::Figure figure = report::drawFigure(*f.stage, f.view, f.labels);
    figure.layout = layout.picture;
    figure.legend = layout.entries;
    return figure;
}

void writeVectorFigure(const VectorFigure& f, const std::string& format, const std::filesystem::path& file)
{
    ensureGuiApplication();
    const report::Figure figure = flatFigure(f);
    writePage(file, figure.width, figure.height, f.theme, format, f.caption,
              [&](QPainter& painter) { paintFigure(painter, figure, f.theme); });
}

void writeStoryboard(const report::Storyboard& storyboard, report::Theme theme, const std::string& format, const std::filesystem::path& file,
                     const std::vector<std::string>& cellPngs)
{
    ensureGuiApplication();
    const report::StoryboardLayout& layout = storyboard.layout;
    writePage(file, layout.width, layout.height, theme, format, storyboard.title, [&](QPainter& painter) {
        for (std::size_t k = 0; k < layout.cells.size(); ++k) {
            const report::Box2& box = layout.cells[k].picture;
            painter.save();
            painter.translate(box.min.x(), box.min.y());
            painter.setClipRect(QRectF(0, 0, box.max.x() - box.min.x(), box.max.y() - box.min.y()));
            if (k < cellPngs.size()) // the painter's own picture of the cell
                painter.drawImage(QPointF(0, 0), QImage::fromData(QByteArray::fromStdString(cellPngs[k]), "PNG"));
            else
                paintFigure(painter, storyboard.cells[k], theme);
            painter.restore();
        }
        paintFigure(painter, storyboard.overlay, theme);
    });
}

} // namespace viewpipe::gui
