#pragma once

#include <cctype>
#include <string>

#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

// Math written as plain text ("z_min", "x = +-z", a hyphen for a minus sign
// as in "-1") outside the text's math, or math the renderers cannot set.
inline bool plainTextMath(const std::string& text)
{
    std::string prose;
    try {
        viewpipe::mathRuns(text);
        for (const viewpipe::TextPart& part : viewpipe::mathTextParts(text))
            prose += part.math ? " " : part.text;
    } catch (const viewpipe::InputError&) {
        return true;
    }
    for (std::size_t k = 0; k < prose.size(); ++k) {
        const char c = prose[k], before = k ? prose[k - 1] : ' ', after = k + 1 < prose.size() ? prose[k + 1] : ' ';
        if (c == '_' || c == '^' || (c == '+' && after == '-') ||
            (c == '-' && std::string(" \t\n(,=").find(before) != std::string::npos && std::isalnum(static_cast<unsigned char>(after))))
            return true;
    }
    return false;
}
