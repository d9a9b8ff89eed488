#include "LessonExport.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "Offscreen.h"
#include "Exporter.h"
#include "Process.h"
#include "StagingFolder.h"
#include "VectorFigure.h"
#include "viewpipe/report/lesson_latex.hpp"
#include "viewpipe/report/report.hpp"
#include "viewpipe/report/web_page.hpp"

namespace viewpipe::gui {
namespace fs = std::filesystem;

namespace {

// The figures' text against the pictures' at their size: a page sets them at
// kHandoutFigureWidth of its text (lesson_latex.hpp); a slide at 0.63 of its
// 152 mm beside the step's text, where 1.25 sets labels of 2.4 % of the width at 8 pt.
constexpr double kPaperFontScale = report::kHandoutFigureTextScale, kSlideFontScale = 1.25;

// Step `step`'s view of `stage` as a PDF figure: its camera, its stage, the
// stage named only when the step does not hide it.
void writeStepFigure(const OffscreenPainter& offscreen, const std::shared_ptr<const EvaluatedScene>& scene,
                     const LessonStep& step, int stage, bool named, const std::optional<Vec3<double>>& traced, report::Theme theme,
                     const fs::path& file)
{
    ScenePainter& painter = *offscreen.painter;
    painter.setScene(scene);
    painter.resetView();
    painter.orbit(step.yaw, step.pitch, step.zoom);
    painter.markTraced(traced); // placed with the rest
    const std::string caption = named ? stageCaption(*scene, std::size_t(stage), StageText::Heading) : std::string();
    report::StageShown shown = showStageAtRest(offscreen, *scene, stage, caption, {});
    shown.traced = traced;
    writeVectorFigure({&shown, painter.figureView(), caption, painter.placedLabels(), theme}, "pdf", file);
}

// What pdflatex's log says went wrong ("! ..." and the lines after it), and
// the line of the document it names ("l.123"), if any.
std::pair<std::string, int> latexError(const fs::path& log)
{
    std::ifstream in(log);
    std::string line, what;
    int after = 0, at = 0;
    while (std::getline(in, line) && what.size() < 600) {
        if (!line.empty() && line[0] == '!')
            after = 3;
        if (line.rfind("l.", 0) == 0 && at == 0)
            at = std::atoi(line.c_str() + 2);
        if (after > 0) {
            what += (what.empty() ? "" : " ") + line;
            --after;
        }
    }
    std::string squeezed; // the log pads its lines with spaces
    for (char c : what)
        if (!(c == ' ' && !squeezed.empty() && squeezed.back() == ' '))
            squeezed += c;
    return {squeezed.empty() ? "no reason given" : squeezed, at};
}

// The field of the lesson whose text is at `line` of the document: the step marked last before it.
std::string fieldAt(const fs::path& document, int line)
{
    std::ifstream in(document);
    std::string text, field = "title";
    for (int k = 1; k <= line && std::getline(in, text); ++k)
        if (text.rfind(report::kStepMark, 0) == 0)
            field = "steps" + text.substr(std::string(report::kStepMark).size());
    return field;
}

// pdflatex without its terminal talk, reading no file outside the folder
// (openin_any=p), stopped after a minute (a lesson's macros could loop).
void compile(const fs::path& folder, const std::string& document)
{
    ChildStreams quiet;
    quiet.stdoutToNull = true;
    quiet.stderrToNull = true; // its refusals are in the log, and in the message below
    quiet.workingDirectory = folder.string();
    quiet.environment = {"openin_any=p", "openout_any=p"};
    const int status = runProgram({"pdflatex", "-interaction=batchmode", "-halt-on-error", "-no-shell-escape",
                                   document + ".tex"},
                                  quiet, 60);
    if (status == -1)
        throw std::runtime_error("the handout, slides and problem sheet need pdflatex (TeX Live), which was not found: "
                                 "scripts/install-deps.sh --pdf installs it");
    if (status == kTimedOut)
        throw InputError("steps", "pdflatex did not finish in a minute: a caption's macros may never end");
    if (status != 0) {
        const auto [what, line] = latexError(folder / (document + ".log"));
        if (line == 0)
            throw std::runtime_error("pdflatex could not set " + document + ".tex: " + what);
        // The lesson's text is what pdflatex could not set: bad input, named by its step.
        throw InputError(fieldAt(folder / (document + ".tex"), line), "pdflatex cannot set its text: " + what);
    }
}

// The steps' figures, written into `folder`: on paper (the handout, the problem sheet) and, with
// `forSlides`, for the slides.
struct StepFigures {
    std::vector<report::LessonFigures> paper, slides;
};
StepFigures writeStepFigures(const Lesson& lesson, const EvaluatedLesson& evaluated, const LessonExportOptions& options,
                             const fs::path& folder, bool forSlides, const std::function<void(const std::string&)>& step)
{
    StepFigures made{std::vector<report::LessonFigures>(lesson.steps.size()), std::vector<report::LessonFigures>(lesson.steps.size())};
    for (std::size_t s = 0; s < evaluated.shown.size(); ++s) {
        const auto& scene = evaluated.shown[s];
        const OffscreenPainter paper(scene, options.width, options.height, 1, options.theme, false, kPaperFontScale);
        std::optional<OffscreenPainter> projector;
        if (forSlides)
            projector.emplace(scene, options.width, options.height, 1, options.theme, false, kSlideFontScale);
        for (std::size_t k = 0; k < lesson.steps.size(); ++k) {
            if (evaluated.stepShown[k] != int(s))
                continue;
            const LessonStep& lessonStep = lesson.steps[k];
            step("figures of step " + std::to_string(k + 1) + " of " + std::to_string(lesson.steps.size()));
            char name[32];
            std::snprintf(name, sizeof name, "step-%02zu", k + 1);
            auto figures = [&](const OffscreenPainter& offscreen, const std::string& prefix, report::LessonFigures& files) {
                files.revealed = prefix + name + ".pdf";
                writeStepFigure(offscreen, scene, lessonStep, revealedStage(lessonStep), true, tracedAt(lessonStep, true),
                                options.theme, folder / files.revealed);
                if (lessonStep.question) {
                    files.asking = prefix + name + "-asking.pdf";
                    writeStepFigure(offscreen, scene, lessonStep, askingStage(lessonStep), false, tracedAt(lessonStep, false),
                                    options.theme, folder / files.asking);
                }
            };
            figures(paper, "", made.paper[k]);
            if (projector)
                figures(*projector, "slide-", made.slides[k]);
        }
    }
    return made;
}

// lesson.html in `folder`: every scene shown recorded as the app draws it.
void writeLessonPage(const Lesson& lesson, const EvaluatedLesson& evaluated, const LessonExportOptions& options,
                     const fs::path& folder, const std::function<void(const std::string&)>& step)
{
    std::vector<report::LessonScene> scenes;
    for (const auto& scene : evaluated.shown) {
        step("recording " + scene->scene.name);
        scenes.push_back({scene, recordWebViews(scene, options.width, options.height, 1, options.theme, report::FramingMode::Together,
                                                [](const std::string&) {})});
    }
    step("lesson.html");
    writeFileAtomically(folder / "lesson.html", report::lessonPage(lesson, evaluated.stepShown, scenes, report::loadWebAssets()));
}

} // namespace

std::set<std::string> parseLessonFormats(const std::string& list)
{
    std::set<std::string> formats;
    std::istringstream in(list);
    for (std::string name; std::getline(in, name, ',');) {
        if (name != "html" && name != "pdf" && name != "sheet")
            throw InputError("--format", "must be html, pdf or sheet, or a comma-separated list of them (got \"" + list + "\")");
        formats.insert(name);
    }
    if (formats.empty())
        throw InputError("--format", "names no format");
    return formats;
}

std::vector<fs::path> exportLesson(const Lesson& lesson, const EvaluatedLesson& evaluated,
                                   const LessonExportOptions& options,
                                   const std::function<void(const std::string&)>& step)
{
    if (options.width < 64 || options.height < 64 || options.width > 8192 || options.height > 8192)
        throw InputError("--size", "must be WxH with 64 <= W, H <= 8192");
    StagingFolder staging(options.out);
    std::vector<std::string> files;
    if (options.formats.count("html")) {
        writeLessonPage(lesson, evaluated, options, staging.path(), step);
        files.push_back("lesson.html");
    }
    const bool pdf = options.formats.count("pdf") > 0, sheet = options.formats.count("sheet") > 0;
    // The handout, the slides and the problem sheet, with the figures they are made of.
    const StepFigures figures =
        pdf || sheet ? writeStepFigures(lesson, evaluated, options, staging.path(), pdf, step) : StepFigures{};
    if (pdf) {
        step("handout.pdf");
        writeFileAtomically(staging.path() / "handout.tex", report::lessonHandoutLatex(lesson, figures.paper));
        compile(staging.path(), "handout");
        step("slides.pdf");
        writeFileAtomically(staging.path() / "slides.tex", report::lessonSlidesLatex(lesson, figures.slides));
        compile(staging.path(), "slides");
        files.insert(files.end(), {"handout.pdf", "slides.pdf"});
    }
    if (sheet) {
        step("sheet.pdf");
        writeFileAtomically(staging.path() / "sheet.tex", report::lessonSheetLatex(lesson, figures.paper));
        compile(staging.path(), "sheet");
        files.push_back("sheet.pdf");
    }
    return staging.commit(files);
}

std::vector<fs::path> packLessonInto(const Lesson& lesson, const std::string& lessonFileName, const fs::path& out)
{
    const LessonPack pack = packLesson(lesson, lessonFileName, out);
    StagingFolder staging(out);
    std::set<std::string> names; // what `out` gains: the lesson, scenes/, meshes/
    const auto target = [&](const fs::path& relative) {
        names.insert(relative.begin()->string());
        fs::create_directories((staging.path() / relative).parent_path());
        return staging.path() / relative;
    };
    try {
        for (const auto& [relative, text] : pack.texts)
            writeFileAtomically(target(relative), text);
        for (const auto& [relative, source] : pack.copies)
            fs::copy_file(source, target(relative));
    } catch (const std::exception& e) {
        throw InputError("--out", std::string("cannot write the pack: ") + e.what());
    }
    evaluateLesson(loadLesson(staging.path() / lessonFileName)); // only a pack that reads back, meshes too
    try {
        return staging.commit({names.begin(), names.end()});
    } catch (const fs::filesystem_error& e) {
        throw InputError("--out", std::string("cannot move the pack into place: ") + e.what());
    }
}

} // namespace viewpipe::gui
