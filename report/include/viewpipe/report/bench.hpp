#pragma once

// The precision ladder's results (viewpipe/precision_ladder.hpp) as the JSON
// object of `viewpipe bench --json` and as its table.

#include <nlohmann/json.hpp>

#include <ostream>

#include "viewpipe/precision_ladder.hpp"

namespace viewpipe::cli {

nlohmann::json benchJson(const BenchResult& result);
void printBench(std::ostream& out, const BenchResult& result);

} // namespace viewpipe::cli
