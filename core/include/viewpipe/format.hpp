#pragma once

// Numbers for people: one format for every table, report and matrix the CLI
// and the export print.

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

} // namespace viewpipe
