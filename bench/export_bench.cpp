// Export speed: `viewpipe export` of every stage of Foley's house at
// 1920x1080 PNG against a bare VTK program that renders the same geometry
// (the painter's props, moved by vtkProp3D::SetUserMatrix on the GPU) to the
// same number of PNG files. Run both in one process, side by side:
//   xvfb-run -a build/bench/export_bench --benchmark_repetitions=5

#include <benchmark/benchmark.h>

#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkProp3D.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <filesystem>

#include "build_paths.h"
#include "export/Exporter.h"
#include "painter/EigenVtk.h"
#include "viewpipe/animation.hpp"

namespace {

using namespace viewpipe;
namespace fs = std::filesystem;

const Scene& house()
{
    static const Scene scene = loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json");
    return scene;
}

fs::path scratch(const char* name)
{
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void ViewpipeExport(benchmark::State& state)
{
    const fs::path out = scratch("viewpipe-bench-export");
    gui::ExportOptions options;
    options.out = out;
    options.width = 1920;
    options.height = 1080;
    const std::atomic<bool> cancel{false};
    const auto scene = evaluateScene(house());
    for (auto _ : state)
        benchmark::DoNotOptimize(gui::exportStages(scene, options, {}, cancel));
    fs::remove_all(out);
}

void BareVtk(benchmark::State& state)
{
    const fs::path out = scratch("viewpipe-bench-bare");
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(1920, 1080);
    vtkNew<vtkRenderer> renderer;
    renderer->UseFXAAOn();
    window->AddRenderer(renderer);
    gui::ScenePainter painter(renderer, nullptr); // only builds the same props
    painter.setTheme(report::Theme::Light);
    painter.setScene(evaluateScene(house()));
    window->Render();
    painter.resetView();
    const std::vector<Stage<double>> stages = buildPipeline(house().camera).stages;
    for (auto _ : state) {
        for (std::size_t k = 0; k <= stages.size(); ++k) {
            const auto matrix = gui::toVtk(cumulativeAt(stages, double(k)));
            vtkPropCollection* props = renderer->GetViewProps();
            props->InitTraversal();
            while (vtkProp* prop = props->GetNextProp())
                if (auto* prop3d = vtkProp3D::SafeDownCast(prop))
                    prop3d->SetUserMatrix(matrix);
            renderer->ResetCamera();
            window->Render();
            vtkNew<vtkWindowToImageFilter> grab;
            grab->SetInput(window);
            grab->ReadFrontBufferOff();
            vtkNew<vtkPNGWriter> writer;
            writer->SetInputConnection(grab->GetOutputPort());
            writer->SetFileName((out / ("stage-" + std::to_string(k) + ".png")).c_str());
            writer->Write();
        }
    }
    fs::remove_all(out);
}

} // namespace

BENCHMARK(ViewpipeExport)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BareVtk)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
