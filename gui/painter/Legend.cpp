#include "Legend.h"
#include "VtkGeometry.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkLegendBoxActor.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace viewpipe::gui {
namespace {

// A legend's symbol: polygons in their colors within a box kSymbolWidth wide
// and 1 high, whose corners are points of every symbol so that the legend
// scales all alike.
constexpr double kSymbolWidth = 3;

vtkSmartPointer<vtkPolyData> legendSymbol(const std::vector<std::pair<std::vector<Vec2<double>>, report::Rgb>>& polygons)
{
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->InsertNextPoint(-kSymbolWidth / 2, -0.5, 0);
    points->InsertNextPoint(kSymbolWidth / 2, 0.5, 0);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetNumberOfComponents(3);
    for (const auto& [corners, c] : polygons) {
        std::vector<vtkIdType> ids;
        for (const Vec2<double>& q : corners)
            ids.push_back(points->InsertNextPoint(q.x(), q.y(), 0));
        cells->InsertNextCell(vtkIdType(ids.size()), ids.data());
        colors->InsertNextTypedTuple(report::toBytes(c).data());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetCellData()->SetScalars(colors);
    return data;
}

// Side by side stripes of the given colors, as tall as `halfHeight` above and below the middle.
vtkSmartPointer<vtkPolyData> stripes(const std::vector<report::Rgb>& colors, double halfHeight)
{
    std::vector<std::pair<std::vector<Vec2<double>>, report::Rgb>> polygons;
    const double width = kSymbolWidth / double(colors.size());
    for (std::size_t k = 0; k < colors.size(); ++k) {
        const double left = -kSymbolWidth / 2 + double(k) * width;
        polygons.push_back({{{left, -halfHeight}, {left + width, -halfHeight}, {left + width, halfHeight},
                             {left, halfHeight}},
                            colors[k]});
    }
    return legendSymbol(polygons);
}

vtkSmartPointer<vtkPolyData> dot(const report::Rgb& color)
{
    std::vector<Vec2<double>> circle;
    for (int k = 0; k < 16; ++k)
        circle.emplace_back(0.4 * std::cos(k * M_PI / 8), 0.4 * std::sin(k * M_PI / 8));
    return legendSymbol({{circle, color}});
}

report::Rgb blend(const report::Rgb& color, const double* background, double opacity)
{
    return {opacity * color.r + (1 - opacity) * background[0], opacity * color.g + (1 - opacity) * background[1],
            opacity * color.b + (1 - opacity) * background[2]};
}

} // namespace

vtkSmartPointer<vtkLegendBoxActor> newLegend(bool top)
{
    auto legend = vtkSmartPointer<vtkLegendBoxActor>::New();
    legend->UseBackgroundOn();
    legend->SetBackgroundOpacity(0.85);
    legend->SetPickable(false);
    auto corner = vtkSmartPointer<vtkCoordinate>::New();
    corner->SetCoordinateSystemToNormalizedViewport();
    corner->SetValue(1, top ? 0.96 : 0);
    // Position: pixels from the corner; Position2: the size in pixels.
    legend->GetPositionCoordinate()->SetCoordinateSystemToViewport();
    legend->GetPositionCoordinate()->SetReferenceCoordinate(corner);
    legend->GetPosition2Coordinate()->SetCoordinateSystemToViewport();
    return legend;
}

void fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<const LegendEntry*>& shown,
                report::Theme theme, double labelSize, bool top)
{
    vtkRenderWindow* window = renderer->GetRenderWindow();
    const int dpi = window ? window->GetDPI() : 72;
    const report::LegendLayout rows = report::legendLayout(shown, labelSize, figureFontMeasure(dpi));
    legend->SetNumberOfEntries(int(shown.size()));
    legend->SetVisibility(!shown.empty());
    const double* back = renderer->GetBackground();
    legend->SetBackgroundColor(back[0], back[1], back[2]);
    const report::Rgb border = report::elementColor(Element::Frame, theme), ink = report::elementColor(Element::Objects, theme);
    legend->GetProperty()->SetColor(border.r, border.g, border.b);
    vtkTextProperty* text = legend->GetEntryTextProperty();
    useFigureFont(text, false);
    text->SetColor(ink.r, ink.g, ink.b);
    text->SetFontSize(int(std::lround(rows.textSize)));
    text->Modified(); // new entries take the font and color from it at the next build only if it changed

    using Swatch = LegendEntry::Swatch;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        const LegendEntry& entry = *shown[k];
        const report::Rgb c = blend(report::styledColor(entry.element, entry.swatch == Swatch::Face, theme), back, entry.opacity);
        vtkSmartPointer<vtkPolyData> symbol;
        if (entry.swatch == Swatch::Dot)
            symbol = dot(c);
        else if (entry.swatch == Swatch::Bands)
            symbol = stripes({report::kBandRamp.begin(), report::kBandRamp.end()}, 0.4);
        else if (entry.swatch == Swatch::Pixels)
            symbol = stripes({report::kRasterPalette.begin(), report::kRasterPalette.end()}, 0.4);
        else
            symbol = stripes({c}, entry.swatch == Swatch::Line ? 0.12 : 0.4);
        legend->SetEntrySymbol(int(k), symbol);
        legend->SetEntryString(int(k), entry.text.c_str());
    }
    // VTK fits the text to the box: a box made to the text's size keeps the
    // font size asked for. Symbols take kSymbolWidth times the text's height.
    legend->SetPadding(int(rows.padding));
    legend->GetPosition2Coordinate()->SetValue(rows.size.x(), rows.size.y());
    const double margin = std::max(4.0, labelSize / 2);
    legend->GetPositionCoordinate()->SetValue(-rows.size.x() - margin, top ? -rows.size.y() - 1.6 * labelSize : margin);
}

report::FontMeasure viewFontMeasure(vtkRenderer* renderer)
{
    vtkRenderWindow* window = renderer->GetRenderWindow();
    const int dpi = window ? window->GetDPI() : 72;
    return figureFontMeasure(dpi);
}

void setCaptionText(vtkTextActor* caption, const std::vector<std::string>& lines, double pixels)
{
    std::string joined;
    for (const std::string& line : lines)
        joined += (joined.empty() ? "" : "\n") + line;
    if (joined != (caption->GetInput() ? caption->GetInput() : ""))
        caption->SetInput(joined.c_str());
    if (caption->GetTextProperty()->GetFontSize() != int(std::lround(pixels)))
        caption->GetTextProperty()->SetFontSize(int(std::lround(pixels)));
}

void placeLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const report::PictureLayout& layout,
                 const std::vector<const LegendEntry*>& entries, report::Theme theme, double& filledSize)
{
    if (layout.legend.isEmpty()) {
        legend->SetVisibility(false);
        return;
    }
    if (filledSize != layout.captionSize) {
        fillLegend(legend, renderer, entries, theme, layout.captionSize, true);
        filledSize = layout.captionSize;
    }
    legend->SetVisibility(true);
    // The legend's lower left corner, from the view's top right corner less 4 % (y up).
    const int* size = renderer->GetSize();
    const Vec2<double> corner(layout.legend.min.x() - size[0], 0.04 * size[1] - layout.legend.max.y());
    if ((corner - Vec2<double>(legend->GetPositionCoordinate()->GetValue())).norm() > 0.5)
        legend->GetPositionCoordinate()->SetValue(corner.x(), corner.y());
}

} // namespace viewpipe::gui
