#pragma once

// A stage's flat figure as true vector graphics through Qt's QSvgGenerator
// and QPdfWriter: lines as paths, faces as filled polygons back to front,
// labels, caption and legend as text (the PDF embeds its font). The same
// palette, framing and labels as the PNG of the stage. A storyboard's cells
// and overlay the same way, or as one PNG of the painter's cell pictures.

#include <filesystem>
#include <string>
#include <vector>

#include "viewpipe/report/figure.hpp"
#include "viewpipe/report/storyboard.hpp"
#include "viewpipe/report/style.hpp"

class QPainter;

namespace viewpipe::gui {

struct VectorFigure {
    const report::StageShown* stage;
    report::FigureView view;
    std::string caption;
    report::SceneLabels labels; // where the PNG's painter placed them: every format places them alike
    report::Theme theme = report::Theme::Light;
};

// The figure, with its caption, legend and note laid out as the PNG has them
// (their boxes kept clear of labels).
report::Figure flatFigure(const VectorFigure& figure);

// A figure's shapes, labels and text in its own pixels, over what `painter` has drawn already
// (the app's storyboard paints its overlay so, as the files do).
void paintFigure(QPainter& painter, const report::Figure& figure, report::Theme theme);

// Writes `file` atomically as SVG or PDF (by `format`); throws std::runtime_error when it cannot.
void writeVectorFigure(const VectorFigure& figure, const std::string& format, const std::filesystem::path& file);

// Writes a storyboard atomically as SVG, PDF or PNG (by `format`): each cell's
// figure in its box, or for a PNG the painter's picture of it (`cellPngs`,
// PNG bytes in the cells' order), then the overlay.
void writeStoryboard(const report::Storyboard& storyboard, report::Theme theme, const std::string& format,
                     const std::filesystem::path& file, const std::vector<std::string>& cellPngs = {});

} // namespace viewpipe::gui
