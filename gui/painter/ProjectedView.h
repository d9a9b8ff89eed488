#pragma once

// The projected view: what the camera sees, the scene's objects through the
// normalizing transformation as VTK's camera (letterboxed to keep the window
// square), with the window's outline, the vanishing lines, the z-fighting
// ring and the raster effect's pixels over it, a caption and a legend.

#include <vtkSmartPointer.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "viewpipe/report/style.hpp"

class vtkActor;
class vtkActor2D;
class vtkCallbackCommand;
class vtkLegendBoxActor;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace viewpipe::gui {

class ProjectedView {
public:
    explicit ProjectedView(vtkRenderer* renderer);
    ~ProjectedView();
    ProjectedView(const ProjectedView&) = delete;
    ProjectedView& operator=(const ProjectedView&) = delete;

    // `depthColored[k]`: object k's front faces with their depth levels, or null.
    // `dataOf` gives a mesh's poly data (shared with the world view);
    // `depthColored[k]`: object k's front faces with their depth levels, or null.
    void setScene(const EvaluatedScene& scene, const std::function<vtkSmartPointer<vtkPolyData>(const PolygonMesh&)>& dataOf,
                  const std::vector<vtkSmartPointer<vtkPolyData>>& depthColored);
    void applyStyle(Theme theme, int fontSize);
    void setCaption(const std::string& text);
    void setTextVisible(bool visible);

private:
    struct StyledActor {
        vtkSmartPointer<vtkActor> actor;
        Element element;
        bool surface;
    };
    struct Picture; // what the renderer's start callback lays out for the viewport's shape
    void clear();

    vtkRenderer* renderer_;
    vtkSmartPointer<vtkTextActor> caption_;
    vtkSmartPointer<vtkActor2D> vanishing_;     // vanishing points and the lines meeting there
    vtkSmartPointer<vtkActor2D> rasterGrid_;    // the raster effect's pixels
    vtkSmartPointer<vtkActor2D> zFightingRing_; // around the z-fighting faces
    vtkSmartPointer<vtkLegendBoxActor> legend_;
    vtkSmartPointer<vtkCallbackCommand> layout_;
    std::unique_ptr<Picture> picture_;
    std::vector<StyledActor> actors_;
    std::vector<LegendEntry> entries_;
};

} // namespace viewpipe::gui
