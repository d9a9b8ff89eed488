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

#include "viewpipe/report/figure.hpp"
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

    // `dataOf` gives a mesh's poly data (shared with the world view);
    // `depthColored[k]`: object k's front faces with their depth levels, or null.
    void setScene(const EvaluatedScene& scene,
                  const std::function<vtkSmartPointer<vtkPolyData>(const std::shared_ptr<const PolygonMesh>&)>& dataOf,
                  const std::vector<vtkSmartPointer<vtkPolyData>>& depthColored);
    // Text `fontSize` pixels high, the caption and legend shrinking to `minFontSize` where room runs out.
    void applyStyle(report::Theme theme, int fontSize, int minFontSize);
    void setCaption(const std::string& text);
    void setTextVisible(bool visible);
    // Where its legend goes (layoutPicture).
    void setLegendPlace(report::LegendPlace place);

private:
    struct StyledActor {
        vtkSmartPointer<vtkActor> actor;
        Element element;
        bool surface;
    };
    struct Picture; // what the renderer's start callback lays out for the viewport's shape
    void clear();
    // The caption and legend laid out (layoutPicture) for the viewport; the room they leave the picture, in pixels.
    report::Box2 layOutText();

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
    report::Theme theme_ = report::Theme::Dark;
    int fontSize_ = 18, minFontSize_ = 18;
    double legendFontSize_ = 0; // the size the legend was last filled for; 0: to be filled
    report::LegendPlace legendPlace_ = report::LegendPlace::Best;
    report::PictureLayoutCache layoutCache_;
    std::string captionText_;
    bool textVisible_ = true;
};

} // namespace viewpipe::gui
