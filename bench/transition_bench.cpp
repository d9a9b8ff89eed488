// Stage transitions: the real time of one transition frame of the app's
// painter (the world view with every element, labels and legend included)
// against a bare VTK loop that renders the same poly data for every element
// (built once, outside the timing) moved by user matrices, for the house and
// for the house beside a 10^6-triangle mesh, side by side at the same window
// size. Also opening the mesh scene and jumping five stages. Run under Xvfb:
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/bench/transition_bench --benchmark_repetitions=3

#include <benchmark/benchmark.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include "bare_vtk.h"
#include "build_paths.h"
#include "faces_drawn.h"
#include "sheet_mesh.h"
#include "painter/EigenVtk.h"
#include "painter/MeshDetail.h"
#include "painter/ScenePainter.h"
#include "painter/VtkGeometry.h"
#include "viewpipe/animation.hpp"

namespace {

using namespace viewpipe;
namespace fs = std::filesystem;

constexpr int kWindow = 800;
constexpr int kFramesPerStep = 10; // transition frames timed in a step

Scene house()
{
    return loadScene(std::string(viewpipe::build::dataDir) + "/scenes/house.json");
}

// The wavy sheet of about 10^6 triangles across the house's front, written once.
fs::path millionTriangleMesh()
{
    const fs::path file = fs::temp_directory_path() / "viewpipe-bench-mesh-1m.ply";
    if (!fs::exists(file))
        bench::writeSheetMesh(file, 1'000'000);
    return file;
}

Scene withMesh()
{
    Scene scene = house();
    SceneObject mesh;
    mesh.type = ObjectType::Mesh;
    mesh.resolvedPath = millionTriangleMesh();
    mesh.path = mesh.resolvedPath.string();
    scene.objects.push_back(mesh);
    return scene;
}

Scene sceneNamed(const std::string& name)
{
    return name == "house" ? house() : withMesh();
}

struct Window {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    Window()
    {
        window->SetOffScreenRendering(1);
        window->SetSize(kWindow, kWindow);
        window->AddRenderer(renderer);
    }
};

// The app's world view of a scene, framed at the world stage as the app opens it.
struct AppView : Window {
    gui::ScenePainter painter{renderer, nullptr};
    std::shared_ptr<const EvaluatedScene> scene;
    explicit AppView(const std::string& name) : scene(evaluateScene(sceneNamed(name)))
    {
        painter.setScene(scene);
        painter.resetView();
        window->Render();
    }
    // Moving, as Play is, once the decimated copies of large meshes are made (off the timing).
    void startMoving()
    {
        const vtkIdType full = facesDrawn(renderer);
        painter.setMoving(true);
        for (int tries = 0; tries < 600; ++tries) {
            window->Render();
            if (full < vtkIdType(gui::MeshDetail::kLargeFaces) || facesDrawn(renderer) < full / 2)
                return;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
};

// The app playing through every stage, as Play does: kFramesPerStep frames a step.
class PlayThrough {
public:
    explicit PlayThrough(AppView& view) : view_(view) {}
    bool startsStep() const { return frame_ == 0; }
    // Makes the step's transition (its framing of the whole motion).
    void prepare() { transition_.emplace(*view_.scene, step_, step_ + 1); }
    // Shows the next frame; call prepare() first at the start of a step.
    void next()
    {
        view_.painter.showMoment(transition_->at(double(++frame_) / kFramesPerStep));
        if (frame_ == kFramesPerStep) {
            frame_ = 0;
            step_ = (step_ + 1) % int(view_.scene->pipeline.stages.size());
        }
    }
    int frameCount() const { return int(view_.scene->pipeline.stages.size()) * kFramesPerStep; }

private:
    AppView& view_;
    std::optional<report::StageMotion> transition_;
    int step_ = 0, frame_ = 0;
};

// A frame of Play, between stages: large meshes drawn from their decimated copies.
void appFrame(benchmark::State& state, const std::string& name)
{
    AppView w(name);
    w.startMoving();
    PlayThrough play(w);
    for (auto _ : state) {
        if (play.startsStep()) {
            state.PauseTiming();
            play.prepare();
            state.ResumeTiming();
        }
        play.next();
        w.window->Render();
    }
}

// The app's frame at rest, every stage in turn: full detail.
void appAtRest(benchmark::State& state, const std::string& name)
{
    AppView w(name);
    const auto& stages = w.scene->pipeline.stages;
    int stage = 0;
    for (auto _ : state) {
        state.PauseTiming();
        w.painter.showMoment(report::stageAtRest(*w.scene, stage));
        stage = (stage + 1) % int(stages.size());
        state.ResumeTiming();
        w.window->Render();
    }
}

// What the app's world view shows at one frame: its camera and the stage's matrix.
struct Shot {
    vtkNew<vtkCamera> camera;
    vtkSmartPointer<vtkMatrix4x4> matrix;
};

// The bare loop replays the app's frames: the same poly data, camera and matrices, one actor per primitive.
void bareVtkFrame(benchmark::State& state, const std::string& name)
{
    AppView app(name);
    PlayThrough play(app);
    std::vector<std::unique_ptr<Shot>> shots;
    for (int k = 0; k < play.frameCount(); ++k) {
        if (play.startsStep())
            play.prepare();
        play.next();
        auto shot = std::make_unique<Shot>();
        shot->camera->DeepCopy(app.renderer->GetActiveCamera());
        shot->matrix = vtkSmartPointer<vtkMatrix4x4>::New();
        vtkActorCollection* actors = app.renderer->GetActors();
        actors->InitTraversal();
        while (vtkActor* actor = actors->GetNextActor())
            if (actor->GetUserMatrix())
                shot->matrix->DeepCopy(actor->GetUserMatrix());
        shots.push_back(std::move(shot));
    }

    Window w;
    const std::vector<vtkSmartPointer<vtkActor>> actors = bench::primitiveActors(*app.scene);
    for (const auto& actor : actors)
        w.renderer->AddActor(actor);
    std::size_t frame = 0;
    for (auto _ : state) {
        const Shot& shot = *shots[frame++ % shots.size()];
        w.renderer->GetActiveCamera()->DeepCopy(shot.camera);
        for (const auto& actor : actors)
            actor->SetUserMatrix(shot.matrix);
        w.window->Render();
    }
}

// Opening a scene in the app, as File > Open does: reading the scene and its mesh, evaluating it,
// building the props and the first frame, in the window the app already shows (the house in it).
void openScene(benchmark::State& state, const std::string& name)
{
    const Scene scene = sceneNamed(name);
    AppView w("house");
    for (auto _ : state) {
        w.painter.setScene(evaluateScene(scene));
        w.painter.resetView();
        w.window->Render(); // one frame, as the app draws on opening (the captions' room framed in it)
        // Untimed: the decimated copy made on the other core, then the house again, as at the start.
        state.PauseTiming();
        w.startMoving();
        w.painter.setMoving(false);
        w.painter.setScene(w.scene);
        w.painter.resetView();
        w.window->Render();
        state.ResumeTiming();
    }
}

// The same in a new window, as `viewpipe open` starts: the window's OpenGL context made and its
// shaders compiled as well.
void openSceneInANewWindow(benchmark::State& state, const std::string& name)
{
    const Scene scene = sceneNamed(name);
    for (auto _ : state) {
        auto w = std::make_unique<Window>();
        auto painter = std::make_unique<gui::ScenePainter>(w->renderer, nullptr);
        painter->setScene(evaluateScene(scene));
        painter->resetView();
        w->window->Render();
        // Untimed: closing waits for the decimated copy still being made on the other core, which the
        // open scene does not wait for.
        state.PauseTiming();
        painter.reset();
        w.reset();
        state.ResumeTiming();
    }
}

// Reading the scene's mesh and evaluating the scene, no drawing: what VTK's reader alone does, and the evaluation.
void readScene(benchmark::State& state, const std::string& name)
{
    const Scene scene = sceneNamed(name);
    for (auto _ : state)
        benchmark::DoNotOptimize(evaluateScene(scene)->meshes.size());
}

// VTK's own reader on the scene's mesh file.
void vtkReaderOpen(benchmark::State& state, const std::string&)
{
    const std::string file = millionTriangleMesh().string();
    for (auto _ : state)
        benchmark::DoNotOptimize(bench::readWithVtk(file)->GetNumberOfPolys());
}

// What a bare VTK viewer does to open the file, for a like-for-like ratio with Open/app: VTK's
// reader, an actor drawn as the app draws a mesh (unlit, translucent), the camera reset and the
// first frame, in a window already showing the house's primitives.
void vtkReaderOpenAndDraw(benchmark::State& state, const std::string&)
{
    const std::string file = millionTriangleMesh().string();
    const auto houseScene = evaluateScene(house());
    Window w;
    for (const Primitive& p : houseScene->primitives)
        w.renderer->AddActor(gui::unlitActor(gui::primitiveData(p)));
    w.window->Render();
    for (auto _ : state) {
        vtkSmartPointer<vtkActor> actor = gui::unlitActor(bench::readWithVtk(file));
        actor->GetProperty()->SetOpacity(0.35);
        w.renderer->AddActor(actor);
        w.renderer->ResetCamera();
        w.window->Render();
        // Untimed, as in Open/app: the mesh let go and the house alone again, as at the start.
        state.PauseTiming();
        w.renderer->RemoveActor(actor);
        actor = nullptr;
        w.window->Render();
        state.ResumeTiming();
    }
}

// From stage 5 to the world, one step at a time as the app does: each step's
// transition made and its last frame drawn (the animation's frames between
// are Frame/app's; the app gives each step 600 ms).
void jumpFiveStages(benchmark::State& state, const std::string& name)
{
    AppView w(name);
    for (auto _ : state) {
        state.PauseTiming();
        w.painter.showMoment(report::stageAtRest(*w.scene, 5));
        w.window->Render();
        state.ResumeTiming();
        for (int stage = 5; stage > 0; --stage) {
            w.painter.showMoment(report::StageMotion(*w.scene, stage, stage - 1).at(1));
            w.window->Render();
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    for (const std::string name : {"house", "mesh_1m"}) {
        benchmark::RegisterBenchmark(("Frame/app/" + name).c_str(), appFrame, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("Frame/bare_vtk/" + name).c_str(), bareVtkFrame, name)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    benchmark::RegisterBenchmark("AtRest/app/mesh_1m", appAtRest, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark("Open/app/mesh_1m", openScene, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::RegisterBenchmark("OpenNewWindow/app/mesh_1m", openSceneInANewWindow, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::RegisterBenchmark("Read/app/mesh_1m", readScene, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::RegisterBenchmark("Open/vtk_reader/mesh_1m", vtkReaderOpen, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::RegisterBenchmark("OpenAndDraw/bare_vtk/mesh_1m", vtkReaderOpenAndDraw, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::RegisterBenchmark("JumpFiveStages/app/mesh_1m", jumpFiveStages, std::string("mesh_1m"))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(3);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
