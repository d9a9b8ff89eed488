#pragma once
// A lesson as files: lesson.html (one self-contained page, as the app shows
// the lesson), and on paper handout.pdf (each step the room it needs, the
// questions without their answers, the answer key at the end), slides.pdf
// (16:9, a question's answer on the slide after it) and sheet.pdf (the
// questions as a problem sheet, then their solutions worked out). The figures are the stages'
// vector figures through each step's camera; pdflatex sets the text and the math.
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "viewpipe/lesson.hpp"
#include "viewpipe/report/style.hpp"

namespace viewpipe::gui {

struct LessonExportOptions {
    std::filesystem::path out;
    std::set<std::string> formats = {"html"}; // html: lesson.html; pdf: handout.pdf and slides.pdf; sheet: sheet.pdf
    int width = 1280, height = 720;           // the pictures' (the PDF's figures too)
    report::Theme theme = report::Theme::Light;
};

// "pdf,html": a comma-separated list of html, pdf and sheet; throws InputError naming --format.
std::set<std::string> parseLessonFormats(const std::string& list);

// Writes the lesson in every format asked for, moved into `out` only once all
// are made (StagingFolder); returns the files. Throws InputError for a bad
// size or an `out` that cannot be made, and naming the step whose text
// pdflatex cannot set; std::runtime_error when pdflatex is missing or fails.
std::vector<std::filesystem::path> exportLesson(const Lesson& lesson, const EvaluatedLesson& evaluated,
                                                const LessonExportOptions& options,
                                                const std::function<void(const std::string&)>& step);

// Writes the lesson with the scenes and meshes it uses into `out` (packLesson),
// the lesson as `lessonFileName`, written into a staging folder (StagingFolder)
// and moved into place only once the lesson reads back from there with its meshes; returns what
// `out` gained (the lesson, scenes/, meshes/). Throws InputError naming --out
// when it cannot be written, or the file a step names that cannot be read.
std::vector<std::filesystem::path> packLessonInto(const Lesson& lesson, const std::string& lessonFileName,
                                                  const std::filesystem::path& out);

} // namespace viewpipe::gui
