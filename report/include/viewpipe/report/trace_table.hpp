#pragma once

// A vertex traced through the stages, as the app's Matrices panel and the web
// page show it: the same texts in both. No Qt.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "viewpipe/exact.hpp"
#include "viewpipe/pipeline.hpp"

namespace viewpipe::report {

// A number in a table (the Matrices panel's, the trace's): its exact value as math ("$-\frac{1}{3}$") where
// `exact` is at hand and reads so, else five significant digits with minus signs (U+2212), not hyphens.
std::string tableCell(double x, const Exact* exact = nullptr);

struct TraceTable {
    struct Row {
        std::string stage;                // "world", or the stage's symbol as math ("$T(-\mathit{PRP})$")
        std::array<std::string, 4> cells; // x, y, z, w: each a tableCell
    };
    std::vector<Row> rows; // the world, then each stage up to `lastRow`
    // With every stage's row: the divided point and whether it is inside the canonical volume, as a
    // sentence ("After the divide: (…); inside the canonical volume."); empty otherwise.
    std::string verdict;
};

// `point` (as its file writes it: 0.1 is one tenth) after each stage of `pipeline`, rows up to stage
// `lastRow`; `exact`, the same pipeline computed exactly (exactPipeline), where at hand, gives the
// values that read exactly and decides inside or outside.
TraceTable traceTable(const Pipeline<double>& pipeline, const Pipeline<Exact>* exact, const Vec3<double>& point,
                      int lastRow);

} // namespace viewpipe::report
