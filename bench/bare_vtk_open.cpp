// A bare VTK viewer opening a mesh, for bench/peak_memory.sh to set its peak memory beside the app's:
// two render windows about the size of the app's two views in `viewpipe open --screenshot` (1600x950),
// each showing the house's primitives and, given a PLY file, the mesh as VTK's reader reads it, drawn
// as the app draws a mesh (unlit, translucent); one frame each, then exit. The first window is framed
// as the app's world view opens; the second looks from the PRP through the window, about as the
// projected view shows it. Run under Xvfb:
//   bare_vtk_open [MESH.ply]

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cmath>
#include <iostream>
#include <string>
#include <variant>

#include "bare_vtk.h"
#include "build_paths.h"
#include "painter/ScenePainter.h"
#include "viewpipe/report/world_view.hpp"
#include "viewpipe/scene.hpp"

int main(int argc, char** argv)
{
    using namespace viewpipe;
    if (argc > 2) {
        std::cerr << "usage: bare_vtk_open [MESH.ply]\n";
        return 2;
    }
    const Scene scene = loadScene(std::string(build::dataDir) + "/scenes/house.json");
    const auto house = evaluateScene(scene);
    vtkSmartPointer<vtkPolyData> mesh;
    if (argc == 2) {
        mesh = bench::readWithVtk(argv[1]);
        if (mesh->GetNumberOfPolys() == 0) {
            std::cerr << "bare_vtk_open: no faces read from " << argv[1] << "\n";
            return 2;
        }
    }
    // The world view and the projected view, as wide as the app's at 1600x950.
    const int widths[] = {490, 296}, height = 905;
    vtkSmartPointer<vtkRenderWindow> windows[2];
    for (int view = 0; view < 2; ++view) {
        vtkNew<vtkRenderer> renderer;
        for (const auto& actor : bench::primitiveActors(*house))
            renderer->AddActor(actor);
        if (mesh) {
            vtkSmartPointer<vtkActor> actor = gui::unlitActor(mesh);
            actor->GetProperty()->SetOpacity(0.35);
            renderer->AddActor(actor);
        }
        if (view == 0) {
            report::WorldCamera camera;
            report::frameOn(camera, report::stageFraming(*house, 0), report::ViewFit{widths[view], height, {}, 1, Vec3<double>::Zero()});
            gui::setVtkCamera(renderer->GetActiveCamera(), camera);
        } else { // from the PRP at the window's center, the window's width across (the house's VRC is world)
            const auto& spec = std::get<foley::ViewSpec<double>>(scene.camera);
            const Vec3<double> prp = spec.prp;
            vtkCamera* camera = renderer->GetActiveCamera();
            camera->SetPosition(prp.data());
            camera->SetFocalPoint(prp.x(), prp.y(), 0);
            camera->UseHorizontalViewAngleOn();
            camera->SetViewAngle(2 * std::atan(0.5 * (spec.window.umax - spec.window.umin) / prp.z()) * 180 / M_PI);
            renderer->ResetCameraClippingRange();
        }
        windows[view] = vtkSmartPointer<vtkRenderWindow>::New();
        windows[view]->SetSize(widths[view], height);
        windows[view]->AddRenderer(renderer);
        windows[view]->Render();
    }
}
