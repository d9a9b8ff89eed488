#pragma once

// The precision ladder's results (viewpipe/precision_ladder.hpp) as the JSON
// object of `viewpipe bench --json` and as its table.

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "viewpipe/precision_ladder.hpp"

namespace viewpipe::report {

nlohmann::json benchJson(const BenchResult& result);
void printBench(std::ostream& out, const BenchResult& result);
// An absolute error with its size in units of epsilon in brackets, as the table and the app's panel show it.
std::string errorCell(double error, double epsilon);

} // namespace viewpipe::report
