#pragma once

// What differs between the graphics APIs beyond their projection matrices:
// how their documentation writes the matrix, how their math libraries store
// it, their viewport transforms, and a camera for one API that draws the same
// picture as a camera for another.

#include <array>
#include <string>

#include "viewpipe/gl.hpp"

namespace viewpipe::gl {

// Direct3D's documentation writes matrices for row vectors (p' = p M).
inline bool rowVectors(Api api)
{
    return api == Api::Direct3D;
}

// A column-vector matrix as the API's documentation writes it: Direct3D's
// (XMMatrixPerspectiveFovLH ...) is the transpose.
template <class T> Mat4<T> asDocumented(const Mat4<T>& columnVectorMatrix, Api api)
{
    return rowVectors(api) ? Mat4<T>(columnVectorMatrix.transpose()) : columnVectorMatrix;
}

// A column-vector matrix's 16 numbers in the order the APIs' usual math
// libraries keep them in memory: column by column for glm, simd and
// wgpu-matrix; DirectXMath keeps the row-vector matrix (the transpose) row by
// row, which is the same order.
template <class T> std::array<T, 16> memoryOrder(const Mat4<T>& columnVectorMatrix)
{
    std::array<T, 16> out;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            out[std::size_t(4 * c + r)] = columnVectorMatrix(r, c);
    return out;
}
// The library that memoryOrder describes for the API, and how it stores a matrix.
std::string memoryOrderLibrary(Api api);

// Normalized device coordinates to window (framebuffer) coordinates through
// the API's viewport transform for a width x height viewport at (0, 0) with
// its default depth range [0, 1]: OpenGL's origin at the bottom left, y up,
// window z = (z + 1)/2; the others' at the top left, y down, window z = z.
Vec3<double> windowCoordinates(Api api, const Vec3<double>& ndc, double width, double height);

// A camera for `api` with `handedness` and `depth` that draws the same picture
// as `camera`: the same window x and y (from the top left) and the same depth
// order. Across handedness the eye's x is mirrored, so left and right are
// negated (left > right: a gluPerspective camera becomes such a frustum).
Camera<double> convertCamera(const Camera<double>& camera, Api api, Handedness handedness, DepthMode depth);

} // namespace viewpipe::gl
