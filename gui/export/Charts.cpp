#include "Charts.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChart.h>
#include <vtkChartLegend.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "Exporter.h"
#include "painter/VtkGeometry.h"

namespace viewpipe::gui {

namespace {

// 10 to the power e as a reader sets it: "10⁻¹⁵", not "1e-15".
std::string powerOfTen(int e)
{
    if (e == 0)
        return "1";
    static const char* const superscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    std::string out = e < 0 ? "10⁻" : "10";
    if (e == 1)
        return out;
    for (const char digit : std::to_string(std::abs(e)))
        out += superscripts[digit - '0'];
    return out;
}

} // namespace

ChartText chartTextFor(int width, double textScale)
{
    const double label = report::exportLabelSize(width, textScale), small = report::smallTextSize(label);
    return {1.1 * label, label, small, small};
}

ChartText fitChartText(int width, int height, double textScale, const ChartWords& words)
{
    // The text at a scale, with the room it leaves the plot, and whether everything fits.
    const auto measured = [&](double scale) {
        ChartText text = chartTextFor(width, scale);
        const auto wide = [](const std::string& line, double size, bool bold) { return figureTextSize(line, size, bold).x(); };
        double legendWidth = 0;
        for (const std::string& entry : words.legend)
            legendWidth = std::max(legendWidth, wide(entry, text.legend, false) + 3 * text.legend); // and its swatch
        const double legendHeight = words.legend.empty() ? 0 : 1.4 * text.legend * double(words.legend.size()) + text.legend;
        // Top to bottom: the title, the plot, the bottom axis' numbers and title, the legend.
        text.plotHeight = height - 1.6 * text.title - 1.6 * text.labels - 1.5 * text.axisTitle - legendHeight;
        const double leftTitle = figureTextSize(words.leftTitle, text.axisTitle, true).y(); // turned: its height is its width
        text.plotWidth = width - 1.2 * leftTitle - wide(words.widestLeftLabel, text.labels, false) - 2 * text.labels;
        const bool fits = wide(words.title, text.title, false) <= 0.96 * width &&
                          wide(words.bottomTitle, text.axisTitle, true) <= 0.96 * text.plotWidth &&
                          wide(words.leftTitle, text.axisTitle, true) <= 0.96 * text.plotHeight &&
                          legendWidth <= 0.96 * width && text.plotHeight >= height / 3.0;
        return std::pair{text, fits};
    };
    // In whole percents (5 at a time) from the one asked down to 100 % (or the one asked, if smaller).
    const int asked = int(std::lround(textScale * 100)), floor = std::min(100, asked);
    for (int percent = asked; percent > floor; percent -= 5)
        if (const auto [text, fits] = measured(percent / 100.0); fits)
            return text;
    return measured(floor / 100.0).first;
}

void styleLinearAxis(vtkAxis* axis, const std::string& title, report::Theme theme, double low, double high, double length,
                     const ChartText& text)
{
    styleAxis(axis, title, theme, text);
    if (!(std::isfinite(low) && std::isfinite(high) && high > low && length > 0))
        return; // nothing to divide: VTK's own numbers
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(low, high);
    const auto label = [](double value, int decimals) {
        std::ostringstream out;
        out << std::fixed << std::setprecision(decimals) << value;
        return out.str();
    };
    // The smallest round step whose labels, each as wide as the widest, leave a label's height between them.
    const double span = high - low;
    for (int decade = int(std::floor(std::log10(span))) - 2;; ++decade)
        for (const double factor : {1.0, 2.0, 5.0}) {
            const double step = factor * std::pow(10.0, decade);
            const int decimals = std::clamp(-decade, 0, 17);
            const double widest = std::max(figureTextSize(label(low, decimals), text.labels, false).x(),
                                           figureTextSize(label(high, decimals), text.labels, false).x());
            if (span / step * (widest + text.labels) > length && span / step > 1)
                continue;
            vtkNew<vtkDoubleArray> ticks;
            vtkNew<vtkStringArray> labels;
            const double first = std::ceil(low / step);
            for (int k = 0; (first + k) * step <= high + 1e-9 * step; ++k) {
                const double value = (first + k) * step;
                ticks->InsertNextValue(value);
                labels->InsertNextValue(label(std::abs(value) < 1e-9 * step ? 0.0 : value, decimals));
            }
            axis->SetCustomTickPositions(ticks, labels);
            return;
        }
}

void styleAxis(vtkAxis* axis, const std::string& title, report::Theme theme, const ChartText& text)
{
    axis->SetTitle(title);
    useFigureFont(axis->GetTitleProperties(), true);
    useFigureFont(axis->GetLabelProperties(), false); // a font with superscripts (powerOfTen)
    axis->GetTitleProperties()->SetFontSize(int(std::lround(text.axisTitle)));
    axis->GetLabelProperties()->SetFontSize(int(std::lround(text.labels)));
    const double c = theme == report::Theme::Dark ? 0.9 : 0.1;
    axis->GetTitleProperties()->SetColor(c, c, c);
    axis->GetLabelProperties()->SetColor(c, c, c);
    axis->GetPen()->SetColorF(c, c, c);
}

void styleLogAxis(vtkAxis* axis, const std::string& title, report::Theme theme, double low, double high, int maxLabels,
                  const ChartText& text)
{
    styleAxis(axis, title, theme, text);
    const double room = std::max(1.0, (std::log10(high) - std::log10(low)) / 8);
    const int first = int(std::floor(std::log10(low) - room));
    const int last = int(std::ceil(std::log10(high) + room));
    // Numbers at multiples of the step (10⁻¹⁰, 10⁻⁵, 1), at most maxLabels of them.
    int step = std::max(1, (last - first + maxLabels - 1) / maxLabels);
    auto startFor = [first](int s) { return int(std::floor(double(first) / s)) * s; };
    while ((last - startFor(step)) / step + 1 > std::max(1, maxLabels))
        ++step;
    const int start = startFor(step);
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(start - 0.5 * step, last); // the lowest number above the corner, where the other axis' first is
    vtkNew<vtkDoubleArray> ticks;
    vtkNew<vtkStringArray> labels;
    for (int e = start; e <= last; e += step) {
        ticks->InsertNextValue(double(e));
        labels->InsertNextValue(powerOfTen(e));
    }
    axis->SetCustomTickPositions(ticks, labels);
}

void styleChart(vtkChart* chart, const std::string& title, report::Theme theme, const ChartText& text)
{
    const bool dark = theme == report::Theme::Dark;
    chart->SetTitle(title);
    useFigureFont(chart->GetTitleProperties(), false);
    useFigureFont(chart->GetLegend()->GetLabelProperties(), false);
    chart->GetTitleProperties()->SetFontSize(int(std::lround(text.title)));
    const double c = dark ? 0.95 : 0.05;
    chart->GetTitleProperties()->SetColor(c, c, c);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(int(std::lround(text.legend)));
    chart->GetLegend()->GetLabelProperties()->SetColor(c, c, c);
    const unsigned char legend = dark ? 40 : 255;
    chart->GetLegend()->GetBrush()->SetColor(legend, legend, legend, 230);
}

void writeChartPng(const std::function<void(vtkContextView*)>& draw, int width, int height, report::Theme theme,
                   const std::filesystem::path& file, const std::string& field)
{
    vtkNew<vtkContextView> view;
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(width, height);
    const double bg = theme == report::Theme::Dark ? 0.11 : 1.0;
    view->GetRenderer()->SetBackground(bg, bg, bg);
    draw(view);
    view->GetRenderWindow()->Render();
    try {
        writeWindowPng(view->GetRenderWindow(), false, file);
    } catch (const std::runtime_error& e) {
        throw InputError(field, "cannot write \"" + file.string() + "\": " + e.what());
    }
}

} // namespace viewpipe::gui
