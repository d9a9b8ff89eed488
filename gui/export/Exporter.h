#pragma once

// Exports the stages of a scene as images for slides, in the formats of one
// table (Exporter.cpp's formatTable: a name, each stage's file, the scene's
// files): one picture per stage drawn by the scene painter, true vector
// SVG/PDF and TikZ figures of the same stage with the same framing (and
// figures.tex showing them all), the scene as one web page (scene.html); and
// always the matrices as LaTeX and JSON; the animated transition as an MP4
// video (H.264, encoded by ffmpeg) on request. Files are written into a
// staging folder and moved into place only when all are complete
// (StagingFolder): a failed or cancelled export leaves nothing half-written.

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "painter/ScenePainter.h"
#include "viewpipe/report/web_page.hpp"

class vtkRenderWindow;

namespace viewpipe::gui {

struct ExportOptions {
    std::filesystem::path out;
    int width = 1280, height = 720;
    int scale = 1;               // pixels per size unit: 2 for high-DPI slides
    int textScale = 100;         // percent of the text's size (exportLabelSize)
    std::vector<int> stages;     // empty: all, 0 (the world) to n
    report::Theme theme = report::Theme::Light;
    bool transparent = false;
    std::set<std::string> formats = {"png"}; // names of exportFormats()
    bool animate = false;
    int fps = 30;
    int digits = 4;              // decimals in matrices.tex
    // Every picture has the same camera direction, size and palette. By default
    // the stages that keep sizes share a framing (their motion shows) and the
    // others are framed anew: the scale stages shrink the scene (the default
    // scene about 35 times at S_per), and one framing for all would leave those
    // pictures nearly empty. Fixed uses one framing that holds every stage,
    // for side-by-side comparison of sizes; per-stage frames each on its own.
    report::FramingMode framing = report::FramingMode::Together;
    // What the pictures leave out (--hide): the elements by the names a lesson step's `hide` takes,
    // "labels", "legend", "caption", "ticks" (the grey axes' ticks and numbers) and "notes" (the effects'
    // note and the notice of labels left out for room).
    std::set<std::string> hidden;
    report::LegendPlace legend = report::LegendPlace::Best;
    double zoom = 1; // the subject this many times larger than framed, about its center
    // Every stage at once (--layout storyboard): one storyboard file per format instead of a file per stage.
    bool storyboard = false;
    // The scenes folder whose presets (presetScenes) the web page offers; empty: none.
    std::filesystem::path presets;
    // Told what a picture could not do as asked (a legend with no room where asked), for the reader to know.
    std::function<void(const std::string&)> notice;
};

// A format `export` writes, as --format names it.
struct ExportFormat {
    std::string name;
    std::string description;
};
std::vector<ExportFormat> exportFormats();
// "png, svg, pdf, tikz, html": for help texts and messages.
std::string exportFormatNames();
// Parses a comma-separated list of format names; throws InputError naming --format.
std::set<std::string> parseFormats(const std::string& list);

// What an export is doing, for progress bars: `done` of `total` steps.
using ExportProgress = std::function<void(int done, int total, const std::string& what)>;

// Throws InputError for bad options and std::runtime_error for failures
// (disk full, encoder missing). Returns the files written. Stops, cleaning
// up, when `cancel` becomes true (then returns nothing).
std::vector<std::filesystem::path> exportStages(const std::shared_ptr<const EvaluatedScene>& scene, const ExportOptions& options,
                                                const ExportProgress& progress, const std::atomic<bool>& cancel);

// The scene as one self-contained web page at `file` (export's html format),
// written atomically; throws as exportStages does.
void exportWebPage(const std::shared_ptr<const EvaluatedScene>& scene, const std::filesystem::path& file, report::Theme theme,
                   const ExportProgress& progress, const std::atomic<bool>& cancel);

// What the web page of a scene draws (webPageViews, report/web_page.hpp):
// every stage at rest as its picture of that size, scale and framing shows
// it, and the app's transitions frame by frame, text measured in the
// pictures' font. Throws InputError for a bad size or
// scale; `step` hears of each stage. `textScale` as OffscreenPainter's; `hidden` and `legend` as export's
// --hide and --legend (the scene already without what `hidden` names), the page's choices at first.
report::WebPageViews recordWebViews(const std::shared_ptr<const EvaluatedScene>& scene, int width, int height, int scale,
                            report::Theme theme, report::FramingMode framing, const std::function<void(const std::string&)>& step,
                            double textScale = 1, const std::set<std::string>& hidden = {},
                            report::LegendPlace legend = report::LegendPlace::Best);

// The CAD layout of seed 001 for a scene's objects, as one PNG: the top view
// above the front view, the (right) side view beside it, and the isometric
// view in the remaining corner. Written atomically; throws InputError for a
// bad size, a scene without objects or an unwritable file.
void exportSheet(const EvaluatedScene& scene, const std::filesystem::path& file, int width, int height, report::Theme theme);

// What a render window shows, as a PNG (with alpha when `transparent`);
// throws std::runtime_error when it cannot be written.
void writeWindowPng(vtkRenderWindow* window, bool transparent, const std::filesystem::path& file);

// Parses "all" or a list such as "0,2,4-5"; throws InputError naming --stages.
std::vector<int> parseStages(const std::string& text, int stageCount);

} // namespace viewpipe::gui
