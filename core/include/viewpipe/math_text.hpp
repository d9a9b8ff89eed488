#pragma once

// The math ViewPipe sets, one definition for every renderer: text with inline
// math between `$` signs (`\$` is a dollar sign), the math a small subset of
// LaTeX that KaTeX and pdflatex (with amsmath) read alike:
//   ASCII letters (in italics), digits and signs; groups `{…}`; scripts `_`
//   and `^` (one letter, group or command each, two levels deep at most);
//   \mathit \mathrm \operatorname \text \textrm{…}; \frac{a}{b}; \sqrt{a};
//   \left and \right in pairs before a delimiter; the Greek letters, signs,
//   spaces and function names of mathSubsetCommands() (docs/lesson-format.md).
// Renderers without TeX (VTK, SVG, Qt's rich text) draw the runs: each a piece
// of text in one style at one script level, signs as Unicode (a real minus).

#include <string>
#include <vector>

namespace viewpipe {

// How renderers without TeX set a script: its size, and how far its baseline
// drops (a subscript) or rises (a superscript), in sizes of the text around it.
constexpr double kScriptScale = 0.7;
constexpr double kSubscriptDrop = 0.2;
constexpr double kSuperscriptRise = 0.38;

struct MathRun {
    std::string text; // UTF-8
    bool italic = false;
    int level = 0; // 0 on the baseline, 1 a superscript, -1 a subscript, ±2 one deeper
    bool operator==(const MathRun& other) const
    {
        return text == other.text && italic == other.italic && level == other.level;
    }
};

// The text cut where its math begins and ends: prose (a `\$` in it now a
// dollar sign) and math (without its `$` signs), in order. Throws
// InputError(path, reason) for a `$` not closed.
struct TextPart {
    std::string text;
    bool math = false;
};
std::vector<TextPart> mathTextParts(const std::string& text, const std::string& path = "text");

// The text's runs, prose and math alike. Throws InputError(path, reason) for
// math outside the subset, braces that do not pair up, or a `$` not closed.
std::vector<MathRun> mathRuns(const std::string& text, const std::string& path = "text");

// The characters beyond ASCII that text may hold (outside math, or in
// \text{…}), each with the LaTeX that sets it: what the app, the page, the
// pictures (DejaVu Sans) and pdflatex all set. pdflatex sets Latin-1's letters
// (é, ü, ß; not Ð, Þ, ð, þ) through its own UTF-8 input, the rest as `latex`
// (texEscaped); CJK, emoji and the like are set by no output here.
struct TextSymbol {
    const char* utf8;
    const char* latex;
};
const std::vector<TextSymbol>& textSymbols();
// Throws InputError(path, reason) for a character that textSymbols() and
// Latin-1's letters do not hold, naming it and its code point.
void checkTextCharacters(const std::string& text, const std::string& path);

// Throws as mathRuns and checkTextCharacters do: what a reader of untrusted text (a lesson) checks.
void checkMathText(const std::string& text, const std::string& path);

// The runs as one line of Unicode text, scripts inline: what a plain-text
// medium (a window title, a terminal) shows.
std::string mathPlainText(const std::string& text);
// The runs as a screen reader should say them: scripts in words ("S sub per",
// "x squared", "45°"), not as "_" and "^".
std::string mathSpokenText(const std::string& text);

// The words of a line of text, split at spaces outside math: where it may wrap.
std::vector<std::string> mathTextWords(const std::string& line);

// The commands the subset has besides the font commands, \frac, \sqrt, \left and \right
// (docs/lesson-format.md lists them; a test keeps the two alike).
std::vector<std::string> mathSubsetCommands();

// A stage symbol as math (stageSymbolMath of its kind): "SH_per" -> "\mathit{SH}_{\mathrm{per}}"; a symbol
// no stage has is left as it is.
std::string symbolMath(const std::string& symbol);

} // namespace viewpipe
