#pragma once

#include <string>
#include <vector>

#include "viewpipe/linalg.hpp"
#include "viewpipe/math_text.hpp"
#include "viewpipe/stage_kind.hpp"

namespace viewpipe {

// One step of a normalizing transformation: its kind (which names it), a
// one-line explanation for people, its matrix. The divide, (x, y, z, w) ->
// (x/w, y/w, z/w, 1), is no matrix: such a stage `divides`, and its `matrix`
// is the identity (the point it gives is the same point of projective space:
// products of matrices are unchanged by it).
template <class T> struct Stage {
    StageKind kind;
    std::string explanation;
    Mat4<T> matrix;

    std::string symbol() const { return stageSymbol(kind); }
    bool divides() const { return stageDivides(kind); }
};

// How a dividing stage is written where a matrix would be.
inline const char* kDivideMapping = "(x, y, z, w) -> (x/w, y/w, z/w, 1)";

// Running products: element k is stages[k] * ... * stages[0].
template <class T> std::vector<Mat4<T>> cumulativeProducts(const std::vector<Stage<T>>& stages)
{
    std::vector<Mat4<T>> products;
    Mat4<T> running = Mat4<T>::Identity();
    for (const Stage<T>& stage : stages) {
        running = stage.matrix * running;
        products.push_back(running);
    }
    return products;
}

// The texts that name stage k of a pipeline for people, k = 0 being the world
// before any stage, with the symbols and formulas as math (math_text.hpp;
// mathPlainText for a terminal).
enum class StageText {
    ListEntry, // "0. World — the scene in world coordinates", "2. $R$ — rotate ...": the app's list of stages
    Caption,   // "World coordinates", "After $R$": over the picture of the world view
    Heading,   // "0. World coordinates", "2. $R$ – rotate ...": exported pictures
    Figure,    // "World coordinates", "$R$ – rotate ...": a figure in a document, which numbers it
};

template <class T> std::string stageText(const std::vector<Stage<T>>& stages, std::size_t k, StageText text)
{
    if (k == 0) {
        switch (text) {
        case StageText::ListEntry: return "0. World — the scene in world coordinates";
        case StageText::Caption: return "World coordinates";
        case StageText::Heading: return "0. World coordinates";
        case StageText::Figure: return "World coordinates";
        }
    }
    const Stage<T>& stage = stages[k - 1];
    const std::string number = std::to_string(k) + ". ";
    const std::string symbol = "$" + stageSymbolMath(stage.kind) + "$";
    switch (text) {
    case StageText::ListEntry: return number + symbol + " — " + stage.explanation;
    case StageText::Caption: return "After " + symbol;
    case StageText::Heading: return number + symbol + " – " + stage.explanation;
    case StageText::Figure: return symbol + " – " + stage.explanation;
    }
    return "";
}

} // namespace viewpipe
