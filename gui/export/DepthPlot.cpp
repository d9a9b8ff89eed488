#include "DepthPlot.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "Charts.h"

namespace viewpipe::gui {
void drawDepthChart(vtkChartXY* chart, const Pipeline<double>& pipeline, const DepthOptions& options, Theme theme)
{
    chart->ClearPlots();
    const bool foley = pipeline.convention == Convention::Foley;
    styleChart(chart, "Depth resolution against distance", theme);
    chart->SetShowLegend(true);
    // Bottom right: the curves rise from there, and it stays clear of them.
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);

    std::vector<DepthOptions> formats = {{16, false, false}, {24, false, false}, {32, false, false},
                                         {32, true, false}, {32, true, true}};
    formats.erase(std::remove_if(formats.begin(), formats.end(), [&](const DepthOptions& o) { return o == options; }),
                  formats.end());
    formats.push_back(options); // last: drawn over the others
    static const unsigned char colors[][3] = {{150, 150, 150}, {55, 126, 184}, {77, 175, 74}, {152, 78, 163}, {255, 127, 0}};
    double low = 1e300, high = 0, reach = 0;
    for (std::size_t i = 0; i < formats.size(); ++i) {
        const bool scene = i + 1 == formats.size();
        const std::vector<DepthSample> curve = depthResolution(pipeline, formats[i], 65);
        vtkNew<vtkTable> table;
        vtkNew<vtkDoubleArray> x, y;
        x->SetName("distance");
        y->SetName((depthFormatName(formats[i]) + (scene ? " (this scene)" : "")).c_str());
        for (const DepthSample& sample : curve) {
            if (sample.pastFar)
                continue; // a level cut short by the far plane is no measure of resolution
            x->InsertNextValue(sample.distance);
            y->InsertNextValue(std::log10(sample.step));
            low = std::min(low, sample.step), high = std::max(high, sample.step);
            reach = std::max(reach, sample.distance);
        }
        table->AddColumn(x);
        table->AddColumn(y);
        vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
        plot->SetInputData(table, 0, 1);
        if (scene)
            plot->SetColor(228, 26, 28, 255);
        else
            plot->SetColor(colors[i % 5][0], colors[i % 5][1], colors[i % 5][2], 255);
        plot->SetWidth(scene ? 4.0f : 2.0f);
        // Float has a 24-bit significand: unreversed, it matches 24-bit fixed point, whose line shows between the dashes.
        if (formats[i].floating && !scene)
            plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
    }
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    styleAxis(bottom, foley ? "distance from the front plane (F), along the view" : "distance from the near plane, along the view",
              theme);
    bottom->SetBehavior(vtkAxis::FIXED);
    bottom->SetRange(0, reach);
    styleLogAxis(chart->GetAxis(vtkAxis::LEFT), "depth step (world units, log scale)", theme, low, high);
}

void writeDepthPlot(const Pipeline<double>& pipeline, const DepthOptions& options, const std::filesystem::path& file,
                    Theme theme)
{
    writeChartPng(
        [&](vtkContextView* view) {
            vtkNew<vtkChartXY> chart;
            view->GetScene()->AddItem(chart);
            drawDepthChart(chart, pipeline, options, theme);
        },
        1200, 700, theme, file, "--out");
}

} // namespace viewpipe::gui
