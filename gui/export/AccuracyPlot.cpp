#include "AccuracyPlot.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>

namespace viewpipe::gui {
namespace {

// One color and marker per precision tier, in ladder order.
const unsigned char kColors[][3] = {{228, 26, 28}, {55, 126, 184}, {77, 175, 74},
                                    {152, 78, 163}, {255, 127, 0}, {166, 86, 40}};
const int kMarkers[] = {vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                        vtkPlotPoints::CROSS,  vtkPlotPoints::PLUS,   vtkPlotPoints::CIRCLE};

// VTK's charts hold points in single precision, where MPFR's errors (1e-50)
// underflow: the points are plotted as log10 values on linear axes, labelled
// in powers of ten, with a decade of margin and at most a dozen labels.
void styleAxis(vtkAxis* axis, const std::string& title, bool dark, double low, double high)
{
    axis->SetTitle(title);
    const int first = int(std::floor(std::log10(low))) - 1;
    const int last = int(std::ceil(std::log10(high))) + 1;
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(first, last);
    const int step = std::max(1, (last - first + 11) / 12);
    vtkNew<vtkDoubleArray> ticks;
    vtkNew<vtkStringArray> labels;
    for (int e = first; e <= last; e += step) {
        ticks->InsertNextValue(double(e));
        labels->InsertNextValue(e == 0 ? "1" : e == 1 ? "10" : "1e" + std::to_string(e));
    }
    axis->SetCustomTickPositions(ticks, labels);
    axis->GetTitleProperties()->SetFontSize(16);
    axis->GetLabelProperties()->SetFontSize(13);
    const double c = dark ? 0.9 : 0.1;
    axis->GetTitleProperties()->SetColor(c, c, c);
    axis->GetLabelProperties()->SetColor(c, c, c);
    axis->GetPen()->SetColorF(c, c, c);
}

void addPanel(vtkChartXY* chart, const cli::BenchResult& result, bool vertices, bool dark)
{
    chart->SetTitle(vertices ? "Pushing vertices: NDC error against time" : "Building N: entry error against time");
    chart->GetTitleProperties()->SetFontSize(18);
    const double c = dark ? 0.95 : 0.05;
    chart->GetTitleProperties()->SetColor(c, c, c);
    chart->SetShowLegend(vertices);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
    chart->GetLegend()->GetLabelProperties()->SetColor(c, c, c);
    const unsigned char legend = dark ? 40 : 255;
    chart->GetLegend()->GetBrush()->SetColor(legend, legend, legend, 230);
    for (std::size_t i = 0; i < result.rows.size(); ++i) {
        const cli::BenchRow& row = result.rows[i];
        vtkNew<vtkTable> table;
        vtkNew<vtkDoubleArray> x, y;
        x->SetName("time");
        y->SetName((row.precision + " (" + std::to_string(row.bits) + " bits)").c_str());
        const double error = vertices ? row.errors.ndcMaxError : row.errors.maxRelativeError;
        x->InsertNextValue(std::log10(vertices ? row.vertexNs : row.buildNs));
        y->InsertNextValue(std::log10(std::max(error, 1e-300))); // an exact result has no logarithm
        table->AddColumn(x);
        table->AddColumn(y);
        auto* plot = vtkPlotPoints::SafeDownCast(chart->AddPlot(vtkChart::POINTS));
        plot->SetInputData(table, 0, 1);
        plot->SetMarkerStyle(kMarkers[i % 6]);
        plot->SetMarkerSize(14);
        plot->SetColor(kColors[i % 6][0], kColors[i % 6][1], kColors[i % 6][2], 255);
        plot->SetWidth(3);
    }
    double xLow = 1e300, xHigh = 0, yLow = 1e300, yHigh = 0;
    for (const cli::BenchRow& row : result.rows) {
        const double x = vertices ? row.vertexNs : row.buildNs;
        const double y = std::max(vertices ? row.errors.ndcMaxError : row.errors.maxRelativeError, 1e-300);
        xLow = std::min(xLow, x), xHigh = std::max(xHigh, x), yLow = std::min(yLow, y), yHigh = std::max(yHigh, y);
    }
    styleAxis(chart->GetAxis(vtkAxis::BOTTOM), vertices ? "ns per vertex (transform and divide)" : "ns per build",
              dark, xLow, xHigh);
    styleAxis(chart->GetAxis(vtkAxis::LEFT), vertices ? "max error in NDC" : "max relative error of N's entries",
              dark, yLow, yHigh);
}

} // namespace

void drawAccuracyCharts(vtkChartMatrix* charts, const cli::BenchResult& result, Theme theme, bool stacked)
{
    const bool dark = theme == Theme::Dark;
    // vtkChartMatrix counts rows from the bottom: the vertex panel goes on top when stacked.
    charts->SetSize(stacked ? vtkVector2i(1, 2) : vtkVector2i(2, 1));
    charts->SetGutter(vtkVector2f(60, 60));
    addPanel(vtkChartXY::SafeDownCast(charts->GetChart(stacked ? vtkVector2i(0, 1) : vtkVector2i(0, 0))), result, true,
             dark);
    addPanel(vtkChartXY::SafeDownCast(charts->GetChart(stacked ? vtkVector2i(0, 0) : vtkVector2i(1, 0))), result,
             false, dark);
}

void writeAccuracyPlot(const cli::BenchResult& result, const std::filesystem::path& file, Theme theme)
{
    vtkNew<vtkContextView> view;
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(1600, 700);
    const double bg = theme == Theme::Dark ? 0.11 : 1.0;
    view->GetRenderer()->SetBackground(bg, bg, bg);
    vtkNew<vtkChartMatrix> charts;
    view->GetScene()->AddItem(charts);
    drawAccuracyCharts(charts, result, theme, false);
    view->GetRenderWindow()->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->ReadFrontBufferOff();
    const std::filesystem::path temporary = file.string() + ".tmp.png";
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(temporary.c_str());
    writer->Write();
    std::error_code error;
    if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary))
        throw InputError("--plot", "cannot write \"" + file.string() + "\"");
    std::filesystem::rename(temporary, file, error);
    if (error)
        throw InputError("--plot", "cannot replace \"" + file.string() + "\": " + error.message());
}

} // namespace viewpipe::gui
