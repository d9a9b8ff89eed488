// `viewpipe lesson check FILE`, `viewpipe lesson export FILE --out DIR --format html,pdf` and
// `viewpipe lesson pack FILE --out DIR`.

#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "drawing_commands.hpp"
#include "export/LessonExport.h"
#include "export/VirtualDisplay.h"
#include "viewpipe/lesson.hpp"

namespace viewpipe::commands {
namespace {

namespace fs = std::filesystem;

struct LessonOptions {
    std::string file, out, format = "html", size = "1280x720", theme = "light";
    bool quiet = false;
};

int runExport(const LessonOptions& options)
{
    return guarded(options.file, "viewpipe lesson export", [&] {
        const Lesson lesson = loadLesson(options.file);
        gui::LessonExportOptions o;
        o.out = options.out;
        o.formats = gui::parseLessonFormats(options.format);
        std::tie(o.width, o.height) = parseSize(options.size, "--size");
        o.theme = options.theme == "dark" ? report::Theme::Dark : report::Theme::Light;
        const EvaluatedLesson evaluated = evaluateLesson(lesson);
        const gui::VirtualDisplay display;
        const auto files = gui::exportLesson(lesson, evaluated, o, [&](const std::string& what) {
            if (!options.quiet)
                std::cerr << what << "\n";
        });
        if (!options.quiet)
            for (const fs::path& file : files)
                std::cout << file.string() << "\n";
        return 0;
    });
}

} // namespace

void addLessonCommand(CLI::App& app)
{
    CLI::App* lesson = app.add_subcommand("lesson", "Check a lesson file, export it as a web page or as a handout and slides, or pack it to travel");
    lesson->require_subcommand(1);

    auto file = std::make_shared<std::string>();
    CLI::App* check = lesson->add_subcommand("check", "Validate a lesson; print nothing and exit 0 if it is valid");
    check->add_option("FILE", *file, "Lesson file (JSON, docs/lesson-format.md)")->required();
    setRun(check, [file] {
        return guarded(*file, "viewpipe: internal error", [&] {
            evaluateLesson(loadLesson(*file));
            return 0;
        });
    });

    auto options = std::make_shared<LessonOptions>();
    CLI::App* exportCommand = lesson->add_subcommand("export", "Write the lesson as one web page (lesson.html), as handout.pdf and slides.pdf, as a problem sheet (sheet.pdf), or any of them");
    exportCommand->add_option("FILE", options->file, "Lesson file (JSON)")->required();
    exportCommand->add_option("--out", options->out, "Folder for the files (created if missing)")->required();
    exportCommand->add_option("--format", options->format, "html: one self-contained page, lesson.html; pdf: handout.pdf and 16:9 slides.pdf; sheet: sheet.pdf, a problem sheet with worked solutions (pdf and sheet need pdflatex); or a comma-separated list")->capture_default_str();
    exportCommand->add_option("--size", options->size, "The pictures' size WxH, as export's (the PDF's figures too)")->capture_default_str();
    exportCommand->add_option("--theme", options->theme, "light or dark")
        ->check(CLI::IsMember({"light", "dark"}))
        ->capture_default_str();
    exportCommand->add_flag("--quiet", options->quiet, "Print nothing");
    setRun(exportCommand, [options] { return runExport(*options); });

    auto pack = std::make_shared<LessonOptions>();
    CLI::App* packCommand = lesson->add_subcommand("pack", "Write the lesson with the scenes and meshes it uses into one folder, paths relative to the lesson, to travel");
    packCommand->add_option("FILE", pack->file, "Lesson file (JSON)")->required();
    packCommand->add_option("--out", pack->out, "Folder for the lesson, scenes/ and meshes/ (created if missing)")->required();
    packCommand->add_flag("--quiet", pack->quiet, "Print nothing");
    setRun(packCommand, [pack] {
        return guarded(pack->file, "viewpipe lesson pack", [&] {
            const auto written = gui::packLessonInto(loadLesson(pack->file), fs::path(pack->file).filename().string(), pack->out);
            if (!pack->quiet)
                for (const fs::path& file : written)
                    std::cout << file.string() << "\n";
            return 0;
        });
    });
}

} // namespace viewpipe::commands
