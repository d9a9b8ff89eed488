#include "MatrixPanel.h"
#include "MathText.h"

#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include "viewpipe/exact.hpp"
#include "viewpipe/report/stage_symbols.hpp"
#include "viewpipe/report/trace_table.hpp"

namespace viewpipe::gui {
namespace {

// A space of the panel's font before a column's text: the cells' pixel padding
// stays 3 px when the text grows, and "0" "−20" at 200 % read as "0−20".
const QString kColumnGap = "&nbsp;";

constexpr const char* kChanged = "#f2c14e";  // the entries a stage changed in the product
constexpr const char* kLessonMark = "#8ecae6"; // the entries a lesson step points at

// A 4 x 4 table of cells given as HTML (numbers, or math set by mathHtml).
QString table(const QString& caption, const std::array<QString, 16>& cells, const std::array<bool, 16>& highlight = {},
              const char* color = kChanged)
{
    QString html = "<table cellspacing='0' cellpadding='3' style='margin-bottom:8px'><tr><td colspan='4'><b>" +
                   caption + "</b></td></tr>";
    for (int r = 0; r < 4; ++r) {
        html += "<tr>";
        for (int c = 0; c < 4; ++c) {
            const bool h = highlight[std::size_t(r * 4 + c)];
            html += QString("<td align='right' style='white-space:nowrap; %1'>%2%3</td>") // a number never broken
                        .arg(h ? QString("background-color:%1; color:black; font-weight:bold;").arg(color) : QString())
                        .arg(kColumnGap, cells[std::size_t(r * 4 + c)]);
        }
        html += "</tr>";
    }
    return html + "</table>";
}

std::array<QString, 16> numbers(const Mat4<double>& m, const Mat4<Exact>* exact = nullptr)
{
    std::array<QString, 16> cells;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            cells[std::size_t(r * 4 + c)] = mathHtml(report::tableCell(m(r, c), exact ? &(*exact)(r, c) : nullptr));
    return cells;
}

} // namespace

QString matrixTable(const QString& caption, const Mat4<double>& m)
{
    return table(caption, numbers(m));
}

MatrixPanel::MatrixPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    title_ = new QLabel;
    title_->setWordWrap(true);
    title_->setObjectName("stageTitle");
    title_->setToolTip(tr("The stage shown: its symbol and what its matrix does"));
    matrices_ = new QLabel;
    matrices_->setTextFormat(Qt::RichText);
    matrices_->setWordWrap(true); // the notes under a symbolic matrix wrap; the tables keep their width
    matrices_->setObjectName("matrices");
    matrices_->setToolTip(tr("The stage's matrix, symbolic and in numbers, and the product of all stages so far "
                             "(the cumulative matrix), the entries this stage changed highlighted"));
    trace_ = new QLabel(tr("Click a vertex of an object to trace it through the stages."));
    trace_->setTextFormat(Qt::RichText);
    trace_->setWordWrap(true);
    trace_->setObjectName("trace");
    trace_->setToolTip(tr("A vertex picked in the world view, in homogeneous coordinates after every stage"));
    layout->addWidget(title_);
    layout->addWidget(matrices_);
    layout->addWidget(trace_);
    layout->addStretch();
}

void MatrixPanel::showStage(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact, int stage,
                            const std::vector<std::array<int, 2>>& highlighted)
{
    const std::vector<Mat4<double>> cumulative = cumulativeProducts(pipeline.stages);
    const std::vector<Mat4<Exact>> exactCumulative = exact ? cumulativeProducts(exact->stages) : std::vector<Mat4<Exact>>{};
    const auto exactStage = [&](std::size_t k) { return exact ? &exact->stages[k].matrix : nullptr; };
    const auto exactProduct = [&](std::size_t k) { return exact ? &exactCumulative[k] : nullptr; };
    if (stage <= 0) {
        title_->setText(tr("<b>World</b>: the scene in world coordinates (WRC), before any transformation."));
        matrices_->setText(table(tr("Cumulative"), numbers(Mat4<double>::Identity())));
        return;
    }
    const Stage<double>& s = pipeline.stages[std::size_t(stage - 1)];
    title_->setText(QString("<b>%1. %2</b> — %3").arg(stage).arg(mathHtml("$" + stageSymbolMath(s.kind) + "$"),
                                                                   mathHtml(s.explanation)));
    const Mat4<double>& now = cumulative[std::size_t(stage - 1)];
    const Mat4<double> before = stage >= 2 ? cumulative[std::size_t(stage - 2)] : Mat4<double>::Identity();
    std::array<bool, 16> changed{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            changed[std::size_t(r * 4 + c)] =
                std::abs(now(r, c) - before(r, c)) > 1e-12 * std::max(1.0, std::abs(before(r, c)));
    const QString symbol = mathHtml("$" + stageSymbolMath(s.kind) + "$");
    QString html;
    const report::SymbolicForm symbolic = report::symbolicMatrix(s.kind);
    if (!symbolic.cells[0].empty()) {
        std::array<QString, 16> cells;
        for (std::size_t k = 0; k < cells.size(); ++k)
            cells[k] = mathHtml("$" + symbolic.cells[k] + "$");
        html += table(symbol + tr(" (symbolic)"), cells);
        for (const std::string& note : symbolic.notes)
            html += "<div style='margin-bottom:4px'>" + mathHtml(note) + "</div>";
    }
    if (s.divides()) // no matrix does this: each point is divided by its own w
        html += "<p><b>" + symbol + "</b>: " + QString(kDivideMapping).toHtmlEscaped() + "<br><i>" +
                tr("Not a matrix: each point is divided by its own w. The cumulative matrix is unchanged; the "
                   "points it gives are divided.") + "</i></p>";
    else {
        std::array<bool, 16> marked{};
        for (const auto& [row, column] : highlighted)
            marked[std::size_t((row - 1) * 4 + column - 1)] = true;
        html += table(symbol, numbers(s.matrix, exactStage(std::size_t(stage - 1))), marked, kLessonMark);
    }
    html += table(tr("Cumulative (changed entries highlighted)"), numbers(now, exactProduct(std::size_t(stage - 1))),
                  changed);
    matrices_->setText(html);
}

void MatrixPanel::showTrace(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact,
                            const std::optional<Vec3<double>>& point, int stage, int lastRow)
{
    if (!point) {
        trace_->setText(tr("Click a vertex of an object to trace it through the stages."));
        return;
    }
    const report::TraceTable t = report::traceTable(pipeline, exact, *point, lastRow);
    QString html = tr("<b>Traced vertex</b> (x, y, z, w):<table cellspacing='0' cellpadding='2'>");
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        html += QString("<tr%1><td>%2</td>").arg(int(k) == stage ? " style='font-weight:bold'" : "", mathHtml(t.rows[k].stage));
        for (const std::string& cell : t.rows[k].cells)
            html += "<td align='right'>" + kColumnGap + mathHtml(cell) + "</td>";
        html += "</tr>";
    }
    trace_->setText(html + "</table>" + mathHtml(t.verdict));
}

void MatrixPanel::showWaiting(const QString& why)
{
    title_->setText(why);
    matrices_->clear();
    trace_->clear();
}

QString MatrixPanel::traceText() const
{
    return trace_->text();
}

QString MatrixPanel::matricesText() const
{
    return matrices_->text();
}

QString MatrixPanel::stageText() const
{
    return title_->text();
}

} // namespace viewpipe::gui
