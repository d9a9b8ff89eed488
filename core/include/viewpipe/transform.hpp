#pragma once

// Pushing many vertices through a 4x4 matrix with the homogeneous divide: the
// loop every precision tier is timed on. Points are x, y, z interleaved.

#include <cstddef>

#include "viewpipe/linalg.hpp"

namespace viewpipe {

template <class T> void transformPoints(const Mat4<T>& matrix, const T* in, T* out, std::size_t count)
{
    // Copy the entries into locals once: the loop then runs on registers.
    T m[4][4];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            m[r][c] = matrix(r, c);
    for (std::size_t i = 0; i < count; ++i) {
        const T x = in[3 * i], y = in[3 * i + 1], z = in[3 * i + 2];
        const T w = m[3][0] * x + m[3][1] * y + m[3][2] * z + m[3][3];
        const T inverse = T(1) / w;
        out[3 * i] = (m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3]) * inverse;
        out[3 * i + 1] = (m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3]) * inverse;
        out[3 * i + 2] = (m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3]) * inverse;
    }
}

} // namespace viewpipe
