#include "Exporter.h"

#include <vtkCamera.h>
#include <vtkErrorCode.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

#include "DepthPlot.h"
#include "Offscreen.h"
#include "Process.h"
#include "StagingFolder.h"
#include "VectorFigure.h"
#include "viewpipe/report/storyboard.hpp"
#include "viewpipe/report/tikz.hpp"
#include "viewpipe/report/latex.hpp"
#include "viewpipe/report/report.hpp"
#include "painter/VtkGeometry.h"
#include "viewpipe/animation.hpp"
#include "viewpipe/classical.hpp"

namespace viewpipe::gui {
namespace fs = std::filesystem;

namespace {

constexpr double kHoldSeconds = 0.6; // the animation rests this long at each stage

struct Cancelled {};

// The window's picture encoded as PNG.
std::string windowPng(vtkRenderWindow* window, bool transparent)
{
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    if (transparent)
        grab->SetInputBufferTypeToRGBA();
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->WriteToMemoryOn();
    writer->Write();
    vtkUnsignedCharArray* bytes = writer->GetResult();
    if (writer->GetErrorCode() != vtkErrorCode::NoError || !bytes || bytes->GetNumberOfValues() == 0)
        throw std::runtime_error(std::string("cannot encode the picture as PNG (") +
                                 vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()) + ")");
    return {reinterpret_cast<const char*>(bytes->GetPointer(0)), std::size_t(bytes->GetNumberOfValues())};
}

} // namespace

void writeWindowPng(vtkRenderWindow* window, bool transparent, const fs::path& file)
{
    writeFileAtomically(file, windowPng(window, transparent));
}

namespace {

void validatePictureSize(int width, int height, int scale)
{
    if (width < 64 || height < 64 || width > 8192 || height > 8192)
        throw InputError("--size", "must be WxH with 64 <= W, H <= 8192");
    if (scale < 1 || scale > 4 || width * scale > 16384 || height * scale > 16384)
        throw InputError("--scale", "must be 1 to 4, and size times scale at most 16384");
}


// Counts an export's steps for its progress bar; throws Cancelled once `cancel` is set.
class Steps {
public:
    Steps(const ExportProgress& progress, const std::atomic<bool>& cancel, int total)
        : progress_(progress), cancel_(cancel), total_(total)
    {
    }
    void operator()(const std::string& what)
    {
        if (cancel_)
            throw Cancelled{};
        if (progress_)
            progress_(++done_, total_, what);
    }

private:
    const ExportProgress& progress_;
    const std::atomic<bool>& cancel_;
    int total_, done_ = 0;
};

// What a stage's files are drawn from: the painter's window and the stage's vector figure.
struct StagePicture {
    vtkRenderWindow* window;
    bool transparent;
    VectorFigure vector;
};

// What a scene's own files are made from, once every stage is drawn.
struct SceneOutput {
    std::shared_ptr<const EvaluatedScene> evaluated;
    const ExportOptions& options;
    std::vector<std::pair<std::string, int>> figures; // each stage's file name without extension, and its number
    fs::path folder;
    Steps& step;
};

// A storyboard's files are drawn from: its figures and the painter's picture of each cell.
struct StoryboardPictures {
    report::Storyboard storyboard;
    std::vector<std::string> cellPngs;
    report::Theme theme;
};

// An export format: a file for each stage (its name the stage's and `suffix`),
// files for the whole scene, or both; with --layout storyboard, one file of
// every stage at once ("storyboard" and `suffix`) instead of the stages'.
struct Format {
    ExportFormat about;
    std::string suffix;
    std::function<void(const StagePicture&, const fs::path&)> writeStage;
    std::function<void(SceneOutput&)> writeScene;
    std::function<int(const EvaluatedScene&)> sceneSteps; // progress steps of writeScene
    std::function<void(const StoryboardPictures&, const fs::path&)> writeStoryboardFile = {};
};

// The web page's steps: every stage recorded, then the page.
int pageSteps(const EvaluatedScene& scene)
{
    return int(scene.pipeline.stages.size()) + 2;
}

// The scene as one self-contained web page, its views recorded at the options' size, drawn without what
// --hide names at first (the reader may bring it back: the page's core has the scene whole).
std::string scenePage(const std::shared_ptr<const EvaluatedScene>& scene, const ExportOptions& options, Steps& step)
{
    const auto shown = withoutHidden(scene, options.hidden);
    report::WebPageViews views = recordWebViews(shown, options.width, options.height, options.scale, options.theme,
                                                options.framing, std::ref(step), options.textScale / 100.0, options.hidden,
                                                options.legend);
    views.options.zoom = options.zoom; // the page zooms its recorded views itself
    step("scene.html");
    return viewpipe::report::webPage(*shown, views, report::loadWebAssets("/usr/share/javascript", {}, options.presets));
}

const std::vector<Format>& formatTable()
{
    static const std::vector<Format> table = {
        {{"png", "a picture of each stage, as the app draws it"}, ".png",
         [](const StagePicture& p, const fs::path& file) { writeWindowPng(p.window, p.transparent, file); }, {}, {},
         [](const StoryboardPictures& p, const fs::path& file) {
             writeStoryboard(p.storyboard, p.theme, "png", file, p.cellPngs);
         }},
        {{"svg", "a vector figure of each stage"}, ".svg",
         [](const StagePicture& p, const fs::path& file) { writeVectorFigure(p.vector, "svg", file); }, {}, {},
         [](const StoryboardPictures& p, const fs::path& file) { writeStoryboard(p.storyboard, p.theme, "svg", file); }},
        {{"pdf", "a vector figure of each stage"}, ".pdf",
         [](const StagePicture& p, const fs::path& file) { writeVectorFigure(p.vector, "pdf", file); }, {}, {},
         [](const StoryboardPictures& p, const fs::path& file) { writeStoryboard(p.storyboard, p.theme, "pdf", file); }},
        // "-tikz.tex": pdflatex makes "-tikz.pdf" of it, not the PDF format's file.
        {{"tikz", "a TikZ figure of each stage, and figures.tex showing them all"}, "-tikz.tex",
         [](const StagePicture& p, const fs::path& file) {
             writeFileAtomically(file, report::tikzFigure(flatFigure(p.vector), p.vector.theme));
         },
         [](SceneOutput& out) {
             out.step("figures.tex");
             std::vector<std::pair<std::string, std::string>> figures;
             for (const auto& [base, k] : out.figures) // numbered by the document, not by the stage
                 figures.emplace_back(base + "-tikz", stageCaption(*out.evaluated, std::size_t(k), StageText::Figure));
             writeFileAtomically(out.folder / "figures.tex", report::tikzFiguresDocument(figures));
         },
         [](const EvaluatedScene&) { return 1; },
         [](const StoryboardPictures& p, const fs::path& file) {
             writeFileAtomically(file, report::tikzStoryboard(p.storyboard, p.theme));
         }},
        {{"html", "one self-contained web page of the scene, scene.html"}, "", {},
         [](SceneOutput& out) { writeFileAtomically(out.folder / "scene.html", scenePage(out.evaluated, out.options, out.step)); },
         pageSteps},
    };
    return table;
}

const Format& formatNamed(const std::string& name)
{
    for (const Format& format : formatTable())
        if (format.about.name == name)
            return format;
    throw InputError("--format", "unknown format \"" + name + "\" (" + exportFormatNames() + ")");
}

// "03-t-prp": a stage's files' name, in stage order.
std::string stageFileBase(const Pipeline<double>& pipeline, int k)
{
    return (k < 10 ? "0" : "") + std::to_string(k) + "-" +
           (k == 0 ? std::string("world") : stageSlug(pipeline.stages[std::size_t(k - 1)].kind));
}

// matrices.tex, matrices.json and, with a depth buffer, depth-resolution.png.
void writeReports(const EvaluatedScene& evaluated, const ExportOptions& options, const fs::path& folder, Steps& step)
{
    step("matrices.tex");
    writeFileAtomically(folder / "matrices.tex", report::matricesDocument(evaluated.scene, options.digits));
    if (const auto& depth = evaluated.outcomes.depth) {
        step("depth-resolution.png");
        writeDepthPlot(evaluated.pipeline, depth->options, folder / "depth-resolution.png", options.theme, options.width,
                       options.height, options.textScale / 100.0);
    }
    step("matrices.json");
    writeFileAtomically(folder / "matrices.json",
                        report::pipelineJson(evaluated.scene, report::PrecisionChoice{}, evaluated.outcomes).dump(2) + "\n");
}

// Each step takes fps frames, and every stage is held for kHoldSeconds.
int holdFrames(int fps)
{
    return int(std::lround(fps * kHoldSeconds));
}

int animationFrames(int stageCount, int fps)
{
    return stageCount * fps + (stageCount + 1) * holdFrames(fps);
}

// The caption over stage k's picture: none where --hide names it.
std::string pictureCaption(const EvaluatedScene& scene, int k, const ExportOptions& options)
{
    return options.hidden.count("caption") ? "" : stageCaption(scene, std::size_t(k), StageText::Heading);
}

// animation.mp4: the app's transitions, with the same motion and framing, each stage held.
void writeAnimation(OffscreenPainter& offscreen, const EvaluatedScene& evaluated, const ExportOptions& options,
                    const report::StageFramings& framing, const fs::path& folder, Steps& step,
                    const std::atomic<bool>& cancel)
{
    const int n = int(evaluated.pipeline.stages.size()), total = animationFrames(n, options.fps);
    const fs::path frames = folder / "frames";
    fs::create_directories(frames);
    int frame = 0;
    auto emit = [&] {
        char name[32];
        std::snprintf(name, sizeof name, "%05d.png", frame++);
        step("frame " + std::to_string(frame) + " of " + std::to_string(total));
        offscreen.window->Render();
        writeWindowPng(offscreen.window, false, frames / name);
    };
    for (int k = 0; k <= n; ++k) {
        const std::string caption = pictureCaption(evaluated, k, options);
        offscreen.painter->setCaptions(caption, "");
        if (k > 0) {
            const report::StageMotion motion(evaluated, k - 1, k, framing);
            for (int f = 1; f <= options.fps; ++f) {
                offscreen.painter->showMoment(motion.at(double(f) / options.fps));
                emit();
            }
        }
        showStageAtRest(offscreen, evaluated, k, caption, framing);
        for (int f = 0; f < holdFrames(options.fps); ++f)
            emit();
    }
    // H.264 in MP4 with yuv420p plays in browsers and in slide software.
    const int status = runProgram({"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
                                   std::to_string(options.fps), "-i", (frames / "%05d.png").string(), "-vf",
                                   "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                                   "-movflags", "+faststart", (folder / "animation.mp4").string()});
    if (cancel)
        throw Cancelled{};
    if (status == -1)
        throw std::runtime_error("the animation needs ffmpeg (Debian package ffmpeg), which was not found");
    if (status != 0)
        throw std::runtime_error("ffmpeg failed to encode the animation (exit " + std::to_string(status) + ")");
    fs::remove_all(frames);
}

void validate(const ExportOptions& o)
{
    validatePictureSize(o.width, o.height, o.scale);
    report::checkTextScale(o.textScale, "--text-scale");
    if (o.fps < 1 || o.fps > 120)
        throw InputError("--fps", "must be 1 to 120");
    if (o.digits < 1 || o.digits > 17)
        throw InputError("--digits", "must be 1 to 17");
    if (o.formats.empty())
        throw InputError("--format", "names no format");
    if (!(o.zoom >= 0.1 && o.zoom <= 10))
        throw InputError("--zoom", "must be 0.1 to 10");
    if (o.storyboard && o.animate)
        throw InputError("--animate", "a storyboard shows every stage at once: it has no animation");
    if (o.storyboard && o.transparent)
        throw InputError("--transparent", "a storyboard is drawn on its theme's background");
    if (o.storyboard && std::none_of(o.formats.begin(), o.formats.end(), [](const std::string& name) {
            return bool(formatNamed(name).writeStoryboardFile);
        }))
        throw InputError("--format", "a storyboard is drawn as png, svg, pdf or tikz: name one of them");
    const std::vector<std::string> names = hideNames();
    for (const std::string& name : o.hidden)
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            std::string list;
            for (const std::string& known : names)
                list += (list.empty() ? "" : ", ") + known;
            throw InputError("--hide", "\"" + name + "\" is not one of " + list);
        }
    for (const std::string& name : o.formats)
        formatNamed(name);
}


// Every chosen stage at once, one file per format: each cell drawn by a painter of the cell's size with the
// storyboard's text size, no legend of its own, the traced point marked.
void writeStoryboardFiles(const std::shared_ptr<const EvaluatedScene>& evaluated, const ExportOptions& options,
                          const std::vector<int>& chosen, const std::vector<const Format*>& formats,
                          const fs::path& folder, Steps& step)
{
    const int width = options.width * options.scale, height = options.height * options.scale;
    const double labelSize = report::storyboardLabelSize(width, options.textScale / 100.0);
    const Vec3<double> traced = report::storyboardTracedPoint(*evaluated);
    const report::StoryboardLayout layout = report::layoutStoryboard(*evaluated, chosen, traced, width, height, labelSize, figureFontMeasure());
    if (layout.cells.empty())
        throw InputError("--size", "leaves no room for a storyboard of " + std::to_string(chosen.size()) + " pictures");
    const report::Box2& cell = layout.cells.front().picture;
    const auto cellScene = withoutEffectsNote(evaluated);
    OffscreenPainter offscreen(cellScene, int(cell.max.x() - cell.min.x()), int(cell.max.y() - cell.min.y()), 1,
                               options.theme, false);
    ScenePainter& painter = *offscreen.painter;
    styleStoryboardCell(painter, layout.labelSize, !options.hidden.count("ticks"), !options.hidden.count("notes"), traced);
    painter.setLineScale(options.scale);
    painter.orbit(0, 0, options.zoom);
    const report::StageFramings framing = stageFramings(*cellScene, options.framing);
    StoryboardPictures pictures{{layout, {}, report::storyboardOverlay(*evaluated, layout, traced, figureFontMeasure(), options.scale),
                                 evaluated->scene.name.empty() ? "Storyboard" : evaluated->scene.name + ": every stage"},
                                {}, options.theme};
    for (const int k : chosen) {
        step("storyboard: stage " + std::to_string(k));
        report::StageShown shown = showStageAtRest(offscreen, *cellScene, k, "", framing);
        shown.traced = traced;
        report::Figure figure = flatFigure(VectorFigure{&shown, painter.figureView(), "", painter.placedLabels(), options.theme});
        report::cutShapesTo(figure, {{0, 0}, {double(figure.width), double(figure.height)}});
        pictures.storyboard.cells.push_back(std::move(figure));
        pictures.cellPngs.push_back(windowPng(offscreen.window, false));
    }
    for (const Format* format : formats)
        if (format->writeStoryboardFile) {
            const std::string file = "storyboard" + format->suffix;
            step(file);
            format->writeStoryboardFile(pictures, folder / file);
        }
}

} // namespace

void exportWebPage(const std::shared_ptr<const EvaluatedScene>& scene, const fs::path& file, report::Theme theme,
                   const ExportProgress& progress, const std::atomic<bool>& cancel)
{
    ExportOptions options;
    options.theme = theme;
    Steps step(progress, cancel, pageSteps(*scene));
    try {
        const std::string page = scenePage(scene, options, step);
        if (!cancel) // a Cancel seen in the last step's progress
            writeFileAtomically(file, page);
    } catch (const Cancelled&) {
        // Nothing was written.
    }
}

void exportSheet(const EvaluatedScene& scene, const fs::path& file, int width, int height, report::Theme theme)
{
    if (width < 128 || height < 128 || width > 8192 || height > 8192)
        throw InputError("--size", "must be WxH with 128 <= W, H <= 8192");
    const Eigen::AlignedBox<double, 3> box = scene.objectBounds();
    if (box.isEmpty())
        throw InputError("objects", "the scene has no objects to draw");
    struct Panel {
        ClassicalKind kind;
        const char* caption;
        double x0, y0; // lower-left corner of the viewport
    };
    const Panel panels[] = {{ClassicalKind::Top, "Top", 0, 0.5},
                            {ClassicalKind::Isometric, "Isometric", 0.5, 0.5},
                            {ClassicalKind::Front, "Front", 0, 0},
                            {ClassicalKind::Side, "Side (right)", 0.5, 0}};
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    const double background = theme == report::Theme::Dark ? 0.11 : 1.0;
    const report::Rgb ink = report::elementColor(Element::Objects, theme);
    // One scale for the four views, as a drawing has: lengths compare across them.
    std::vector<foley::ViewSpec<double>> views;
    double scale = 0;
    for (const Panel& panel : panels) {
        views.push_back(classicalView(panel.kind, box.min(), box.max()));
        scale = std::max(scale, 0.5 * (views.back().window.vmax - views.back().window.vmin));
    }
    std::vector<vtkRenderer*> renderers;
    for (std::size_t k = 0; k < 4; ++k) {
        // These views are orthographic (projectors along VPN): VTK's parallel
        // camera, aimed along -VPN at the window's center, sees the window.
        const Panel& panel = panels[k];
        const foley::ViewSpec<double>& view = views[k];
        const Basis<double> b = foley::vrcBasis(view);
        const Vec3<double> center = foley::vrcToWorld(view, b, foley::windowCenter(view));
        vtkNew<vtkRenderer> renderer;
        renderer->SetViewport(panel.x0, panel.y0, panel.x0 + 0.5, panel.y0 + 0.5);
        renderer->SetBackground(background, background, background);
        renderers.push_back(renderer);
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->ParallelProjectionOn();
        camera->SetFocalPoint(center.data());
        camera->SetPosition(Vec3<double>(center + (view.prp.z() - view.back) * b.n).data());
        camera->SetViewUp(b.v.data());
        camera->SetParallelScale(scale);
        vtkNew<vtkTextActor> caption;
        caption->SetInput(panel.caption);
        caption->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
        caption->SetPosition(0.03, 0.93);
        caption->GetTextProperty()->SetFontSize(std::max(14, height / 40));
        caption->GetTextProperty()->SetBold(true);
        caption->GetTextProperty()->SetColor(ink.r, ink.g, ink.b);
        renderer->AddActor2D(caption);
        window->AddRenderer(renderer);
    }
    addObjectActors(renderers, scene, theme);
    for (vtkRenderer* renderer : renderers)
        renderer->ResetCameraClippingRange();
    window->Render();
    try {
        writeWindowPng(window, false, file);
    } catch (const std::exception& e) {
        throw InputError("--out", std::string("cannot write the sheet: ") + e.what());
    }
}

std::vector<int> parseStages(const std::string& text, int stageCount)
{
    std::vector<int> stages;
    if (text == "all") {
        for (int k = 0; k <= stageCount; ++k)
            stages.push_back(k);
        return stages;
    }
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        int first = 0, last = 0;
        char dash = 0;
        std::istringstream range(item);
        if (!(range >> first))
            throw InputError("--stages", "must be \"all\" or a list such as 0,2,4-5 (got \"" + text + "\")");
        last = first;
        if (range >> dash && (dash != '-' || !(range >> last)))
            throw InputError("--stages", "must be \"all\" or a list such as 0,2,4-5 (got \"" + text + "\")");
        if (first < 0 || last > stageCount || first > last)
            throw InputError("--stages", "stage numbers run from 0 (the world) to " + std::to_string(stageCount) +
                                             " (got \"" + item + "\")");
        for (int k = first; k <= last; ++k)
            stages.push_back(k);
    }
    if (stages.empty())
        throw InputError("--stages", "names no stage");
    return stages;
}

report::WebPageViews recordWebViews(const std::shared_ptr<const EvaluatedScene>& evaluated, int width, int height, int scale,
                            report::Theme theme, report::FramingMode framing, const std::function<void(const std::string&)>& step,
                            double textScale, const std::set<std::string>& hidden, report::LegendPlace legend)
{
    validatePictureSize(width, height, scale);
    report::WebViewOptions options;
    options.width = width * scale;
    options.height = height * scale;
    // In whole pixels, as the painter sets its text (OffscreenPainter).
    options.fontSize = int(report::exportLabelSize(options.width, textScale));
    options.minFontSize = int(report::exportLabelSize(options.width, 1));
    options.lineScale = scale;
    options.theme = theme;
    options.framing = framing;
    options.hidden = hidden;
    options.legend = legend;
    const int n = int(evaluated->pipeline.stages.size());
    return report::webPageViews(*evaluated, options, figureFontMeasure(), [&](int k) {
        step("web page: stage " + std::to_string(k) + " of " + std::to_string(n));
    });
}

std::vector<fs::path> exportStages(const std::shared_ptr<const EvaluatedScene>& scene, const ExportOptions& options,
                                   const ExportProgress& progress, const std::atomic<bool>& cancel)
{
    validate(options);
    const std::shared_ptr<const EvaluatedScene> evaluated = withoutHidden(scene, options.hidden);
    const int n = int(evaluated->pipeline.stages.size());
    std::vector<int> chosen = options.stages.empty() ? parseStages("all", n) : options.stages;
    for (int k : chosen)
        if (k < 0 || k > n)
            throw InputError("--stages", "stage numbers run from 0 (the world) to " + std::to_string(n));
    std::vector<const Format*> formats;
    for (const Format& format : formatTable())
        if (options.formats.count(format.about.name))
            formats.push_back(&format);

    int total = 2 + (evaluated->outcomes.depth ? 1 : 0) + (options.animate ? animationFrames(n, options.fps) : 0);
    if (options.storyboard)
        total += int(chosen.size());
    for (const Format* format : formats)
        total += options.storyboard ? (format->writeStoryboardFile ? 1 : 0) + (format->writeScene && !format->writeStage ? format->sceneSteps(*evaluated) : 0)
                                    : (format->writeStage ? int(chosen.size()) : 0) + (format->writeScene ? format->sceneSteps(*evaluated) : 0);
    Steps step(progress, cancel, total);

    StagingFolder staging(options.out);
    try {
        if (options.storyboard) {
            writeStoryboardFiles(evaluated, options, chosen, formats, staging.path(), step);
            SceneOutput output{scene, options, {}, staging.path(), step};
            for (const Format* format : formats)
                if (format->writeScene && !format->writeStage) // the web page; figures.tex lists stage files
                    format->writeScene(output);
            writeReports(*evaluated, options, staging.path(), step);
            return staging.commit();
        }
        // One offscreen window, one painter, one camera framing every stage.
        OffscreenPainter offscreen(evaluated, options.width, options.height, options.scale, options.theme,
                                   options.transparent, options.textScale / 100.0);
        offscreen.painter->setLegendPlace(options.legend);
        offscreen.painter->setTicksAndNotesShown(!options.hidden.count("ticks"), !options.hidden.count("notes"));
        offscreen.painter->orbit(0, 0, options.zoom);
        const report::StageFramings framing = report::stageFramings(*evaluated, options.framing);
        SceneOutput output{scene, options, {}, staging.path(), step}; // the page draws the scene whole
        for (int k : chosen) {
            const std::string base = stageFileBase(evaluated->pipeline, k);
            const std::string caption = pictureCaption(*evaluated, k, options);
            const report::StageShown shown = showStageAtRest(offscreen, *evaluated, k, caption, framing);
            if (const report::LegendPlace at = offscreen.painter->pictureLayout().legendAt;
                options.notice && !options.hidden.count("legend") && options.legend != report::LegendPlace::Best &&
                options.legend != report::LegendPlace::None && at != options.legend)
                options.notice("stage " + std::to_string(k) + ": no room for the legend " +
                               report::legendPlaceTitle(options.legend) + "; " +
                               (at == report::LegendPlace::None ? std::string("left out")
                                                                : std::string("it stands ") + report::legendPlaceTitle(at)));
            const StagePicture picture{offscreen.window, options.transparent,
                                       VectorFigure{&shown, offscreen.painter->figureView(), caption,
                                                    offscreen.painter->placedLabels(), options.theme}};
            for (const Format* format : formats)
                if (format->writeStage) {
                    const std::string file = base + format->suffix;
                    step("stage " + std::to_string(k) + " of " + std::to_string(n) + ": " + file);
                    format->writeStage(picture, staging.path() / file);
                }
            output.figures.emplace_back(base, k);
        }
        for (const Format* format : formats)
            if (format->writeScene)
                format->writeScene(output);
        writeReports(*evaluated, options, staging.path(), step);
        if (options.animate)
            writeAnimation(offscreen, *evaluated, options, framing, staging.path(), step, cancel);
        return staging.commit();
    } catch (const Cancelled&) {
        return {};
    }
}

std::string exportFormatNames()
{
    std::string names;
    for (const Format& format : formatTable())
        names += (names.empty() ? "" : ", ") + format.about.name;
    return names;
}

std::vector<ExportFormat> exportFormats()
{
    std::vector<ExportFormat> formats;
    for (const Format& format : formatTable())
        formats.push_back(format.about);
    return formats;
}

std::set<std::string> parseFormats(const std::string& list)
{
    std::set<std::string> names;
    std::istringstream in(list);
    for (std::string name; std::getline(in, name, ',');)
        names.insert(formatNamed(name).about.name);
    if (names.empty())
        throw InputError("--format", "names no format");
    return names;
}

} // namespace viewpipe::gui
