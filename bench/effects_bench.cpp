// What each effect costs, as a ratio to the plain transform of the same
// vertices, on the default scene and on a mesh of 10^6 triangles, side by side:
//   build/bench/effects_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <vector>

#include "build_paths.h"
#include "viewpipe/effects.hpp"
#include "viewpipe/exact.hpp"
#include "viewpipe/scene.hpp"
#include "viewpipe/transform.hpp"

namespace {

using namespace viewpipe;

const Pipeline<double>& housePipeline()
{
    static const Pipeline<double> p =
        buildPipeline(loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json").camera);
    return p;
}

// A 500 x 1000 grid of quads, each cut into two triangles (10^6 triangles),
// spread through the default view volume.
const std::vector<PolygonMesh>& bigMesh()
{
    static const std::vector<PolygonMesh> mesh = [] {
        PolygonMesh m;
        const int nx = 501, ny = 1001;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                m.vertices.emplace_back(-30 + 60.0 * i / (nx - 1), -30 + 60.0 * j / (ny - 1), 30 + 20.0 * ((i + j) % 7) / 7);
        for (int j = 0; j + 1 < ny; ++j)
            for (int i = 0; i + 1 < nx; ++i) {
                const int a = j * nx + i;
                m.faces.push_back({a, a + 1, a + nx + 1});
                m.faces.push_back({a, a + nx + 1, a + nx});
            }
        return std::vector<PolygonMesh>{m};
    }();
    return mesh;
}

const std::vector<PolygonMesh>& house()
{
    static const std::vector<PolygonMesh> h = {houseMesh()};
    return h;
}

// The plain transform: every vertex through the clip matrix and the divide.
void Plain(benchmark::State& state, const std::vector<PolygonMesh>* objects)
{
    const Pipeline<double>& p = housePipeline();
    const Mat4<double> clip = p.clipMatrix();
    std::vector<double> in, out;
    for (const PolygonMesh& m : *objects)
        for (const Vec3<double>& v : m.vertices)
            in.insert(in.end(), {v.x(), v.y(), v.z()});
    out.resize(in.size());
    for (auto _ : state) {
        transformPoints(clip, in.data(), out.data(), in.size() / 3);
        benchmark::ClobberMemory();
    }
}

void Effect(benchmark::State& state, const std::vector<PolygonMesh>* objects, std::string name)
{
    const EffectList effects = withEffect({}, name, true);
    for (auto _ : state)
        benchmark::DoNotOptimize(runEffects(housePipeline(), *objects, effects));
}

// The same with the exact clip matrix at hand, as a scene listing clip or cull
// is evaluated: verdicts near a boundary are decided exactly.
void ExactEffect(benchmark::State& state, const std::vector<PolygonMesh>* objects, std::string name)
{
    const EffectList effects = withEffect({}, name, true);
    const Mat4<Exact> exactClip =
        exactPipeline(loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json")).clipMatrix();
    for (auto _ : state)
        benchmark::DoNotOptimize(runEffects(housePipeline(), *objects, effects, &exactClip));
}

} // namespace

BENCHMARK_CAPTURE(Plain, house, &house());
BENCHMARK_CAPTURE(Effect, house_clip, &house(), "clip");
BENCHMARK_CAPTURE(Effect, house_cull, &house(), "cull");
BENCHMARK_CAPTURE(ExactEffect, house_clip_exact, &house(), "clip");
BENCHMARK_CAPTURE(ExactEffect, house_cull_exact, &house(), "cull");
BENCHMARK_CAPTURE(Effect, house_depth, &house(), "depth");
BENCHMARK_CAPTURE(Effect, house_raster, &house(), "raster");
BENCHMARK_CAPTURE(Plain, mesh, &bigMesh())->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Effect, mesh_clip, &bigMesh(), "clip")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(Effect, mesh_cull, &bigMesh(), "cull")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(ExactEffect, mesh_clip_exact, &bigMesh(), "clip")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(ExactEffect, mesh_cull_exact, &bigMesh(), "cull")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(Effect, mesh_depth, &bigMesh(), "depth")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(Effect, mesh_raster, &bigMesh(), "raster")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_MAIN();
