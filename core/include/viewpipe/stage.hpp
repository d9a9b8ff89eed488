#pragma once

#include <string>
#include <vector>

#include "viewpipe/linalg.hpp"

namespace viewpipe {

// One step of a normalizing transformation: its symbol (a stable interface:
// "T(-VRP)", "SH_per", ...), a one-line explanation for people, its matrix.
template <class T> struct Stage {
    std::string symbol;
    std::string explanation;
    Mat4<T> matrix;
};

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

} // namespace viewpipe
