#include "viewpipe/math_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <map>
#include <utility>

#include "viewpipe/error.hpp"
#include "viewpipe/stage_kind.hpp"

namespace viewpipe {
namespace {

// Commands set as one sign or a space, as KaTeX sets them.
const std::map<std::string, std::string>& signs()
{
    static const std::map<std::string, std::string> table = {
        {"alpha", "α"},   {"beta", "β"},       {"gamma", "γ"},   {"delta", "δ"},     {"epsilon", "ε"},
        {"theta", "θ"},   {"lambda", "λ"},     {"mu", "μ"},      {"pi", "π"},        {"rho", "ρ"},
        {"sigma", "σ"},   {"tau", "τ"},        {"phi", "φ"},     {"omega", "ω"},     {"Delta", "Δ"},
        {"Theta", "Θ"},   {"Pi", "Π"},         {"Phi", "Φ"},     {"approx", " ≈ "},  {"cdot", " · "},
        {"times", " × "}, {"le", " ≤ "},       {"leq", " ≤ "},   {"ge", " ≥ "},      {"geq", " ≥ "},
        {"ne", " ≠ "},    {"neq", " ≠ "},      {"to", " → "},    {"rightarrow", " → "}, {"mapsto", " ↦ "},
        {"equiv", " ≡ "}, {"sim", " ∼ "},      {"in", " ∈ "},    {"infty", "∞"},     {"pm", "±"},
        {"mp", "∓"},      {"circ", "°"},       {"ldots", "…"},   {"dots", "…"},      {"cdots", "⋯"},
        {"perp", "⊥"},    {"parallel", "∥"},   {"prime", "′"},   {"quad", "  "},     {"qquad", "    "},
        {",", " "},       {";", " "},          {":", " "},       {"!", ""},          {"{", "{"},
        {"}", "}"},       {"$", "$"},          {"%", "%"},       {"_", "_"},         {"|", "‖"}};
    return table;
}

// Function names, set upright as written.
const std::vector<std::string>& functions()
{
    static const std::vector<std::string> names = {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos",
                                                   "arctan", "min", "max", "log", "ln", "exp", "det"};
    return names;
}

enum class Font { Default, Italic, Upright, Text };

// Reads math left to right into runs: a group up to its closing brace, scripts
// and commands with their arguments.
class MathReader {
public:
    MathReader(const std::string& math, const std::string& path, std::vector<MathRun>& runs)
        : math_(math), path_(path), runs_(runs)
    {
    }

    void read()
    {
        group(false, Font::Default, 0);
    }

private:
    // Deeper nesting than any lesson's math (a hostile file's thousands of braces) is refused.
    static constexpr int kMaxDepth = 40;

    [[noreturn]] void refuse(const std::string& reason) const
    {
        throw InputError(path_, "has math " + reason + ": $" + math_ + "$");
    }

    void add(const std::string& text, bool italic, int level)
    {
        if (text.empty())
            return;
        starting_ = false;
        if (!runs_.empty() && runs_.back().italic == italic && runs_.back().level == level)
            runs_.back().text += text;
        else
            runs_.push_back({text, italic, level});
    }

    void group(bool braced, Font font, int level)
    {
        starting_ = true;
        const int lefts = lefts_; // a \left closes in its own group, as TeX requires
        bool closed = false;
        while (at_ < math_.size() && !closed) {
            if (math_[at_] == '}') {
                if (!braced)
                    refuse("whose braces do not pair up");
                ++at_;
                closed = true;
            } else {
                item(font, level);
            }
        }
        if (braced && !closed)
            refuse("whose braces do not pair up");
        if (lefts_ != lefts)
            refuse("with a \\left and no \\right");
    }

    // One character, one braced group or one command with its arguments.
    void item(Font font, int level)
    {
        struct Deeper {
            explicit Deeper(int& depth) : depth_(depth) { ++depth_; }
            ~Deeper() { --depth_; }
            int& depth_;
        } deeper(depth_);
        if (depth_ > kMaxDepth)
            refuse("nested deeper than " + std::to_string(kMaxDepth) + " levels");
        const char c = math_[at_];
        if (c == '{') {
            ++at_;
            group(true, font, level);
        } else if (c == '_' || c == '^') {
            if (font == Font::Text)
                refuse("with a script in text");
            ++at_;
            skipSpaces();
            if (at_ >= math_.size() || math_[at_] == '}' || math_[at_] == '_' || math_[at_] == '^')
                refuse(std::string("with a ") + c + " that has nothing to set");
            if (c == '^' && math_.compare(at_, 5, "\\circ") == 0 &&
                (at_ + 5 == math_.size() || !std::isalpha(static_cast<unsigned char>(math_[at_ + 5])))) {
                add("°", false, level); // 45^\circ: the degree sign on the line
                at_ += 5;
            } else {
                const int scripted = level + (c == '^' ? 1 : -1);
                if (std::abs(scripted) > 2)
                    refuse("with scripts more than two levels deep");
                starting_ = true;
                item(font, scripted); // one letter, one group or one command, as TeX takes a script
            }
            skipSpaces();
            if (at_ < math_.size() && math_[at_] == c)
                refuse(std::string("with a double ") + (c == '^' ? "superscript" : "subscript"));
        } else if (c == '\\') {
            command(font, level);
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            add(std::string(1, c), font == Font::Default || font == Font::Italic, level);
            ++at_;
        } else if (c == '&' || c == '#' || c == '~' || c == '%') {
            refuse(std::string("with a ") + c + ", which the subset does not set");
        } else if (static_cast<unsigned char>(c) >= 0x80 && font != Font::Text) {
            refuse("with a character beyond ASCII (write \\pm for ±, \\le for ≤, \\alpha for α)");
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            if (font == Font::Text)
                add(" ", false, level);
            ++at_; // math ignores spaces; its own are commands
        } else if (font == Font::Text) {
            add(std::string(1, c), false, level);
            ++at_;
        } else {
            // Spaced as math spaces them: relations and sums on both sides, a comma after; z' with a prime, as
            // TeX sets it.
            static const std::map<char, std::string> spaced = {{'-', "−"},  {'=', " = "}, {'+', " + "}, {'<', " < "},
                                                               {'>', " > "}, {',', ", "}, {'\'', "′"}};
            const auto sign = spaced.find(c);
            std::string text = sign == spaced.end() ? std::string(1, c) : sign->second;
            if (c == '-' || c == '+') { // a sign, not a sum, at the start of math, a group or a script, or after an opening
                const bool unary = starting_ || runs_.empty() || runs_.back().text.empty() ||
                                   std::string("([{,=<> ").find(runs_.back().text.back()) != std::string::npos;
                text = c == '-' ? (unary ? "−" : " − ") : (unary ? "+" : " + ");
            }
            add(text, false, level);
            ++at_;
        }
    }

    void skipSpaces()
    {
        while (at_ < math_.size() && std::isspace(static_cast<unsigned char>(math_[at_])))
            ++at_;
    }

    // One argument of a command: a braced group or a single item.
    void argument(Font font, int level)
    {
        skipSpaces();
        if (at_ >= math_.size() || math_[at_] == '}')
            refuse("with a command that lacks its argument");
        starting_ = true;
        item(font, level);
    }

    void command(Font font, int level)
    {
        ++at_; // the backslash
        std::size_t end = at_;
        while (end < math_.size() && std::isalpha(static_cast<unsigned char>(math_[end])))
            ++end;
        if (end == at_ && end < math_.size())
            ++end; // a sign: \, \; \{
        const std::string name = math_.substr(at_, end - at_);
        at_ = end;
        if (name.empty())
            refuse("that ends in a backslash");
        if (font == Font::Text && std::isalpha(static_cast<unsigned char>(name[0])))
            refuse("with \\" + name + " in text (close the text first)");
        if (name == "mathit") {
            argument(Font::Italic, level);
        } else if (name == "mathrm" || name == "operatorname") {
            argument(Font::Upright, level);
        } else if (name == "text" || name == "textrm") {
            argument(Font::Text, level);
        } else if (name == "frac") { // on one line: a/b, (a + b)/c
            const std::vector<MathRun> top = captured(font, level), bottom = captured(font, level);
            addBracketed(top, level);
            add("/", false, level);
            addBracketed(bottom, level);
        } else if (name == "sqrt") { // an overline would run into the line above in a label
            add("√", false, level);
            addBracketed(captured(font, level), level);
        } else if (name == "left" || name == "right") {
            skipSpaces();
            const bool delimiter = at_ < math_.size() && (std::string("()[]|.").find(math_[at_]) != std::string::npos ||
                                                          (math_[at_] == '\\' && at_ + 1 < math_.size() &&
                                                           std::string("{}|").find(math_[at_ + 1]) != std::string::npos));
            if (!delimiter)
                refuse("with \\" + name + " not before a delimiter");
            if (name == "left")
                ++lefts_;
            else if (--lefts_ < 0)
                refuse("with a \\right and no \\left");
            if (math_[at_] == '.')
                ++at_; // the empty delimiter
        } else if (const auto sign = signs().find(name); sign != signs().end()) {
            add(sign->second, false, level);
        } else if (std::find(functions().begin(), functions().end(), name) != functions().end()) {
            add(name, false, level);
        } else {
            refuse("with \\" + name + ", which ViewPipe does not set (it sets the LaTeX subset docs/lesson-format.md lists)");
        }
    }

    // The runs of one argument, apart from those before it.
    std::vector<MathRun> captured(Font font, int level)
    {
        std::vector<MathRun> before;
        before.swap(runs_);
        argument(font, level);
        before.swap(runs_);
        return before;
    }

    // Runs in brackets unless they are one word or number.
    void addBracketed(const std::vector<MathRun>& runs, int level)
    {
        const bool simple = runs.size() == 1 && runs[0].text.size() < 16 &&
                            std::all_of(runs[0].text.begin(), runs[0].text.end(),
                                        [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '.'; });
        if (!simple)
            add("(", false, level);
        for (const MathRun& run : runs)
            add(run.text, run.italic, run.level);
        if (!simple)
            add(")", false, level);
    }

    const std::string& math_;
    const std::string& path_;
    std::vector<MathRun>& runs_;
    std::size_t at_ = 0;
    int depth_ = 0;
    int lefts_ = 0;         // \left not yet closed by \right
    bool starting_ = true;  // nothing set yet in this math, group or script: a minus here is a sign
};

} // namespace

std::vector<TextPart> mathTextParts(const std::string& text, const std::string& path)
{
    std::vector<TextPart> parts;
    std::string prose;
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text[k] == '\\' && k + 1 < text.size() && text[k + 1] == '$') {
            prose += '$';
            ++k;
        } else if (text[k] == '$') {
            std::size_t close = k + 1;
            while (close < text.size() && (text[close] != '$' || text[close - 1] == '\\'))
                ++close;
            if (close >= text.size())
                throw InputError(path, "has a $ that opens math and none that closes it (write \\$ for a dollar sign)");
            if (!prose.empty())
                parts.push_back({std::exchange(prose, {}), false});
            parts.push_back({text.substr(k + 1, close - k - 1), true});
            k = close;
        } else {
            prose += text[k];
        }
    }
    if (!prose.empty())
        parts.push_back({prose, false});
    return parts;
}

std::vector<MathRun> mathRuns(const std::string& text, const std::string& path)
{
    std::vector<MathRun> runs;
    for (const TextPart& part : mathTextParts(text, path)) {
        if (part.math)
            MathReader(part.text, path, runs).read();
        else if (!runs.empty() && !runs.back().italic && runs.back().level == 0)
            runs.back().text += part.text;
        else
            runs.push_back({part.text, false, 0});
    }
    return runs;
}

const std::vector<TextSymbol>& textSymbols()
{
    static const std::vector<TextSymbol> symbols = {
        // Greek: those like Latin capitals are set as them, as TeX sets them.
        {"α", "\\ensuremath{\\alpha}"}, {"β", "\\ensuremath{\\beta}"}, {"γ", "\\ensuremath{\\gamma}"},
        {"δ", "\\ensuremath{\\delta}"}, {"ε", "\\ensuremath{\\varepsilon}"}, {"ζ", "\\ensuremath{\\zeta}"},
        {"η", "\\ensuremath{\\eta}"}, {"θ", "\\ensuremath{\\theta}"}, {"ι", "\\ensuremath{\\iota}"},
        {"κ", "\\ensuremath{\\kappa}"}, {"λ", "\\ensuremath{\\lambda}"}, {"μ", "\\ensuremath{\\mu}"},
        {"ν", "\\ensuremath{\\nu}"}, {"ξ", "\\ensuremath{\\xi}"}, {"ο", "\\ensuremath{o}"},
        {"π", "\\ensuremath{\\pi}"}, {"ρ", "\\ensuremath{\\rho}"}, {"ς", "\\ensuremath{\\varsigma}"},
        {"σ", "\\ensuremath{\\sigma}"}, {"τ", "\\ensuremath{\\tau}"}, {"υ", "\\ensuremath{\\upsilon}"},
        {"φ", "\\ensuremath{\\varphi}"}, {"χ", "\\ensuremath{\\chi}"}, {"ψ", "\\ensuremath{\\psi}"},
        {"ω", "\\ensuremath{\\omega}"}, {"Α", "A"}, {"Β", "B"}, {"Γ", "\\ensuremath{\\Gamma}"},
        {"Δ", "\\ensuremath{\\Delta}"}, {"Ε", "E"}, {"Ζ", "Z"}, {"Η", "H"}, {"Θ", "\\ensuremath{\\Theta}"},
        {"Ι", "I"}, {"Κ", "K"}, {"Λ", "\\ensuremath{\\Lambda}"}, {"Μ", "M"}, {"Ν", "N"},
        {"Ξ", "\\ensuremath{\\Xi}"}, {"Ο", "O"}, {"Π", "\\ensuremath{\\Pi}"}, {"Ρ", "P"},
        {"Σ", "\\ensuremath{\\Sigma}"}, {"Τ", "T"}, {"Υ", "\\ensuremath{\\Upsilon}"},
        {"Φ", "\\ensuremath{\\Phi}"}, {"Χ", "X"}, {"Ψ", "\\ensuremath{\\Psi}"}, {"Ω", "\\ensuremath{\\Omega}"},
        // Signs and punctuation.
        {"±", "\\ensuremath{\\pm}"}, {"×", "\\ensuremath{\\times}"}, {"÷", "\\ensuremath{\\div}"},
        {"·", "\\ensuremath{\\cdot}"}, {"°", "\\ensuremath{^\\circ}"}, {"−", "\\ensuremath{-}"},
        {"≤", "\\ensuremath{\\le}"}, {"≥", "\\ensuremath{\\ge}"}, {"≠", "\\ensuremath{\\ne}"},
        {"≈", "\\ensuremath{\\approx}"}, {"≡", "\\ensuremath{\\equiv}"}, {"∼", "\\ensuremath{\\sim}"},
        {"→", "\\ensuremath{\\to}"}, {"←", "\\ensuremath{\\leftarrow}"}, {"↔", "\\ensuremath{\\leftrightarrow}"},
        {"⇒", "\\ensuremath{\\Rightarrow}"}, {"↦", "\\ensuremath{\\mapsto}"}, {"∞", "\\ensuremath{\\infty}"},
        {"√", "\\ensuremath{\\surd}"}, {"∈", "\\ensuremath{\\in}"}, {"∉", "\\ensuremath{\\notin}"},
        {"⊥", "\\ensuremath{\\perp}"}, {"∥", "\\ensuremath{\\parallel}"}, {"∘", "\\ensuremath{\\circ}"},
        {"∠", "\\ensuremath{\\angle}"}, {"′", "\\ensuremath{'}"}, {"″", "\\ensuremath{''}"},
        {"…", "\\ldots{}"}, {"–", "--"}, {"—", "---"}, {"‘", "`"}, {"’", "'"}, {"“", "``"}, {"”", "''"},
        {"•", "\\textbullet{}"},
        {"\u00a0", "~"},
    };
    return symbols;
}

void checkTextCharacters(const std::string& text, const std::string& path)
{
    for (std::size_t k = 0; k < text.size();) {
        const unsigned char lead = static_cast<unsigned char>(text[k]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        const std::string character = text.substr(k, length);
        k += length;
        if (length == 1)
            continue;
        char32_t code = lead & (length == 2 ? 0x1F : length == 3 ? 0x0F : 0x07);
        for (std::size_t b = 1; b < character.size(); ++b)
            code = (code << 6) | (static_cast<unsigned char>(character[b]) & 0x3F);
        // Latin-1's letters but Ð, Þ, ð, þ, which pdflatex's default (OT1) fonts lack.
        const bool latinLetter = code >= 0xC0 && code <= 0xFF && code != 0xD7 && code != 0xF7 && code != 0xD0 &&
                                 code != 0xDE && code != 0xF0 && code != 0xFE;
        const auto& symbols = textSymbols();
        if (latinLetter || std::any_of(symbols.begin(), symbols.end(), [&](const TextSymbol& s) { return character == s.utf8; }))
            continue;
        char codePoint[16];
        std::snprintf(codePoint, sizeof codePoint, "U+%04X", unsigned(code));
        throw InputError(path, "has the character " + character + " (" + codePoint +
                                   "), which not every output sets (the handout's pdflatex and the pictures' font have "
                                   "no glyph for it): write it in words, or as math");
    }
}

void checkMathText(const std::string& text, const std::string& path)
{
    mathRuns(text, path);
    checkTextCharacters(text, path);
}

std::string mathPlainText(const std::string& text)
{
    std::string out;
    for (const MathRun& run : mathRuns(text))
        out += run.level == 0 ? run.text
                              : (run.level < 0 ? "_" : "^") +
                                    (run.text.find_first_of(" +-/") == std::string::npos ? run.text : "(" + run.text + ")");
    return out;
}

std::string mathSpokenText(const std::string& text)
{
    // Neighbouring runs at one level are one script ("2n", not "2" then "n").
    std::vector<MathRun> runs;
    for (const MathRun& run : mathRuns(text))
        if (!runs.empty() && runs.back().level == run.level)
            runs.back().text += run.text;
        else
            runs.push_back(run);
    std::string out;
    for (const MathRun& run : runs) {
        if (run.level == 0)
            out += run.text;
        else if (run.level < 0)
            out += " sub " + run.text + " ";
        else if (run.text == "2")
            out += " squared ";
        else if (run.text == "3")
            out += " cubed ";
        else if (run.text == "−1")
            out += " inverse ";
        else
            out += " to the power " + run.text + " ";
    }
    // One space between words, none before punctuation.
    std::string spoken;
    for (std::size_t k = 0; k < out.size(); ++k) {
        const char c = out[k];
        if (c == ' ' && (spoken.empty() || spoken.back() == ' ' || spoken.back() == '(' ||
                         (k + 1 < out.size() && std::strchr(" ,.;:)", out[k + 1]))))
            continue;
        spoken += c;
    }
    while (!spoken.empty() && spoken.back() == ' ')
        spoken.pop_back();
    return spoken;
}

std::vector<std::string> mathTextWords(const std::string& line)
{
    std::vector<std::string> words(1);
    for (const TextPart& part : mathTextParts(line)) {
        if (part.math) {
            words.back() += "$" + part.text + "$";
            continue;
        }
        for (const char c : part.text)
            if (std::isspace(static_cast<unsigned char>(c))) {
                if (!words.back().empty())
                    words.emplace_back();
            } else {
                words.back() += c == '$' ? std::string("\\$") : std::string(1, c);
            }
    }
    if (words.back().empty())
        words.pop_back();
    return words;
}

std::vector<std::string> mathSubsetCommands()
{
    std::vector<std::string> names;
    for (const auto& [name, sign] : signs())
        names.push_back(name);
    names.insert(names.end(), functions().begin(), functions().end());
    return names;
}

std::string symbolMath(const std::string& symbol)
{
    const std::optional<StageKind> kind = stageKindNamed(symbol);
    return kind ? stageSymbolMath(*kind) : symbol;
}

} // namespace viewpipe
