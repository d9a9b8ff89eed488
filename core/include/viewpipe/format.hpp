#pragma once

// Numbers for people: one format for every table, report and matrix the CLI,
// the export and the app's panels print.

#include <charconv>
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
    char buffer[64];
    const std::string scientific(buffer,
                                 std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific).ptr);
    if (!std::isfinite(x))
        return scientific;
    const std::size_t sign = x < 0 ? 1 : 0, e = scientific.find('e');
    std::string digits;
    for (std::size_t i = sign; i < e; ++i)
        if (scientific[i] != '.')
            digits += scientific[i];
    const int point = std::stoi(scientific.substr(e + 1)) + 1; // digits before the point, written out
    const int count = int(digits.size());
    if (point <= -4 || point > count + 5)
        return scientific;
    std::string full;
    if (point <= 0)
        full = "0." + std::string(std::size_t(-point), '0') + digits;
    else if (point >= count)
        full = digits + std::string(std::size_t(point - count), '0');
    else
        full = digits.substr(0, std::size_t(point)) + "." + digits.substr(std::size_t(point));
    return (sign ? "-" : "") + full;
}

} // namespace viewpipe
