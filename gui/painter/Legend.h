#pragma once

// A view's legend: what each color means, for the elements the scene shows.

#include <vtkSmartPointer.h>

#include <vector>

#include "viewpipe/report/style.hpp"

class vtkLegendBoxActor;
class vtkRenderer;

namespace viewpipe::gui {

// A legend box in the top-right corner of a view (below its caption's line)
// or the bottom-right corner, sized in pixels by fillLegend.
vtkSmartPointer<vtkLegendBoxActor> newLegend(bool top);

// Fills a legend with its entries at a font size, sized to its text (the
// canonical volume's entry only while it shows).
void fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<LegendEntry>& entries,
                Theme theme, int fontSize, bool canonicalShown, bool top);

} // namespace viewpipe::gui
