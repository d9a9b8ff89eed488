// What precision costs, against peers, side by side in one run:
//   build/bench/accuracy_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Matrix building: viewpipe's gluLookAt and glFrustum against GLM's. Vertex
// transforms (with the homogeneous divide) over 10^6 points: every precision
// tier, VTK's vtkPerspectiveTransform::TransformPoints (the VTK transform that
// divides; vtkTransform treats a matrix as affine), a GLM loop, and a memcpy
// of the same bytes (the memory-bandwidth floor).

#include <benchmark/benchmark.h>

#define GLM_FORCE_CTOR_INIT
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPerspectiveTransform.h>
#include <vtkPoints.h>

#include <cstring>
#include <vector>

#include "viewpipe/accuracy.hpp"

namespace {

using namespace viewpipe;

constexpr std::size_t kVertices = 1000000;

const gl::Camera<double>& camera()
{
    static const gl::Camera<double> c{{{40, 30, 100}, {8, 8, 42}, {0, 1, 0}}, gl::Frustum<double>{-4, 4, -3, 3, 5, 80}};
    return c;
}

// Points inside the camera's view volume, x, y, z interleaved.
const std::vector<double>& points()
{
    static const std::vector<double> p = [] {
        std::vector<double> out;
        for (const Vec3<double>& q : pointsInside(gl::viewVolumeCorners(camera()), kVertices, 3))
            out.insert(out.end(), {q.x(), q.y(), q.z()});
        return out;
    }();
    return p;
}

Mat4<double> clipMatrix()
{
    return buildPipeline(CameraSpec<double>(camera())).composite;
}

void BuildViewpipeLookAtFrustum(benchmark::State& state)
{
    const auto& c = camera();
    for (auto _ : state) {
        Mat4<double> m = gl::projectionMatrix(c.projection) * gl::lookAt(c.lookAt);
        benchmark::DoNotOptimize(m);
    }
}

void BuildGlmLookAtFrustum(benchmark::State& state)
{
    const auto& c = camera();
    const auto& f = std::get<gl::Frustum<double>>(c.projection);
    const glm::dvec3 eye(c.lookAt.eye.x(), c.lookAt.eye.y(), c.lookAt.eye.z());
    const glm::dvec3 center(c.lookAt.center.x(), c.lookAt.center.y(), c.lookAt.center.z());
    const glm::dvec3 up(c.lookAt.up.x(), c.lookAt.up.y(), c.lookAt.up.z());
    for (auto _ : state) {
        glm::dmat4 m = glm::frustum(f.left, f.right, f.bottom, f.top, f.zNear, f.zFar) * glm::lookAt(eye, center, up);
        benchmark::DoNotOptimize(m);
    }
}

template <class T> void BuildPipelineTier(benchmark::State& state)
{
    const CameraSpec<T> spec = castCamera<T>(CameraSpec<double>(camera()));
    for (auto _ : state) {
        Pipeline<T> p = buildPipeline(spec);
        benchmark::DoNotOptimize(p);
    }
}

template <class T> void TransformTier(benchmark::State& state)
{
    const Mat4<T> m = clipMatrix().cast<T>();
    const std::vector<T> in(points().begin(), points().end());
    std::vector<T> out(in.size());
    for (auto _ : state) {
        transformPoints(m, in.data(), out.data(), kVertices);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

void TransformFloat128(benchmark::State& state)
{
    const Mat4<Float128> m = buildPipeline(castCamera<Float128>(CameraSpec<double>(camera()))).composite;
    const std::vector<Float128> in(points().begin(), points().end());
    std::vector<Float128> out(in.size());
    for (auto _ : state) {
        transformPoints(m, in.data(), out.data(), kVertices);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

void TransformDoubleDouble(benchmark::State& state)
{
    const Mat4DD m = toDoubleDouble(buildPipeline(castCamera<Float128>(CameraSpec<double>(camera()))).composite);
    std::vector<double> hi(points().size()), lo(points().size());
    for (auto _ : state) {
        transformPointsDoubleDouble(m, points().data(), hi.data(), lo.data(), kVertices);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

void TransformMpfr160(benchmark::State& state)
{
    setReferenceBits(160);
    const Mat4<Mpfr> m = buildPipeline(castCamera<Mpfr>(CameraSpec<double>(camera()))).composite;
    const std::size_t count = kVertices / 10; // a tenth, per item the same
    const std::vector<Mpfr> in(points().begin(), points().begin() + long(3 * count));
    std::vector<Mpfr> out(in.size());
    for (auto _ : state) {
        transformPoints(m, in.data(), out.data(), count);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * count));
}

void TransformVtkPerspective(benchmark::State& state)
{
    vtkNew<vtkPerspectiveTransform> transform;
    const Mat4<double> m = clipMatrix();
    double elements[16];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            elements[4 * r + c] = m(r, c);
    transform->SetMatrix(elements);
    vtkNew<vtkPoints> in, out;
    in->SetDataTypeToDouble();
    out->SetDataTypeToDouble();
    in->SetNumberOfPoints(vtkIdType(kVertices));
    std::memcpy(vtkDoubleArray::SafeDownCast(in->GetData())->GetPointer(0), points().data(), 24 * kVertices);
    for (auto _ : state) {
        out->Reset();
        transform->TransformPoints(in, out);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

void TransformGlm(benchmark::State& state)
{
    const Mat4<double> m = clipMatrix();
    glm::dmat4 g;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            g[c][r] = m(r, c); // GLM is column-major: g[column][row]
    const std::vector<double>& in = points();
    std::vector<double> out(in.size());
    for (auto _ : state) {
        for (std::size_t i = 0; i < kVertices; ++i) {
            const glm::dvec4 h = g * glm::dvec4(in[3 * i], in[3 * i + 1], in[3 * i + 2], 1.0);
            out[3 * i] = h.x / h.w;
            out[3 * i + 1] = h.y / h.w;
            out[3 * i + 2] = h.z / h.w;
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

void CopyBaseline(benchmark::State& state)
{
    const std::vector<double>& in = points();
    std::vector<double> out(in.size());
    for (auto _ : state) {
        std::memcpy(out.data(), in.data(), in.size() * sizeof(double));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * kVertices));
}

} // namespace

BENCHMARK(BuildViewpipeLookAtFrustum);
BENCHMARK(BuildGlmLookAtFrustum);
BENCHMARK(BuildPipelineTier<float>);
BENCHMARK(BuildPipelineTier<double>);
BENCHMARK(BuildPipelineTier<long double>);
BENCHMARK(BuildPipelineTier<Float128>);
BENCHMARK(CopyBaseline)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformTier<double>)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformVtkPerspective)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformGlm)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformTier<float>)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformTier<long double>)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformDoubleDouble)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformFloat128)->Unit(benchmark::kMillisecond);
BENCHMARK(TransformMpfr160)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
