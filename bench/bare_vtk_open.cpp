// A bare VTK viewer opening a mesh, for bench/peak_memory.sh to set its peak memory beside the app's:
// two render windows about the size of the app's two views in `viewpipe open --screenshot` (1600x950),
// each showing the house's primitives and, given a PLY file, the mesh as VTK's reader reads it, drawn
// as the app draws a mesh (unlit, translucent); one frame each, then exit. The first window is framed
// as the app's world view opens; the second looks from the PRP through the window, about as the
// projected view shows it. Run under Xvfb:
//   bare_vtk_open [MESH.ply]

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <iostream>
#include <string>

#include "build_paths.h"
#include "painter/ScenePainter.h"
#include "painter/VtkGeometry.h"
#include "viewpipe/evaluated_scene.hpp"
#include "viewpipe/report/world_view.hpp"
#include "viewpipe/scene.hpp"

int main(int argc, char** argv)
{
    using namespace viewpipe;
    if (argc > 2) {
        std::cerr << "usage: bare_vtk_open [MESH.ply]\n";
        return 2;
    }
    const auto house = evaluateScene(loadScene(std::string(build::dataDir) + "/scenes/house.json"));
    vtkSmartPointer<vtkPolyData> mesh;
    if (argc == 2) {
        vtkNew<vtkPLYReader> reader;
        reader->SetFileName(argv[1]);
        reader->Update();
        mesh = reader->GetOutput();
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
        for (const Primitive& p : house->primitives) {
            vtkSmartPointer<vtkActor> actor = gui::unlitActor(gui::primitiveData(p));
            actor->GetProperty()->SetOpacity(p.opacity);
            renderer->AddActor(actor);
        }
        if (mesh) {
            vtkSmartPointer<vtkActor> actor = gui::unlitActor(mesh);
            actor->GetProperty()->SetOpacity(0.35);
            renderer->AddActor(actor);
        }
        if (view == 0) {
            WorldCamera camera;
            frameOn(camera, stageFraming(*house, 0), ViewFit{widths[view], height, {}, 1, Vec3<double>::Zero()});
            gui::setVtkCamera(renderer->GetActiveCamera(), camera);
        } else { // the house's view (VRC is world): from its PRP at its window, [-50, 50] across
            vtkCamera* camera = renderer->GetActiveCamera();
            camera->SetPosition(8, 6, 84);
            camera->SetFocalPoint(8, 6, 0);
            camera->UseHorizontalViewAngleOn();
            camera->SetViewAngle(2 * std::atan(50.0 / 84) * 180 / 3.14159265358979);
            renderer->ResetCameraClippingRange();
        }
        windows[view] = vtkSmartPointer<vtkRenderWindow>::New();
        windows[view]->SetSize(widths[view], height);
        windows[view]->AddRenderer(renderer);
        windows[view]->Render();
    }
}
