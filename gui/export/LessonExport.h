#pragma once
// A lesson on paper: handout.pdf (one A4 page per step, the questions without
// their answers, the answer key at the end) and slides.pdf (16:9, a question's
// answer on the slide after it). The figures are the stages' vector figures
// through each step's camera; pdflatex sets the text and the math.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/lesson.hpp"
#include "viewpipe/report/style.hpp"

namespace viewpipe::gui {

// `scenes[stepScenes[k]]` is step k's scene, evaluated and as the step shows it (shownAtStep). Both files are moved
// into `out` only once both are made; the figures are `width` x `height` pixels; throws std::runtime_error when pdflatex
// is missing or fails, InputError when `out` cannot be made.
std::vector<std::filesystem::path> exportLessonPdf(const Lesson& lesson, const std::vector<int>& stepScenes,
                                                   const std::vector<std::shared_ptr<const EvaluatedScene>>& scenes,
                                                   const std::filesystem::path& out, int width, int height, Theme theme,
                                                   const std::function<void(const std::string&)>& step);

} // namespace viewpipe::gui
