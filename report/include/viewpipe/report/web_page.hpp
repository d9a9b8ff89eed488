#pragma once

// The scene as one self-contained web page: the evaluated scene's primitives,
// labels and markers drawn by three.js through each stage's matrix, the
// stepper with the app's transitions (world_view.hpp, as the painter moves),
// the matrices typeset by KaTeX, a vertex traced on click, the scene edited
// with the core compiled to WebAssembly (web/), which makes these anew. Scripts, styles
// and fonts are inlined from Debian's libjs-three and libjs-katex: the page
// makes no network request and opens from file://. No VTK, no Qt.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "viewpipe/lesson.hpp"
#include "viewpipe/report/figure.hpp"
#include "viewpipe/report/style.hpp"
#include "viewpipe/report/world_view.hpp"

namespace viewpipe::report {

// One frame of the world view: its camera and what it draws.
struct WebFrame {
    Mat4<double> view = Mat4<double>::Identity();       // stage coordinates -> eye coordinates
    Mat4<double> projection = Mat4<double>::Identity(); // eye -> OpenGL clip coordinates
    Vec3<double> focalPoint = Vec3<double>::Zero();      // what an orbit turns about
    Mat4<double> shown = Mat4<double>::Identity();       // the matrix the primitives are drawn through
    double canonicalOpacity = 0;
    std::optional<Vec4<double>> cut; // world coordinates, kept where cut . (x, y, z, 1) >= 0
};

// A stage at rest: its frame, the ghost of the stage before, the fixed
// axes' extent and the labels as the app places them (pixels of the page's size).
struct WebStage {
    WebFrame rest;
    std::optional<Mat4<double>> ghost;
    Eigen::AlignedBox<double, 3> frameExtent;
    std::vector<PlacedLabel> labels;
    PictureLayout layout; // where the caption, legend and note go, as in the PNG
    bool made = true;     // else only its frame extent: the page asks for the rest when shown (webStageView)
};

// What the page's views are made for: the picture's size in pixels, its
// text and lines, its theme, and how its stages are framed.
struct WebViewOptions {
    int width = 1280, height = 720;
    double fontSize = 20, minFontSize = 20, lineScale = 1;
    Theme theme = Theme::Light;
    FramingMode framing = FramingMode::Together;
    LegendPlace legend = LegendPlace::Best;
    // What the reader leaves out (hideNames): the scene drawn is withoutHidden's; here the caption, the
    // ticks and the notice of labels left out, which the picture's layout and labels leave out.
    std::set<std::string> hidden;
    double zoom = 1; // about the subject (export's --zoom): the reader's at first, as hidden and legend
};

struct WebPageViews {
    WebViewOptions options;
    std::vector<WebStage> stages;                   // 0 (the world) to the number of stages
    std::vector<std::vector<WebFrame>> transitions; // k: from stage k to k + 1, evenly in time, the last at rest;
                                                    // empty: left for the page to ask for (webTransition)
};

// The libraries, read from Debian's packages, KaTeX's fonts inlined into its
// style sheet as data; and ViewPipe's core as WebAssembly inlined in one
// script (`core`: empty for the one built with the app, by web/). Throws
// std::runtime_error naming what is missing.
// A preset the page offers: its group ("", "Classical projections", ...), name and scene JSON.
struct WebPreset {
    std::string group, name, scene;
};
struct WebAssets {
    std::string three, katex, katexCss, core;
    std::vector<WebPreset> presets;
};
// With `presets`, a scenes folder: its presets (presetScenes) without meshes.
WebAssets loadWebAssets(const std::filesystem::path& javascript = "/usr/share/javascript",
                        const std::filesystem::path& core = {}, const std::filesystem::path& presets = {});

// How the page shows a scene: each stage at rest and each step's frames,
// framed as the app frames them (world_view.hpp), from the default viewpoint;
// labels placed by the figures' placement, text measured by `measure` (in
// the font the page sets it in). `onStage(k)` is called before stage k is
// made, for progress and cancelling. With `shown`, what the page asks for
// on an edit: only that stage made (framed, its text laid out, its labels
// placed) and no step's frames, the others asked for when shown
// (webStageView, webTransition), the same.
WebPageViews webPageViews(const EvaluatedScene& scene, const WebViewOptions& options, const FontMeasure& measure,
                          const std::function<void(int)>& onStage = {}, std::optional<int> shown = {});
// Stage k at rest as webPageViews makes it (its frame, ghost, layout and labels), as JSON (as webPageData writes them).
std::string webStageView(const EvaluatedScene& scene, int stage, const WebViewOptions& options, const FontMeasure& measure);
// The step from stage `from` to the next as webPageViews makes it, as JSON (as webPageData writes a transition).
std::string webTransition(const EvaluatedScene& scene, int from, const WebViewOptions& options, const FontMeasure& measure);

// Stage k's labels as webPageViews places them (the figures' placement,
// around the stage's caption and legend), but seen through `camera` (stage
// coordinates -> the picture's clip coordinates): the page's labels while
// the view is turned. As JSON, as webPageData writes a stage's labels.
std::string webStageLabels(const EvaluatedScene& scene, int stage, const Mat4<double>& camera,
                           const WebViewOptions& options, const FontMeasure& measure);
// The same stage's whole flat figure (drawFigure: shapes back to front, in
// pixels, with their colors, and the labels), as JSON: the page's SVG of the view.
std::string webStageFigure(const EvaluatedScene& scene, int stage, const Mat4<double>& camera,
                           const WebViewOptions& options, const FontMeasure& measure);

// Every stage at once (the storyboard, storyboard.hpp) in the page's room, `width` by `height` pixels, as
// JSON: the layout's cells, each with its stage's camera at rest framed in its picture and its labels placed
// there (seen through `cameras[k]`, stage -> clip coordinates, where the page turned the view), the traced
// point (`traced`, else storyboardTracedPoint) and the overlay: the arrows, headers and footers. The text
// is the storyboard's size for `options`' text scale (its fontSize beside exportLabelSize at its width).
// With `shapes`, each cell's lines and faces too (drawFigure's, cut to its picture), in its picture's
// pixels: the storyboard as one figure, which the page saves as SVG.
std::string webStoryboard(const EvaluatedScene& scene, int width, int height, const std::optional<Vec3<double>>& traced,
                          const std::vector<Mat4<double>>& cameras, const WebViewOptions& options,
                          const FontMeasure& measure, bool shapes = false);

// A scene as the page draws it, as JSON: what the page's core makes anew on every edit.
std::string webPageData(const EvaluatedScene& scene, const WebPageViews& views);
// The whole page.
std::string webPage(const EvaluatedScene& scene, const WebPageViews& views, const WebAssets& assets);

// A lesson's page: its steps with captions and questions (their answers as
// the lesson computed them), each step showing one of `scenes`
// (`stepScenes[k]` is step k's index into them).
struct LessonScene {
    std::shared_ptr<const EvaluatedScene> scene;
    WebPageViews views;
};
std::string lessonPage(const Lesson& lesson, const std::vector<int>& stepScenes, const std::vector<LessonScene>& scenes,
                       const WebAssets& assets);

} // namespace viewpipe::report
