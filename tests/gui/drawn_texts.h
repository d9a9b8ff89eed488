#pragma once

// The texts a VTK view draws, as a person sees them: every visible text
// actor's box and size, and the legend's box and entry size.

#include <vtkActor2DCollection.h>
#include <vtkCell.h>
#include <vtkCoordinate.h>
#include <vtkLegendBoxActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "plain_math.h"

struct DrawnText {
    std::string text;
    std::array<double, 4> box; // x0, x1, y0, y1 in viewport pixels (y up)
    int fontSize;              // pixels
    bool bold;
};

struct DrawnLeader {
    std::array<double, 2> from, to; // viewport pixels (y up): at the anchor, at the label
};

struct DrawnTexts {
    std::vector<DrawnText> texts;
    std::optional<std::array<double, 4>> legend;
    int legendFontSize = 0;
    std::vector<DrawnLeader> leaders; // the 2D lines drawn over the view: labels' leaders
};

inline DrawnTexts drawnTexts(vtkRenderer* view)
{
    DrawnTexts drawn;
    vtkActor2DCollection* actors = view->GetActors2D();
    actors->InitTraversal();
    while (vtkActor2D* actor = actors->GetNextActor2D()) {
        if (!actor->GetVisibility())
            continue;
        if (auto* text = vtkTextActor::SafeDownCast(actor); text && text->GetInput() && *text->GetInput()) {
            // The bounding box is relative to the text's position: add it (viewport pixels).
            std::array<double, 4> box;
            text->GetBoundingBox(view, box.data());
            const double* at = text->GetPositionCoordinate()->GetComputedDoubleViewportValue(view);
            box = {box[0] + at[0], box[1] + at[0], box[2] + at[1], box[3] + at[1]};
            drawn.texts.push_back({text->GetInput(), box, text->GetTextProperty()->GetFontSize(),
                                   text->GetTextProperty()->GetBold() != 0});
        } else if (auto* mapper = vtkPolyDataMapper2D::SafeDownCast(actor->GetMapper())) {
            vtkPolyData* lines = mapper->GetInput();
            if (!lines || lines->GetNumberOfLines() == 0 || lines->GetNumberOfPolys() != 0)
                continue; // the markers are filled shapes
            for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c) {
                vtkCell* cell = lines->GetCell(c);
                if (cell->GetNumberOfPoints() != 2)
                    continue;
                double a[3], b[3];
                lines->GetPoint(cell->GetPointId(0), a);
                lines->GetPoint(cell->GetPointId(1), b);
                drawn.leaders.push_back({{a[0], a[1]}, {b[0], b[1]}});
            }
        } else if (auto* legend = vtkLegendBoxActor::SafeDownCast(actor)) {
            // Position2 is relative to Position: computed, it is the upper right corner.
            const int* low = legend->GetPositionCoordinate()->GetComputedViewportValue(view);
            const double x0 = low[0], y0 = low[1];
            const int* high = legend->GetPosition2Coordinate()->GetComputedViewportValue(view);
            drawn.legend = {x0, double(high[0]), y0, double(high[1])};
            drawn.legendFontSize = legend->GetEntryTextProperty()->GetFontSize();
        }
    }
    return drawn;
}

inline bool overlap(const std::array<double, 4>& a, const std::array<double, 4>& b)
{
    return a[0] < b[1] && b[0] < a[1] && a[2] < b[3] && b[2] < a[3];
}

// The first thing a reader would trip over among a view's texts: one leaving
// the view, one on another, one on the legend; empty when there is none.
inline std::string textTrouble(vtkRenderer* view)
{
    const DrawnTexts drawn = drawnTexts(view);
    const int* size = view->GetSize();
    auto box = [](const std::array<double, 4>& b) {
        char text[96];
        std::snprintf(text, sizeof text, " (%g..%g, %g..%g)", b[0], b[1], b[2], b[3]);
        return std::string(text);
    };
    for (std::size_t i = 0; i < drawn.texts.size(); ++i) {
        const DrawnText& t = drawn.texts[i];
        if (t.box[0] < 0 || t.box[1] > size[0] || t.box[2] < 0 || t.box[3] > size[1])
            return "\"" + t.text + "\" leaves the view" + box(t.box);
        if (plainTextMath(t.text))
            return "\"" + t.text + "\" sets math as plain text";
        if (drawn.legend && overlap(t.box, *drawn.legend))
            return "\"" + t.text + "\" covers the legend" + box(t.box) + box(*drawn.legend);
        for (std::size_t j = i + 1; j < drawn.texts.size(); ++j)
            if (overlap(t.box, drawn.texts[j].box))
                return "\"" + t.text + "\" overlaps \"" + drawn.texts[j].text + "\"";
    }
    if (drawn.legend && ((*drawn.legend)[0] < 0 || (*drawn.legend)[1] > size[0] || (*drawn.legend)[2] < 0 || (*drawn.legend)[3] > size[1]))
        return "the legend leaves the view" + box(*drawn.legend);
    return {};
}
