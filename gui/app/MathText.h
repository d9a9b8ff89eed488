#pragma once

// A lesson's text (inline LaTeX math between `$` signs, `\$` a dollar sign) as
// Qt rich text: the math the lessons use set with HTML's italics, sub- and
// superscripts and Unicode signs, as KaTeX sets it on the web page.

#include <QString>

#include <string>

namespace viewpipe::gui {

QString mathHtml(const std::string& text);

} // namespace viewpipe::gui
