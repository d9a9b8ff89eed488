#include "MathText.h"

#include <QHash>
#include <QRegularExpression>

#include <cctype>

namespace viewpipe::gui {
namespace {

const QHash<QString, QString>& signs()
{
    static const QHash<QString, QString> table = {
        {"alpha", "α"},  {"beta", "β"},   {"gamma", "γ"},   {"delta", "δ"},  {"epsilon", "ε"}, {"theta", "θ"},
        {"lambda", "λ"}, {"mu", "μ"},     {"pi", "π"},      {"rho", "ρ"},    {"sigma", "σ"},   {"tau", "τ"},
        {"phi", "φ"},    {"omega", "ω"},  {"Delta", "Δ"},   {"Theta", "Θ"},  {"Pi", "Π"},      {"Phi", "Φ"},
        {"approx", "≈\u200b"}, {"cdot", "·\u200b"},   {"times", "×\u200b"},   {"le", "≤"},     {"leq", "≤"},     {"ge", "≥"},
        {"geq", "≥"},    {"ne", "≠"},     {"neq", "≠"},     {"to", "→"},     {"rightarrow", "→"}, {"mapsto", "↦"},
        {"infty", "∞"},  {"pm", "±"},     {"circ", "°"},    {"ldots", "…"},  {"dots", "…"},    {"cdots", "⋯"},
        {"in", "∈"},     {"quad", "\u2003"}, {"qquad", "\u2003\u2003"}, {",", "\u2009"}, {";", "\u2005"},
        {":", "\u2005"}, {"!", ""},       {"{", "{"},       {"}", "}"},      {"$", "$"},       {"%", "%"},
        {"left", ""},    {"right", ""},   {"|", "‖"},       {"lvert", "|"},  {"rvert", "|"},   {"equiv", "≡"},
        {"sim", "∼"},    {"perp", "⊥"},   {"parallel", "∥"}, {"prime", "′"}};
    return table;
}

// Reads math left to right: a group up to its closing brace, scripts and commands with their arguments.
class MathReader {
public:
    explicit MathReader(const QString& math) : math_(math) {}
    QString read() { return group(false); }

private:
    // Nesting deeper than any lesson's math (a hostile file's thousands of braces) is shown as written.
    static constexpr int kMaxDepth = 50;
    struct Deeper {
        explicit Deeper(int& depth) : depth_(depth) { ++depth_; }
        ~Deeper() { --depth_; }
        int& depth_;
    };
    QString rest()
    {
        const QString written = math_.mid(at_).toHtmlEscaped();
        at_ = int(math_.size());
        return written;
    }

    QString group(bool braced)
    {
        const Deeper deeper(depth_);
        if (depth_ > kMaxDepth)
            return rest();
        QString out;
        while (at_ < math_.size()) {
            const QChar c = math_[at_];
            if (c == '}') {
                ++at_;
                if (braced)
                    return out;
                continue;
            }
            if (c == '{') {
                ++at_;
                out += group(true);
            } else if (c == '_' || c == '^') {
                ++at_;
                const QString script = argument();
                out += script == "°" ? script : QString(c == '_' ? "<sub>%1</sub>" : "<sup>%1</sup>").arg(script);
            } else if (c == '\\') {
                out += command();
            } else if (c.isLetter()) {
                int end = at_;
                while (end < math_.size() && math_[end].isLetter())
                    ++end;
                out += "<i>" + math_.mid(at_, end - at_) + "</i>";
                at_ = end;
            } else if (c == '-') {
                out += "−";
                ++at_;
            } else if (c == '<' || c == '>' || c == '&') {
                out += QString(c).toHtmlEscaped();
                ++at_;
            } else if (c.isSpace()) {
                ++at_; // math ignores spaces; its own are commands
            } else {
                // Spaced as math spaces them: relations and sums both sides, a comma after.
                out += (c == '=' || c == '+') ? QString("\u2009%1\u2009").arg(c) : c == ',' ? QString(", ") : QString(c);
                if (c == '=' || c == '+')
                    out += "\u200b"; // a line may break here, as KaTeX breaks long math
                ++at_;
            }
        }
        return out;
    }

    // One character or one braced group or one command, as a script or an argument takes it.
    QString argument()
    {
        while (at_ < math_.size() && math_[at_].isSpace())
            ++at_;
        if (at_ >= math_.size())
            return {};
        const QChar c = math_[at_];
        if (c == '{') {
            ++at_;
            return group(true);
        }
        if (c == '\\')
            return command();
        ++at_;
        return c.isLetter() ? "<i>" + QString(c) + "</i>" : QString(c).toHtmlEscaped();
    }

    // Text as written (no italics): \mathrm{per}, \text{ if }.
    QString upright()
    {
        QString plain = argument();
        return plain.remove("<i>").remove("</i>");
    }

    QString command()
    {
        const Deeper deeper(depth_);
        if (depth_ > kMaxDepth)
            return rest();
        ++at_; // the backslash
        int end = at_;
        while (end < math_.size() && math_[end].isLetter())
            ++end;
        if (end == at_ && end < math_.size())
            ++end; // a sign: \, \; \{
        const QString name = math_.mid(at_, end - at_);
        at_ = end;
        if (name == "mathit" || name == "mathbf")
            return "<i>" + upright() + "</i>";
        if (name == "mathrm" || name == "text" || name == "operatorname" || name == "textrm")
            return upright();
        if (name == "frac") {
            const QString top = argument(), bottom = argument();
            auto simple = [](const QString& s) { return !s.contains(' ') && !s.contains("−") && s.size() < 16; };
            return (simple(top) ? top : "(" + top + ")") + "/" + (simple(bottom) ? bottom : "(" + bottom + ")");
        }
        if (name == "sqrt") { // an overline would run into the line above in a label
            const QString radicand = argument();
            return radicand.size() == 1 || !radicand.contains(QRegularExpression("\\W")) ? "√" + radicand : "√(" + radicand + ")";
        }
        const auto sign = signs().constFind(name);
        if (sign != signs().constEnd())
            return *sign;
        return name; // \arctan, \sin, \max: the function's name, upright
    }

    QString math_;
    int at_ = 0;
    int depth_ = 0;
};

} // namespace

QString mathHtml(const std::string& text)
{
    const QString all = QString::fromStdString(text);
    QString out, part;
    bool math = false;
    for (int k = 0; k < all.size(); ++k) {
        if (all[k] == '\\' && k + 1 < all.size() && all[k + 1] == '$') {
            part += math ? "\\$" : "$";
            ++k;
        } else if (all[k] == '$') {
            out += math ? MathReader(part).read() : part.toHtmlEscaped();
            part.clear();
            math = !math;
        } else {
            part += all[k];
        }
    }
    return out + (math ? ("$" + part).toHtmlEscaped() : part.toHtmlEscaped());
}

} // namespace viewpipe::gui
