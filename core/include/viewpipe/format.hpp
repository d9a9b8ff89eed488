#pragma once

// Numbers for people: one format for every table, report and matrix the CLI,
// the export and the app's panels print.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace viewpipe {

// x with `digits` significant digits, as printf's %g writes it (1.5e-07 for
// small numbers); -0 is written 0.
inline std::string formatSignificant(double x, int digits)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x == 0 ? 0.0 : x);
    return buffer;
}

// The fewest digits that read back as x, written out in full unless that
// takes more than three zeros after the point or five before it, else with an
// exponent as %g writes it (1e-05, 1.5e+07); -0 is written 0, infinities "inf".
inline std::string formatShortest(double x)
{
    if (x == 0)
        return "0";
    if (!std::isfinite(x))
        return std::isnan(x) ? "nan" : x < 0 ? "-inf" : "inf";
    // fmt's shortest round trip (the same digits in the browser's build), as digits and a decimal point.
    const std::string text = fmt::format("{}", std::fabs(x));
    const std::size_t e = std::min(text.find('e'), text.size());
    const std::string mantissa = text.substr(0, e);
    const std::size_t dot = std::min(mantissa.find('.'), mantissa.size());
    int point = int(dot) + (e < text.size() ? std::stoi(text.substr(e + 1)) : 0); // digits before the point
    std::string digits = mantissa.substr(0, dot) + (dot < mantissa.size() ? mantissa.substr(dot + 1) : "");
    for (; digits.size() > 1 && digits.front() == '0'; --point)
        digits.erase(0, 1);
    while (digits.size() > 1 && digits.back() == '0')
        digits.pop_back();
    const std::string sign = x < 0 ? "-" : "";
    const int count = int(digits.size());
    if (point <= -4 || point > count + 5) {
        const int exponent = point - 1;
        return sign + digits.substr(0, 1) + (count > 1 ? "." + digits.substr(1) : "") + fmt::format("e{:+03d}", exponent);
    }
    if (point <= 0)
        return sign + "0." + std::string(std::size_t(-point), '0') + digits;
    if (point >= count)
        return sign + digits + std::string(std::size_t(point - count), '0');
    return sign + digits.substr(0, std::size_t(point)) + "." + digits.substr(std::size_t(point));
}

// x as the decimal it was written as (formatShortest), in a wider type:
// a scene's "0.1" as one tenth, not as 0.1000000000000000055...
template <class T> T fromDecimal(double x)
{
    return T(formatShortest(x));
}

} // namespace viewpipe
