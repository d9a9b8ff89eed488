#include "viewpipe/report/bench.hpp"

#include <algorithm>
#include <iomanip>

#include "viewpipe/format.hpp"

namespace viewpipe::report {

nlohmann::json benchJson(const BenchResult& result)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const BenchRow& r : result.rows) {
        const AccuracyMetrics& e = r.errors;
        rows.push_back({{"precision", r.precision},
                        {"bits", r.bits},
                        {"epsilon", r.epsilon},
                        {"build_ns", r.buildNs},
                        {"vertex_ns", r.vertexNs},
                        {"max_rel_error", e.maxRelativeError},
                        {"corner_error", e.cornerError},
                        {"orthogonality_error", e.orthogonalityError},
                        {"determinant_error", e.determinantError},
                        {"roundtrip_error", e.roundtripError},
                        {"ndc_max_error", e.ndcMaxError},
                        {"ndc_rms_error", e.ndcRmsError},
                        {"pixel_max_error", e.pixelMaxError},
                        {"pixel_rms_error", e.pixelRmsError}});
    }
    return {{"reference", result.reference},
            {"volume", result.volume},
            {"vertices", result.vertices},
            {"viewport", {result.viewport.width, result.viewport.height}},
            {"rows", rows}};
}

std::string errorCell(double error, double epsilon)
{
    if (epsilon == 0) // the exact type: no rounding, no unit
        return formatSignificant(error, 2);
    return formatSignificant(error, 2) + " [" + formatSignificant(error / epsilon, 2) + "]";
}

void printBench(std::ostream& out, const BenchResult& result)
{
    out << "Reference: " << result.reference << "; " << result.vertices << " vertices timed; pixel errors at "
        << result.viewport.width << "x" << result.viewport.height << ".\n"
        << "Corners and round trip: " << result.volume << ".\n"
        << "Errors are absolute, with units of the type's epsilon in brackets.\n\n";
    const std::vector<std::string> head = {"precision", "bits", "build ns", "ns/vertex", "max rel. error",
                                           "corner error", "|RR^T-I|", "|det R-1|", "round trip", "NDC max",
                                           "NDC rms", "pixel max"};
    std::vector<std::vector<std::string>> table = {head};
    for (const BenchRow& r : result.rows) {
        auto cell = [&r](double x) { return errorCell(x, r.epsilon); };
        const AccuracyMetrics& e = r.errors;
        table.push_back({r.precision, r.bits ? std::to_string(r.bits) : "-", formatSignificant(r.buildNs, 3),
                         formatSignificant(r.vertexNs, 3),
                         cell(e.maxRelativeError), cell(e.cornerError), cell(e.orthogonalityError),
                         cell(e.determinantError), cell(e.roundtripError), cell(e.ndcMaxError), cell(e.ndcRmsError),
                         formatSignificant(e.pixelMaxError, 2)});
    }
    std::vector<std::size_t> width(head.size(), 0);
    for (const auto& row : table)
        for (std::size_t c = 0; c < row.size(); ++c)
            width[c] = std::max(width[c], row[c].size());
    for (const auto& row : table) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out << (c ? "  " : "") << (c == 0 ? std::left : std::right) << std::setw(int(width[c])) << row[c];
        out << std::right << "\n";
    }
}

} // namespace viewpipe::report
