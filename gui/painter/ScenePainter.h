#pragma once

// Draws a viewing set-up with VTK (no Qt): the scene's objects, the WRC axes,
// the VRC axes, the PRP, the window and CW, the direction of projection, the
// view volume with its front and back planes, the projectors, and the
// canonical volume. Every element is kept in world coordinates and shown
// through one cumulative matrix (with the homogeneous divide), so everything
// moves together. A legend in a corner of each view names the colors of what
// the scene shows. One painter serves the app, screenshots and exports.

#include <vtkSmartPointer.h>

#include <optional>
#include <string>
#include <vector>

#include "viewpipe/geometry.hpp"
#include "viewpipe/scene.hpp"
#include "viewpipe/setup.hpp"

class vtkActor;
class vtkActor2D;
class vtkBillboardTextActor3D;
class vtkLegendBoxActor;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace viewpipe::gui {

enum class Theme { Dark, Light };
class ScenePainter;

struct Rgb {
    double r, g, b;
};

// Everything the painter draws, so that callers can style or look them up.
// Frame: the axes of the coordinates the current stage maps into, fixed on
// screen (not transformed), so that a stage's motion reads against them.
// Vanishing: the vanishing points and the edges drawn on to them (projected
// view). ZFighting: faces the depth buffer cannot order.
enum class Element {
    Objects, WorldAxes, ViewAxes, Prp, Window, Dop, Volume, FrontPlane, BackPlane, Projectors, Canonical, Frame,
    Vanishing, ZFighting, Traced
};

// Reads every mesh of a scene (the core's reader); throws InputError naming
// "objects[k].path" for one that cannot be read.
void checkMeshes(const Scene& scene);

// Every vertex of the scene's objects, in world coordinates.
std::vector<Vec3<double>> objectVertices(const Scene& scene);

// The scene's objects as polygon meshes, for effects.
std::vector<PolygonMesh> objectMeshes(const Scene& scene);

// The box around them (empty for a scene without objects).
Eigen::AlignedBox<double, 3> objectBounds(const Scene& scene);

// The scene's objects alone (faces and edges, as the painter styles them),
// added to each renderer (meshes read once); for pictures that need no
// set-up around them.
void addObjectActors(const std::vector<vtkRenderer*>& renderers, const Scene& scene, Theme theme);

class ScenePainter {
public:
    // `projected` may be null: then no projected view is drawn.
    ScenePainter(vtkRenderer* world, vtkRenderer* projected);
    ~ScenePainter();
    ScenePainter(const ScenePainter&) = delete;
    ScenePainter& operator=(const ScenePainter&) = delete;

    // Builds the picture of a scene. Reads its meshes (throws InputError naming
    // "objects[k].path" for one that cannot be read; the previous picture stays).
    void setScene(const Scene& scene);

    // Shows every element through `cumulative`; the canonical volume's outline
    // is drawn with the given opacity (0 hides it).
    void show(const Mat4<double>& cumulative, double canonicalOpacity);

    // Shows or hides every text: labels and captions.
    void setTextVisible(bool visible);

    // Titles in the top-left corners of the two views.
    void setCaptions(const std::string& world, const std::string& projected);
    std::string worldCaption() const;

    // Marks the vertex being traced (world coordinates) in the world view, or none.
    void markTraced(const std::optional<Vec3<double>>& point);

    void setTheme(Theme theme);
    void setFontSize(int points);
    // Line widths are multiplied by this (2 for a picture at twice the pixels).
    void setLineScale(double scale);
    Theme theme() const { return theme_; }

    // Where the world view's camera looks and how much it must see.
    struct Framing {
        Vec3<double> center = Vec3<double>::Zero();
        double radius = 1;
    };
    // What framing shows every element as it would be through `cumulative`
    // (the canonical outline included when `withCanonical`).
    Framing framingOf(const std::vector<Mat4<double>>& cumulatives, bool withCanonical) const;
    // Aims the world view's camera at a framing, keeping the user's
    // direction, zoom and pan; frame() fits what is shown now; resetView()
    // restores the default viewpoint.
    void frameOn(const Framing& framing);
    void frame();
    void resetView();
    // Call when the user has moved the camera, to keep that change in frame().
    void rememberUserCamera();

    // The original (world) coordinates of the object vertex under a display
    // position of the world view, if any.
    std::optional<Vec3<double>> pickVertex(int displayX, int displayY) const;

    // One line per listed effect, as shown at the bottom of the world view:
    // what it found (clip counts, culled faces, depth bands, raster coverage).
    const std::string& effectsNote() const { return effectsNote_; }
    // What the scene's effects found, computed once per setScene.
    const EffectOutcomes& effectOutcomes() const { return outcomes_; }

    // Colors from the Okabe-Ito palette where meanings must not be confused
    // (DOP, vanishing lines, z-fighting), readable by colorblind people.
    static Rgb color(Element element, Theme theme);
    static Rgb faceColor(Theme theme);
    // An element's color: objects' surfaces take faceColor, everything else color.
    static Rgb styledColor(Element element, bool surface, Theme theme);
    static Rgb background(Theme theme, bool projectedView);

private:
    struct Layer;
    struct Label;
    struct LegendEntry;
    void clear();
    void addLayer(Element element, vtkSmartPointer<vtkPolyData> geometry, bool surface, double opacity);
    void addLabel(Element element, const std::string& text, const Vec3<double>& world);
    void applyStyle();
    // Shows a layer's points or a label's anchor through the cumulative matrix (hidden without an image).
    void placeLayer(Layer& layer, const Mat4<double>& cumulative);
    void placeLabel(Label& label, const Mat4<double>& cumulative);
    // Fills a view's legend with its entries, at the painter's font size, in
    // the view's top-right (below the caption) or bottom-right corner.
    void fillLegend(vtkLegendBoxActor* legend, vtkRenderer* renderer, const std::vector<LegendEntry>& entries,
                    bool top);
    using Segment = std::pair<Vec3<double>, Vec3<double>>;
    void setUpProjectedView(const Scene& scene, const Pipeline<double>& pipeline, const std::vector<Segment>& edges,
                            const RasterOutcome* raster, const std::vector<Vec3<double>>& fighting);
    double fitDistance(double radius) const;

    vtkRenderer* world_;
    vtkRenderer* projected_;
    vtkSmartPointer<vtkTextActor> worldCaption_;
    vtkSmartPointer<vtkTextActor> projectedCaption_;
    vtkSmartPointer<vtkTextActor> effectsCaption_;
    std::string effectsNote_;
    EffectOutcomes outcomes_;
    vtkSmartPointer<vtkActor> frameAxes_;
    vtkSmartPointer<vtkActor2D> vanishing_;  // vanishing points and the lines meeting there, projected view
    vtkSmartPointer<vtkActor2D> rasterGrid_; // the raster effect's pixels, projected view
    vtkSmartPointer<vtkActor2D> zFightingRing_; // around the z-fighting faces, projected view
    // What each color means, for the elements the scene shows in each view.
    vtkSmartPointer<vtkLegendBoxActor> worldLegend_;
    vtkSmartPointer<vtkLegendBoxActor> projectedLegend_;
    std::vector<LegendEntry> worldEntries_;
    std::vector<LegendEntry> projectedEntries_;
    std::vector<Layer> layers_;
    std::vector<Label> labels_;
    struct ProjectedActor {
        vtkSmartPointer<vtkActor> actor;
        Element element; // styled as the world view's layers are
        bool surface;
    };
    std::vector<ProjectedActor> projectedActors_;
    Theme theme_ = Theme::Dark;
    int fontSize_ = 18;
    double lineScale_ = 1;
    double canonicalOpacity_ = 0;
    double markerSize_ = 1; // of the scene's point markers, in world units
    // The user's view relative to the automatic framing.
    double userZoom_ = 1;
    Vec3<double> userPan_ = Vec3<double>::Zero();
    Framing framed_;                 // the last framing
    Mat4<double> shownMatrix_ = Mat4<double>::Identity();
};

} // namespace viewpipe::gui
