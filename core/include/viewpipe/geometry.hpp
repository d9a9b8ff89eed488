#pragma once

// The built-in objects as plain vertex and face lists (world coordinates).

#include <array>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <vector>

#include "viewpipe/linalg.hpp"

namespace viewpipe {

// Polygons as one list of vertex indices and where each polygon starts: the
// layout of VTK's cell arrays and of index buffers, so that a drawing uses it
// without a copy (4 bytes an index, where a list per face took about 56 bytes
// more a face).
class FaceList {
public:
    // One face's vertex indices.
    class Face {
    public:
        Face(const int* first, const int* last) : first_(first), last_(last) {}
        const int* begin() const { return first_; }
        const int* end() const { return last_; }
        std::size_t size() const { return std::size_t(last_ - first_); }
        int operator[](std::size_t k) const { return first_[k]; }

    private:
        const int *first_, *last_;
    };
    class const_iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = Face;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = Face;
        const_iterator(const FaceList* list, std::size_t face) : list_(list), face_(face) {}
        Face operator*() const { return (*list_)[face_]; }
        const_iterator& operator++()
        {
            ++face_;
            return *this;
        }
        bool operator==(const const_iterator& other) const { return face_ == other.face_; }
        bool operator!=(const const_iterator& other) const { return face_ != other.face_; }

    private:
        const FaceList* list_;
        std::size_t face_;
    };

    FaceList() = default;
    FaceList(std::initializer_list<std::initializer_list<int>> faces)
    {
        for (const auto& face : faces)
            push_back(face);
    }

    // Appends a face: any range of vertex indices.
    template <class Indices> void push_back(const Indices& face)
    {
        for (const int index : face) // not insert(): there GCC 12 warns falsely of an overflow
            indices_.push_back(index);
        offsets_.push_back(int(indices_.size()));
    }
    void push_back(std::initializer_list<int> face) { push_back<std::initializer_list<int>>(face); }
    void reserve(std::size_t faces, std::size_t indices)
    {
        offsets_.reserve(faces + 1);
        indices_.reserve(indices);
    }

    std::size_t size() const { return offsets_.size() - 1; }
    bool empty() const { return size() == 0; }
    Face operator[](std::size_t f) const
    {
        return {indices_.data() + offsets_[f], indices_.data() + offsets_[f + 1]};
    }
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }
    // Where each face starts in indices(), and where the last one ends: size() + 1 entries from 0.
    const std::vector<int>& offsets() const { return offsets_; }
    const std::vector<int>& indices() const { return indices_; }

    bool operator==(const FaceList& other) const { return offsets_ == other.offsets_ && indices_ == other.indices_; }
    bool operator!=(const FaceList& other) const { return !(*this == other); }

private:
    std::vector<int> offsets_{0};
    std::vector<int> indices_;
};

struct PolygonMesh {
    std::vector<Vec3<double>> vertices;
    FaceList faces; // counter-clockwise seen from outside
};

// Foley's house: the front wall at z = 54 with vertices (0,0), (16,0), (16,10),
// (8,16), (0,10) in x, y; the same outline at z = 30; corresponding vertices
// joined.
inline PolygonMesh houseMesh()
{
    const std::array<std::array<double, 2>, 5> outline = {{{0, 0}, {16, 0}, {16, 10}, {8, 16}, {0, 10}}};
    PolygonMesh mesh;
    for (double z : {54.0, 30.0})
        for (const auto& xy : outline)
            mesh.vertices.emplace_back(xy[0], xy[1], z);
    mesh.faces.push_back({0, 1, 2, 3, 4});
    mesh.faces.push_back({9, 8, 7, 6, 5});
    for (int k = 0; k < 5; ++k) {
        const int next = (k + 1) % 5;
        mesh.faces.push_back({k, k + 5, next + 5, next});
    }
    return mesh;
}

inline PolygonMesh boxMesh(const Vec3<double>& lo, const Vec3<double>& hi)
{
    PolygonMesh mesh;
    for (int k = 0; k < 8; ++k)
        mesh.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    mesh.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return mesh;
}

} // namespace viewpipe
