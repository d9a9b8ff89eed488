#pragma once

// A view's legend: what each color means, for the elements the scene shows.

#include <vtkSmartPointer.h>

#include <vector>

#include "viewpipe/report/figure.hpp"
#include "viewpipe/report/style.hpp"

class vtkLegendBoxActor;
class vtkRenderer;
class vtkTextActor;

namespace viewpipe::gui {

// A legend box in the top-right corner of a view (below its caption's line)
// or the bottom-right corner, sized in pixels by fillLegend.
vtkSmartPointer<vtkLegendBoxActor> newLegend(bool top);

// Fills a legend with its entries beside pictures' labels of `labelSize`
// pixels (legendLayout), sized to its text.
void fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<const LegendEntry*>& entries,
                report::Theme theme, double labelSize, bool top);

// Text measured as a view draws it (the figure font at the view's DPI).
report::FontMeasure viewFontMeasure(vtkRenderer* renderer);

// A caption actor's lines and size as the picture's layout has them.
void setCaptionText(vtkTextActor* caption, const std::vector<std::string>& lines, double pixels);

// A view's legend where the layout puts it (filled anew when the layout's
// size differs from `filledSize`, which it then records), or hidden where
// the layout left it out.
void placeLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const report::PictureLayout& layout,
                 const std::vector<const LegendEntry*>& entries, report::Theme theme, double& filledSize);

} // namespace viewpipe::gui
