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
#include <stdexcept>

#include "Exporter.h"

namespace viewpipe::gui {

ChartText chartTextFor(int width, double textScale)
{
    const double label = exportLabelSize(width, textScale), small = smallTextSize(label);
    return {1.1 * label, label, small, small};
}

void styleAxis(vtkAxis* axis, const std::string& title, Theme theme, const ChartText& text)
{
    axis->SetTitle(title);
    axis->GetTitleProperties()->SetFontSize(int(std::lround(text.axisTitle)));
    axis->GetLabelProperties()->SetFontSize(int(std::lround(text.labels)));
    const double c = theme == Theme::Dark ? 0.9 : 0.1;
    axis->GetTitleProperties()->SetColor(c, c, c);
    axis->GetLabelProperties()->SetColor(c, c, c);
    axis->GetPen()->SetColorF(c, c, c);
}

void styleLogAxis(vtkAxis* axis, const std::string& title, Theme theme, double low, double high, int maxLabels,
                  const ChartText& text)
{
    styleAxis(axis, title, theme, text);
    const int first = int(std::floor(std::log10(low))) - 1;
    const int last = int(std::ceil(std::log10(high))) + 1;
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(first, last);
    const int step = std::max(1, (last - first + maxLabels - 1) / maxLabels);
    vtkNew<vtkDoubleArray> ticks;
    vtkNew<vtkStringArray> labels;
    for (int e = first; e <= last; e += step) {
        ticks->InsertNextValue(double(e));
        labels->InsertNextValue(e == 0 ? "1" : e == 1 ? "10" : "1e" + std::to_string(e));
    }
    axis->SetCustomTickPositions(ticks, labels);
}

void styleChart(vtkChart* chart, const std::string& title, Theme theme, const ChartText& text)
{
    const bool dark = theme == Theme::Dark;
    chart->SetTitle(title);
    chart->GetTitleProperties()->SetFontSize(int(std::lround(text.title)));
    const double c = dark ? 0.95 : 0.05;
    chart->GetTitleProperties()->SetColor(c, c, c);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(int(std::lround(text.legend)));
    chart->GetLegend()->GetLabelProperties()->SetColor(c, c, c);
    const unsigned char legend = dark ? 40 : 255;
    chart->GetLegend()->GetBrush()->SetColor(legend, legend, legend, 230);
}

void writeChartPng(const std::function<void(vtkContextView*)>& draw, int width, int height, Theme theme,
                   const std::filesystem::path& file, const std::string& field)
{
    vtkNew<vtkContextView> view;
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(width, height);
    const double bg = theme == Theme::Dark ? 0.11 : 1.0;
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
