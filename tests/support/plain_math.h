#pragma once

#include <regex>
#include <string>

#include "viewpipe/error.hpp"
#include "viewpipe/math_text.hpp"

// Math written as plain text ("z_min", "x = +-z", a hyphen for a minus sign
// as in "-1") outside the text's math, or math the renderers cannot set.
inline bool plainTextMath(const std::string& text)
{
    try {
        viewpipe::mathRuns(text);
    } catch (const viewpipe::InputError&) {
        return true;
    }
    std::string prose;
    bool math = false;
    for (std::size_t k = 0; k < text.size(); ++k)
        if (text[k] == '$' && (k == 0 || text[k - 1] != '\\'))
            math = !math;
        else if (!math)
            prose += text[k];
    static const std::regex plain(R"(_|\^|\+-|(^|[\s(,=])-[0-9A-Za-z])");
    return std::regex_search(prose, plain);
}
