#pragma once

// Stage matrices as LaTeX bmatrix environments, ready to paste into slides.
// The scene's numbers are taken as the decimals written in the file and the
// pipeline is evaluated with 100-digit MPFR; an entry that agrees with a
// fraction of denominator at most 10^9 to 60 digits is printed as that exact
// fraction (glOrtho's 1/25 and -3/2), any other entry as a decimal.

#include <array>
#include <string>
#include <vector>

#include "viewpipe/scene.hpp"

namespace viewpipe::report {

// Every stage in symbols (stage_symbols.hpp) and in numbers with the product
// so far, the composite and z_min: a fragment for a document that loads amsmath.
std::string matricesLatex(const Scene& scene, int digits);
// The same as a document of its own (matrices.tex) that also \inputs into a
// document loading the standalone package.
std::string matricesDocument(const Scene& scene, int digits);

// One stage's matrix (stage >= 1) as "symbol = \begin{bmatrix}...\end{bmatrix}", the
// `highlighted` entries (row, column from 1) on a colored box (needs xcolor).
std::string stageLatex(const Scene& scene, int stage, int digits, const std::vector<std::array<int, 2>>& highlighted = {});

// The same without its symbol: the matrix alone (the divide's mapping as stageLatex's).
std::string stageMatrixLatex(const Scene& scene, int stage, int digits);
// Each stage's equation (as stageLatex) and the product of the stages so far.
struct StageLatex {
    std::string equation, cumulative;
};
std::vector<StageLatex> stagesLatex(const Scene& scene, int digits);

// An exact value as the textbook writes it (-\frac{13}{36}, \frac{\sqrt{2}}{2}) where it reads so
// (Exact::readsExactly), else a decimal to `digits` significant digits (1.5 \times 10^{-7}).
std::string exactLatex(const Exact& x, int digits);

// Entry (row, column), from 1, of stage `stage`'s matrix: an exact fraction where it is one, else a decimal.
std::string entryLatex(const Scene& scene, int stage, int row, int column, int digits);

// A point (world coordinates) after each of the first `stages` stages, as
// "(x, y, z, w)" math with exact fractions where they are ones (after the
// divide, divided by w); the first is the point itself, w = 1.
std::vector<std::string> tracedLatex(const Scene& scene, const Vec3<Exact>& point, int stages, int digits);

} // namespace viewpipe::report
