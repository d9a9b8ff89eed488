#pragma once

// The benchmarks' and tests' large mesh: a wavy sheet across the house's front, written
// as a binary PLY of 2 (n - 1)^2 triangles (n = 708: about 10^6).

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace viewpipe::bench {

// Writes the sheet with about `triangles` triangles to `file` (through a
// partial file renamed into place, so that an interrupted run leaves none).
inline void writeSheetMesh(const std::filesystem::path& file, long triangles)
{
    const int n = int(std::lround(std::sqrt(double(triangles) / 2))) + 1; // vertices along each side
    const std::filesystem::path partial = file.string() + ".partial";
    std::ofstream out(partial, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << n * n
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << 2L * (n - 1) * (n - 1)
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -4 + 24.0f * float(i) / float(n - 1), y = -2 + 20.0f * float(j) / float(n - 1);
            const float xyz[3] = {x, y, 58 + 1.5f * std::sin(x) * std::cos(y)};
            out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            for (const std::array<int, 3>& t : {std::array<int, 3>{a, b, d}, std::array<int, 3>{a, d, c}}) {
                const unsigned char three = 3;
                out.write(reinterpret_cast<const char*>(&three), 1);
                out.write(reinterpret_cast<const char*>(t.data()), sizeof(int) * 3);
            }
        }
    out.close();
    std::filesystem::rename(partial, file);
}

} // namespace viewpipe::bench
