#include "AccuracyPlot.h"

#include "Charts.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlotPoints.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>

namespace viewpipe::gui {
namespace {

// One color (Okabe-Ito, told apart by colorblind people too) and marker per
// precision tier, in ladder order.
const unsigned char kColors[][3] = {{213, 94, 0},    {0, 114, 178}, {0, 158, 115},
                                    {204, 121, 167}, {230, 159, 0}, {86, 180, 233}};
const int kMarkers[] = {vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                        vtkPlotPoints::CROSS,  vtkPlotPoints::PLUS,   vtkPlotPoints::CIRCLE};

// `narrow`: a panel beside the views, where the legend and the labels take
// room from the plot.
void addPanel(vtkChartXY* chart, const BenchResult& result, bool vertices, report::Theme theme, bool narrow)
{
    styleChart(chart, vertices ? "Pushing vertices" : "Building N", theme);
    // Each chart lays out its own axes' titles and labels inside its cell,
    // and the legend beside the plot, where it covers no marker.
    chart->SetLayoutStrategy(vtkChart::FILL_RECT);
    chart->SetShowLegend(vertices);
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    for (std::size_t i = 0; i < result.rows.size(); ++i) {
        const BenchRow& row = result.rows[i];
        const double error = vertices ? row.errors.ndcMaxError : row.errors.maxRelativeError;
        if (!(error > 0))
            continue; // the exact type: 0 has no place on a logarithmic axis (the table gives its time)
        vtkNew<vtkTable> table;
        vtkNew<vtkDoubleArray> x, y;
        x->SetName("time");
        y->SetName((narrow ? row.precision : row.precision + " (" + std::to_string(row.bits) + " bits)").c_str());
        x->InsertNextValue(std::log10(vertices ? row.vertexNs : row.buildNs));
        y->InsertNextValue(std::log10(error));
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
    for (const BenchRow& row : result.rows) {
        const double y = vertices ? row.errors.ndcMaxError : row.errors.maxRelativeError;
        if (!(y > 0))
            continue;
        const double x = vertices ? row.vertexNs : row.buildNs;
        xLow = std::min(xLow, x), xHigh = std::max(xHigh, x), yLow = std::min(yLow, y), yHigh = std::max(yHigh, y);
    }
    styleLogAxis(chart->GetAxis(vtkAxis::BOTTOM), vertices ? "ns per vertex (transform, divide)" : "ns per build",
                 theme, xLow, xHigh, narrow ? 4 : 12);
    // A title longer than the plot is high would run into the other chart.
    styleLogAxis(chart->GetAxis(vtkAxis::LEFT),
                 vertices ? "max error in NDC" : narrow ? "error of N's entries" : "max relative error of N's entries",
                 theme, yLow, yHigh, narrow ? 8 : 12);
}

} // namespace

void drawAccuracyCharts(vtkChartMatrix* charts, const BenchResult& result, report::Theme theme, bool stacked)
{
    // vtkChartMatrix counts rows from the bottom: the vertex panel goes on top when stacked.
    charts->SetSize(stacked ? vtkVector2i(1, 2) : vtkVector2i(2, 1));
    charts->SetBorders(10, 10, 10, 30); // the top one holds the upper chart's title
    charts->SetGutter(vtkVector2f(30, 40));
    addPanel(vtkChartXY::SafeDownCast(charts->GetChart(stacked ? vtkVector2i(0, 1) : vtkVector2i(0, 0))), result, true,
             theme, stacked);
    addPanel(vtkChartXY::SafeDownCast(charts->GetChart(stacked ? vtkVector2i(0, 0) : vtkVector2i(1, 0))), result,
             false, theme, stacked);
}

void writeAccuracyPlot(const BenchResult& result, const std::filesystem::path& file, report::Theme theme)
{
    writeChartPng(
        [&](vtkContextView* view) {
            vtkNew<vtkChartMatrix> charts;
            view->GetScene()->AddItem(charts);
            drawAccuracyCharts(charts, result, theme, false);
        },
        1600, 700, theme, file, "--plot");
}

} // namespace viewpipe::gui
