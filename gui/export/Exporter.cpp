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
#include <cctype>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

#include "DepthPlot.h"
#include "Offscreen.h"
#include "Process.h"
#include "VectorFigure.h"
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

void validate(const ExportOptions& o)
{
    validatePictureSize(o.width, o.height, o.scale);
    if (o.textScale < 50 || o.textScale > 400)
        throw InputError("--text-scale", "must be a whole percent from 50 to 400 (got " + std::to_string(o.textScale) + ")");
    if (o.fps < 1 || o.fps > 120)
        throw InputError("--fps", "must be 1 to 120");
    if (o.digits < 1 || o.digits > 17)
        throw InputError("--digits", "must be 1 to 17");
    for (const std::string& f : o.formats)
        if (f != "png" && f != "svg" && f != "pdf" && f != "tikz" && f != "html")
            throw InputError("--format", "unknown format \"" + f + "\" (png, svg, pdf, tikz, html)");
    if (o.formats.empty())
        throw InputError("--format", "names no format");
}

} // namespace

void exportWebPage(const std::shared_ptr<const EvaluatedScene>& scene, const fs::path& file, Theme theme,
                   const ExportProgress& progress, const std::atomic<bool>& cancel)
{
    ExportOptions options;
    options.out = file.parent_path() / (".viewpipe-web-" + std::to_string(::getpid()));
    options.formats = {"html"};
    options.theme = theme;
    std::error_code error;
    fs::remove_all(options.out, error);
    try {
        exportStages(scene, options, progress, cancel);
        if (!cancel)
            fs::rename(options.out / "scene.html", file);
    } catch (...) {
        fs::remove_all(options.out, error);
        throw;
    }
    fs::remove_all(options.out, error);
}

void exportSheet(const EvaluatedScene& scene, const fs::path& file, int width, int height, Theme theme)
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
    const double background = theme == Theme::Dark ? 0.11 : 1.0;
    const Rgb ink = elementColor(Element::Objects, theme);
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

std::string slug(const std::string& symbol)
{
    std::string out;
    for (char c : symbol) {
        if (std::isalnum(static_cast<unsigned char>(c)))
            out += char(std::tolower(static_cast<unsigned char>(c)));
        else if (!out.empty() && out.back() != '-')
            out += '-';
    }
    while (!out.empty() && out.back() == '-')
        out.pop_back();
    return out;
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

WebPageViews recordWebViews(const std::shared_ptr<const EvaluatedScene>& evaluated, int width, int height, int scale,
                            Theme theme, bool fixedFraming, const std::function<void(const std::string&)>& step,
                            double textScale)
{
    validatePictureSize(width, height, scale);
    WebViewOptions options;
    options.width = width * scale;
    options.height = height * scale;
    // In whole pixels, as the painter sets its text (OffscreenPainter).
    options.fontSize = int(exportLabelSize(options.width, textScale));
    options.minFontSize = int(exportLabelSize(options.width, 1));
    options.lineScale = scale;
    options.theme = theme;
    options.fixedFraming = fixedFraming;
    const int n = int(evaluated->pipeline.stages.size());
    return webPageViews(*evaluated, options, figureFontMeasure(), [&](int k) {
        step("web page: stage " + std::to_string(k) + " of " + std::to_string(n));
    });
}

std::vector<fs::path> exportStages(const std::shared_ptr<const EvaluatedScene>& evaluated, const ExportOptions& options,
                                   const ExportProgress& progress, const std::atomic<bool>& cancel)
{
    validate(options);
    const Scene& scene = evaluated->scene;
    const Pipeline<double>& pipeline = evaluated->pipeline;
    const std::vector<Stage<double>>& stages = pipeline.stages;
    const int n = int(stages.size());
    std::vector<int> chosen = options.stages;
    if (chosen.empty())
        chosen = parseStages("all", n);
    for (int k : chosen)
        if (k < 0 || k > n)
            throw InputError("--stages", "stage numbers run from 0 (the world) to " + std::to_string(n));

    // Each step takes fps frames, and every stage is held for `hold` frames.
    const int hold = int(std::lround(options.fps * kHoldSeconds));
    const int frameCount = options.animate ? n * options.fps + (n + 1) * hold : 0;
    const bool webPage = options.formats.count("html") > 0;
    const std::size_t pictureFormats = options.formats.size() - (webPage ? 1 : 0);
    const int total = int(chosen.size() * pictureFormats) + 2 + int(options.formats.count("tikz")) +
                      (scene.effects.depth ? 1 : 0) + frameCount + (webPage ? n + 2 : 0);
    int done = 0;
    auto step = [&](const std::string& what) {
        if (cancel)
            throw Cancelled{};
        if (progress)
            progress(++done, total, what);
    };

    std::error_code error;
    const bool created = !fs::exists(options.out);
    fs::create_directories(options.out, error);
    if (error || !fs::is_directory(options.out))
        throw InputError("--out", "cannot create the folder \"" + options.out.string() + "\": " + error.message());
    const fs::path temporary = options.out / (".viewpipe-export-" + std::to_string(::getpid()));
    fs::remove_all(temporary, error);
    fs::create_directories(temporary);

    auto cleanUp = [&] {
        std::error_code ignored;
        fs::remove_all(temporary, ignored);
        if (created)
            fs::remove(options.out, ignored); // only if still empty
    };

    try {
        // One offscreen window, one painter, one camera framing every stage.
        OffscreenPainter offscreen(evaluated, options.width, options.height, options.scale, options.theme,
                                   options.transparent, options.textScale / 100.0);
        vtkRenderWindow* window = offscreen.window;
        ScenePainter& painter = *offscreen.painter;
        const std::optional<Framing> framing = fixedFraming(*evaluated, options.fixedFraming);
        auto showAt = [&](int k, const std::string& caption) {
            return showStageAtRest(offscreen, *evaluated, k, caption, framing);
        };

        std::vector<std::pair<std::string, std::string>> figures; // file name without extension, caption
        for (int k : chosen) {
            const std::string base = (k < 10 ? "0" : "") + std::to_string(k) + "-" +
                                     (k == 0 ? std::string("world") : slug(stages[std::size_t(k - 1)].symbol));
            const std::string caption = stageCaption(*evaluated, std::size_t(k), StageText::Heading);
            const StageShown shown = showAt(k, caption);
            const VectorFigure vector{&shown, painter.figureView(), caption, options.theme};
            for (const std::string& format : options.formats) {
                if (format == "html")
                    continue; // one page for every stage, below
                // "-tikz.tex": pdflatex makes "-tikz.pdf" of it, not the PDF export's file.
                const std::string file = base + (format == "tikz" ? "-tikz.tex" : "." + format);
                step("stage " + std::to_string(k) + " of " + std::to_string(n) + ": " + file);
                if (format == "png")
                    writeWindowPng(window, options.transparent, temporary / file);
                else if (format == "tikz")
                    writeFileAtomically(temporary / file, tikzFigure(flatFigure(vector), options.theme));
                else
                    writeVectorFigure(vector, format, temporary / file);
            }
            figures.emplace_back(base + "-tikz", caption);
        }
        if (options.formats.count("tikz")) {
            step("figures.tex");
            writeFileAtomically(temporary / "figures.tex", tikzFiguresDocument(figures));
        }

        if (webPage) {
            const WebPageViews views = recordWebViews(evaluated, options.width, options.height, options.scale,
                                                      options.theme, options.fixedFraming, step, options.textScale / 100.0);
            step("scene.html");
            writeFileAtomically(temporary / "scene.html", viewpipe::webPage(*evaluated, views, loadWebAssets("/usr/share/javascript", {}, options.presets)));
        }

        step("matrices.tex");
        writeFileAtomically(temporary / "matrices.tex", report::matricesLatex(scene, options.digits));
        if (const auto& depth = evaluated->outcomes.depth) {
            step("depth-resolution.png");
            writeDepthPlot(pipeline, depth->options, temporary / "depth-resolution.png", options.theme, options.width,
                           options.height, options.textScale / 100.0);
        }
        step("matrices.json");
        writeFileAtomically(temporary / "matrices.json", report::pipelineJson(scene, report::PrecisionChoice{}, evaluated->outcomes).dump(2) + "\n");

        if (options.animate) {
            const fs::path frames = temporary / "frames";
            fs::create_directories(frames);
            int frame = 0;
            auto emit = [&] {
                char name[32];
                std::snprintf(name, sizeof name, "%05d.png", frame++);
                step("frame " + std::to_string(frame) + " of " + std::to_string(frameCount));
                window->Render();
                writeWindowPng(window, false, frames / name);
            };
            for (int k = 0; k <= n; ++k) {
                const std::string caption = stageCaption(*evaluated, std::size_t(k), StageText::Heading);
                painter.setCaptions(caption, "");
                if (k > 0) { // the app's transition: the same motion and framing
                    const StageMotion motion(*evaluated, k - 1, k, framing);
                    for (int f = 1; f <= options.fps; ++f) {
                        painter.showMoment(motion.at(double(f) / options.fps));
                        emit();
                    }
                }
                showAt(k, caption);
                for (int f = 0; f < hold; ++f)
                    emit();
            }
            // H.264 in MP4 with yuv420p plays in browsers and in slide software.
            const int status = runProgram({"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
                                           std::to_string(options.fps), "-i", (frames / "%05d.png").string(), "-vf",
                                           "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                                           "yuv420p", "-movflags", "+faststart",
                                           (temporary / "animation.mp4").string()});
            if (cancel)
                throw Cancelled{};
            if (status == -1)
                throw std::runtime_error("the animation needs ffmpeg (Debian package ffmpeg), which was not found");
            if (status != 0)
                throw std::runtime_error("ffmpeg failed to encode the animation (exit " + std::to_string(status) + ")");
            fs::remove_all(frames);
        }

        // Everything is complete: move it into place, file by file (rename is atomic).
        std::vector<fs::path> written;
        for (const auto& entry : fs::directory_iterator(temporary)) {
            const fs::path target = options.out / entry.path().filename();
            fs::rename(entry.path(), target);
            written.push_back(target);
        }
        fs::remove(temporary);
        std::sort(written.begin(), written.end());
        return written;
    } catch (const Cancelled&) {
        cleanUp();
        return {};
    } catch (...) {
        cleanUp();
        throw;
    }
}

} // namespace viewpipe::gui
