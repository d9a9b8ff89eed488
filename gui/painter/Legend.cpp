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

vtkSmartPointer<vtkPolyData> legendSymbol(const std::vector<std::pair<std::vector<Vec2<double>>, Rgb>>& polygons)
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
        colors->InsertNextTypedTuple(toBytes(c).data());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetCellData()->SetScalars(colors);
    return data;
}

// Side by side stripes of the given colors, as tall as `halfHeight` above and below the middle.
vtkSmartPointer<vtkPolyData> stripes(const std::vector<Rgb>& colors, double halfHeight)
{
    std::vector<std::pair<std::vector<Vec2<double>>, Rgb>> polygons;
    const double width = kSymbolWidth / double(colors.size());
    for (std::size_t k = 0; k < colors.size(); ++k) {
        const double left = -kSymbolWidth / 2 + double(k) * width;
        polygons.push_back({{{left, -halfHeight}, {left + width, -halfHeight}, {left + width, halfHeight},
                             {left, halfHeight}},
                            colors[k]});
    }
    return legendSymbol(polygons);
}

vtkSmartPointer<vtkPolyData> dot(const Rgb& color)
{
    std::vector<Vec2<double>> circle;
    for (int k = 0; k < 16; ++k)
        circle.emplace_back(0.4 * std::cos(k * M_PI / 8), 0.4 * std::sin(k * M_PI / 8));
    return legendSymbol({{circle, color}});
}

Rgb blend(const Rgb& color, const double* background, double opacity)
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

void fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<LegendEntry>& entries,
                Theme theme, int fontSize, bool canonicalShown, bool top)
{
    std::vector<const LegendEntry*> shown;
    for (const LegendEntry& entry : entries)
        if (entry.element != Element::Canonical || canonicalShown)
            shown.push_back(&entry);
    legend->SetNumberOfEntries(int(shown.size()));
    legend->SetVisibility(!shown.empty());
    const double* back = renderer->GetBackground();
    legend->SetBackgroundColor(back[0], back[1], back[2]);
    const Rgb border = elementColor(Element::Frame, theme), ink = elementColor(Element::Objects, theme);
    legend->GetProperty()->SetColor(border.r, border.g, border.b);
    vtkTextProperty* text = legend->GetEntryTextProperty();
    useFigureFont(text, false);
    text->SetColor(ink.r, ink.g, ink.b);
    text->SetFontSize(std::max(8, fontSize * 2 / 3));
    text->Modified(); // new entries take the font and color from it at the next build only if it changed

    using Swatch = LegendEntry::Swatch;
    vtkRenderWindow* window = renderer->GetRenderWindow();
    const int dpi = window ? window->GetDPI() : 72;
    int textWidth = 0, textHeight = 0;
    for (std::size_t k = 0; k < shown.size(); ++k) {
        const LegendEntry& entry = *shown[k];
        const Rgb c = blend(styledColor(entry.element, entry.swatch == Swatch::Face, theme), back, entry.opacity);
        vtkSmartPointer<vtkPolyData> symbol;
        if (entry.swatch == Swatch::Dot)
            symbol = dot(c);
        else if (entry.swatch == Swatch::Bands)
            symbol = stripes({kBandRamp.begin(), kBandRamp.end()}, 0.4);
        else if (entry.swatch == Swatch::Pixels)
            symbol = stripes({kRasterPalette.begin(), kRasterPalette.end()}, 0.4);
        else
            symbol = stripes({c}, entry.swatch == Swatch::Line ? 0.12 : 0.4);
        legend->SetEntrySymbol(int(k), symbol);
        legend->SetEntryString(int(k), entry.text.c_str());
        const Vec2<double> size = textSize(text, entry.text, dpi);
        textWidth = std::max(textWidth, int(size.x()));
        textHeight = std::max(textHeight, int(size.y()));
    }
    // VTK fits the text to the box: a box made to the text's size keeps the
    // font size asked for. Symbols take kSymbolWidth times the text's height.
    const int padding = std::max(3, fontSize / 4), margin = std::max(4, fontSize / 2);
    legend->SetPadding(padding);
    const double width = textWidth + kSymbolWidth * textHeight + 2 * padding + 2;
    const double height = double(shown.size()) * std::ceil(1.3 * textHeight) + 2 * padding;
    legend->GetPosition2Coordinate()->SetValue(width, height);
    legend->GetPositionCoordinate()->SetValue(-width - margin, top ? -height - 1.6 * fontSize : margin);
}

} // namespace viewpipe::gui
