#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "build_paths.h"
#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

using namespace viewpipe;

namespace {

std::string refusal(const std::string& text, const std::string& path)
{
    try {
        checkMathText(text, path);
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), path);
        return e.reason();
    }
    return "";
}

} // namespace

TEST(MathText, SetsScriptsItalicsAndSigns)
{
    // As TeX sets $z = z_{\min}$: italic letters, an upright subscript one level down.
    const std::vector<MathRun> zmin = {{"z", true, 0}, {" = ", false, 0}, {"z", true, 0}, {"min", false, -1}};
    EXPECT_EQ(mathRuns("$z = z_{\\min}$"), zmin);
    // The stage symbol SH_per, and prose around math.
    const std::vector<MathRun> shear = {{"4. ", false, 0}, {"SH", true, 0}, {"per", false, -1}, {" shears", false, 0}};
    EXPECT_EQ(mathRuns("4. $\\mathit{SH}_{\\mathrm{per}}$ shears"), shear);
    // A real minus sign: unary after an opening or a relation, spaced between terms; ± and ≤ as signs.
    EXPECT_EQ(mathRuns("$T(-\\mathit{VRP})$")[1].text, "(−");
    EXPECT_EQ(mathPlainText("$x = -z$"), "x = −z");
    EXPECT_EQ(mathPlainText("$z' = (w - z)/2$"), "z′ = (w − z)/2"); // a prime, not an apostrophe
    EXPECT_EQ(mathPlainText("$a - b$"), "a − b");
    EXPECT_EQ(mathPlainText("$x = \\pm z$, $-1 \\le z$"), "x = ±z, −1 ≤ z");
    EXPECT_EQ(mathPlainText("$x^2$"), "x^2");
    // For a screen reader: scripts in words.
    EXPECT_EQ(mathSpokenText("$\\mathit{SH}_{\\mathrm{per}}$, then $S_{\\mathrm{per}}$."), "SH sub per, then S sub per.");
    EXPECT_EQ(mathSpokenText("($x^2$ and $M^{-1}$)"), "(x squared and M inverse)");
    EXPECT_EQ(mathSpokenText("$45^\\circ$ and $z^{n}$"), "45° and z to the power n");
    EXPECT_EQ(mathSpokenText("$x^{2n}$, $z^{n+1}$"), "x to the power 2n, z to the power n + 1");
    EXPECT_EQ(mathPlainText("costs \\$5"), "costs $5");
    EXPECT_EQ(mathPlainText("$\\text{if } x$"), "if x");
}

TEST(MathText, RefusesWhatItDoesNotSetNamingTheField)
{
    EXPECT_NE(refusal("see $\\foo{x}$", "steps[0].caption").find("\\foo"), std::string::npos);
    EXPECT_NE(refusal("$x_{1$", "steps[1].prompt").find("braces"), std::string::npos);
    EXPECT_NE(refusal("$x = 1", "steps[2].caption").find("closes"), std::string::npos);
    EXPECT_NE(refusal("$a & b$", "x").find("&"), std::string::npos);
    EXPECT_NE(refusal("$x_$", "x").find("nothing"), std::string::npos);
    EXPECT_NE(refusal("$\\begin{bmatrix}1\\end{bmatrix}$", "x").find("\\begin"), std::string::npos);
    EXPECT_NE(refusal("$" + std::string(5000, '{') + "$", "x").find("deeper"), std::string::npos);
    EXPECT_EQ(refusal("$\\frac{1}{2} \\cdot \\sqrt{3} \\approx \\arctan x$", "x"), "");
}

// One definition of a lesson's text: what every output sets (textSymbols, Latin-1's letters) is taken,
// in prose and in \text{…}; what none sets here is refused with its field and code point.
TEST(MathText, TakesTheCharactersEveryOutputSetsAndNoOther)
{
    EXPECT_EQ(refusal("Char α here, ≠ and ≤, é, ü, ß, Å: $\\text{β}$", "steps[0].caption"), "");
    for (const TextSymbol& symbol : textSymbols())
        EXPECT_EQ(refusal(std::string("a ") + symbol.utf8 + " b", "x"), "") << symbol.utf8;
    EXPECT_NE(refusal("Char 日 here", "steps[2].caption").find("has the character 日 (U+65E5)"), std::string::npos);
    EXPECT_NE(refusal("🙂", "x").find("(U+1F642)"), std::string::npos);
    EXPECT_NE(refusal("$\\text{日}$", "x").find("(U+65E5)"), std::string::npos);
    EXPECT_NE(refusal("þ", "x").find("(U+00FE)"), std::string::npos); // pdflatex's default fonts lack it
    EXPECT_NE(refusal("✓", "x").find("(U+2713)"), std::string::npos);
}

TEST(MathText, ScriptsAreSetAsTexSetsThem)
{
    // A minus opening a script is a sign: 10^{-6} is "10" and a tight "−6" above it.
    const std::vector<MathRun> power = {{"10", false, 0}, {"−6", false, 1}};
    EXPECT_EQ(mathRuns("$10^{-6}$"), power);
    EXPECT_EQ(mathPlainText("$z_{\\min} - 1$"), "z_min − 1"); // after a script, a difference
    // A script takes one letter, as TeX's does: x^ab is x^a b.
    const std::vector<MathRun> oneLetter = {{"x", true, 0}, {"a", true, 1}, {"b", true, 0}};
    EXPECT_EQ(mathRuns("$x^ab$"), oneLetter);
    EXPECT_EQ(refusal("$x^a^b$", "x").find("double superscript") != std::string::npos, true);
    EXPECT_EQ(refusal("$x^{a^{b^c}}$", "x").find("two levels") != std::string::npos, true);
    EXPECT_EQ(refusal("$\\left( x$", "x").find("\\right") != std::string::npos, true);
    EXPECT_EQ(refusal("$x \\right)$", "x").find("\\left") != std::string::npos, true);
    EXPECT_EQ(refusal("$\\left\\alpha x \\right)$", "x").find("delimiter") != std::string::npos, true);
    EXPECT_EQ(refusal("$\\text{\\alpha}$", "x").find("in text") != std::string::npos, true);
    EXPECT_EQ(refusal("$x = é$", "x").find("beyond ASCII") != std::string::npos, true);
    EXPECT_EQ(refusal("$\\left( \\frac{1}{2} \\right)$ and $\\text{né}$", "x"), "");
}

// docs/lesson-format.md lists every command of the subset, so that an author can read what is set.
TEST(MathText, TheLessonFormatListsTheSubset)
{
    std::ifstream in(std::string(viewpipe::build::dataDir) + "/../docs/lesson-format.md");
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(doc.empty());
    for (const std::string& command : mathSubsetCommands())
        EXPECT_NE(doc.find("\\" + command), std::string::npos) << "\\" << command;
}

TEST(MathText, StageSymbolsAreMath)
{
    EXPECT_EQ(symbolMath("SH_per"), "\\mathit{SH}_{\\mathrm{per}}");
    EXPECT_EQ(symbolMath("T(-VRP)"), "T(-\\mathit{VRP})");
    EXPECT_EQ(symbolMath("R"), "R");
    // An API as people name it; a subscript of two words, words apart.
    EXPECT_EQ(symbolMath("NDC_direct3d"), "\\mathit{NDC}_{\\mathrm{Direct3D}}");
    EXPECT_EQ(symbolMath("NDC_reversed"), "\\mathit{NDC}_{\\mathrm{reversed}}");
    EXPECT_EQ(symbolMath("NDC_vulkan_reversed"), "\\mathit{NDC}_{\\text{Vulkan, reversed}}");
    EXPECT_EQ(mathPlainText("$" + symbolMath("NDC_vulkan_reversed") + "$"), "NDC_(Vulkan, reversed)");
    EXPECT_EQ(mathSpokenText("$" + symbolMath("NDC_webgpu_reversed") + "$"), "NDC sub WebGPU, reversed");
}
