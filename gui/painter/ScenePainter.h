#pragma once

// Draws an evaluated scene with VTK (no Qt): the world view with every
// element the scene evaluated to, and the projected view. Each element's poly
// data is built once per scene in world coordinates; a stage is shown by
// giving every prop the stage's cumulative matrix (projective: the GPU
// divides and clips, so the part of an element in front of the eye is drawn
// and the part behind it is not). One painter serves the app, screenshots and
// exports.

#include <vtkSmartPointer.h>

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "MeshDetail.h"
#include "viewpipe/report/figure.hpp"
#include "viewpipe/report/style.hpp"
#include "viewpipe/report/world_view.hpp"

class vtkActor;
class vtkActor2D;
class vtkCamera;
class vtkCallbackCommand;
class vtkLegendBoxActor;
class vtkMapper;
class vtkPlane;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace viewpipe::gui {

class ProjectedView;

// The scene's objects alone (faces and edges, as the painter styles them),
// added to each renderer; for pictures that need no set-up around them.
void addObjectActors(const std::vector<vtkRenderer*>& renderers, const EvaluatedScene& scene, report::Theme theme);

// Points a VTK camera as the world view's camera says.
void setVtkCamera(vtkCamera* vtk, const report::WorldCamera& camera);

class ScenePainter {
public:
    // `projected` may be null: then no projected view is drawn. Painters given
    // the same `meshes` draw a mesh from one copy of its poly data.
    ScenePainter(vtkRenderer* world, vtkRenderer* projected,
                 std::shared_ptr<MeshDetails> meshes = std::make_shared<MeshDetails>());
    ~ScenePainter();
    ScenePainter(const ScenePainter&) = delete;
    ScenePainter& operator=(const ScenePainter&) = delete;

    // Builds the props of an evaluated scene (the poly data of meshes it
    // shares with the previous scene is kept) and shows its first stage.
    void setScene(std::shared_ptr<const EvaluatedScene> scene);

    // Shows every element through `cumulative`; the canonical volume's outline
    // is drawn with the given opacity (0 hides it).
    void show(const Mat4<double>& cumulative, double canonicalOpacity);
    // Shows the objects' edges and the view volume faintly through `ghost` as
    // well (where they were a stage before), or not.
    void setGhost(const std::optional<Mat4<double>>& ghost);

    // While moving (a transition, Play), large meshes are drawn from decimated
    // copies (MeshDetail); at rest, and in every export, at full detail. The
    // view also counts as moving while VTK's interactor turns it (the window's
    // interactive update rate).
    void setMoving(bool moving);

    // Shows or hides every text: labels and captions.
    void setTextVisible(bool visible);

    // Titles in the top-left corners of the two views.
    void setCaptions(const std::string& world, const std::string& projected);
    std::string worldCaption() const;

    // Marks the vertex being traced (world coordinates) in the world view, or none.
    void markTraced(const std::optional<Vec3<double>>& point);

    void setTheme(report::Theme theme);
    // Labels and captions `points` pixels high; where room runs out, the
    // caption and legend may shrink to `minPoints` (0: they never do).
    void setFontSize(int points, int minPoints = 0);
    // Line widths are multiplied by this (2 for a picture at twice the pixels).
    void setLineScale(double scale);
    report::Theme theme() const { return theme_; }

    // Shows a moment of the world view (world_view.hpp): its matrix, ghost and framing.
    void showMoment(const report::WorldMoment& moment);
    // Aims the world view's camera at a framing, keeping the user's
    // direction, zoom and pan; resetView() restores the default viewpoint,
    // zoom and pan on the framing shown.
    void frameOn(const report::Framing& framing);
    void resetView();
    // Where the world view's legend goes, and the projected view's (the picture's layout: layoutPicture).
    void setLegendPlace(report::LegendPlace place);
    void setProjectedLegendPlace(report::LegendPlace place);
    // Whether the fixed axes' ticks and numbers are drawn, and the notice of labels left out for room.
    void setTicksAndNotesShown(bool ticks, bool notes);
    // Turns the world view's camera about its focal point, in degrees (yaw
    // about the view's up, pitch about its right, as the web page turns) and
    // zooms it, as a lesson step asks; later framing keeps both.
    void orbit(double yaw, double pitch, double zoom);
    // The world view's camera as orbit() sets it from the default viewpoint.
    struct Orbit {
        double yaw = 0, pitch = 0, zoom = 1;
    };
    Orbit orbitAngles() const;
    // Call when the user has moved the camera, to keep that change in later framing.
    void rememberUserCamera();

    // The original (world) coordinates of the object vertex drawn nearest a
    // display position of the world view, within a hundredth of the window's
    // diagonal, if any.
    std::optional<Vec3<double>> pickVertex(int displayX, int displayY) const;

    // How the world view sees the stage shown, for figures drawn as it is.
    report::FigureView figureView() const;
    // Where the last frame placed the labels (none while text is hidden): figures drawn as it is place them there.
    const report::SceneLabels& placedLabels() const { return placed_; }
    // Where the last frame put its caption, legend and note.
    const report::PictureLayout& pictureLayout() const { return layoutCache_.last(); }

private:
    struct Layer {
        const Primitive* primitive;
        vtkSmartPointer<vtkActor> actor;
        std::optional<DetailedActor> detail; // a mesh's faces: its actor, drawn at the detail the motion allows
        std::vector<vtkMapper*> mappers() const;
    };
    struct Label {
        const viewpipe::Label* label;
        vtkSmartPointer<vtkTextActor> actor;
    };
    void clear();
    void addLayer(const Primitive& primitive, vtkSmartPointer<vtkActor> actor, std::optional<DetailedActor> detail = {});
    Label newLabel(const viewpipe::Label& text);
    void addLabel(const viewpipe::Label& label);
    void styleLabel(Label& label) const;
    void styleLabels(); // every label, tick number and the left-out note, at labelSize_
    void applyStyle();
    // Places every label with the one placement step the figures use, for the camera of the coming frame.
    void placeLabels();
    // Where the caption, the note and the legend are, in the view's pixels (empty where not shown).
    std::array<report::Box2, 3> textBoxesShown() const;
    // The text's backdrops (textBackdrops) around textBoxes_: what runs behind the text stops at them.
    void drawBackdrops();
    void beforeFrame();
    void placeLabelsOf(const report::StageShown& stage, const report::FigureView& view, const std::vector<Marker>& markers,
                       std::vector<Segment2>& leaders, std::vector<report::Rgb>& leaderColors);
    void drawMarkers(const std::vector<report::FigureShape>& shapes);
    // Breaks the captions into lines that fit the view's width.
    void fitCaptions();
    // Whether a world point is drawn at the stage shown: it has an image and is not cut away.
    bool shows(const Vec3<double>& world) const;
    // Cuts every moving prop at the scene's near cut while the stage is projective, or not at all.
    void cutNear(const Mat4<double>& cumulative);
    // The near and far planes around everything framed, before each frame (prop bounds mean nothing under a projective matrix).
    void fitClippingRange();
    report::WorldCamera camera() const;
    void setCamera(const report::WorldCamera& camera);
    report::ViewFit viewFit() const;
    const std::shared_ptr<MeshDetail>& meshDetail(const std::shared_ptr<const PolygonMesh>& mesh);

    vtkRenderer* world_;
    std::unique_ptr<ProjectedView> projected_;
    std::shared_ptr<const EvaluatedScene> scene_;
    // The poly data of each mesh shown, so that a scene sharing a mesh with the last one does not rebuild it.
    std::shared_ptr<MeshDetails> meshDetails_;
    vtkSmartPointer<vtkTextActor> worldCaption_;
    vtkSmartPointer<vtkTextActor> effectsCaption_;
    vtkSmartPointer<vtkActor> frameAxes_;
    vtkSmartPointer<vtkActor2D> leaders_; // lines from labels moved away to their anchors
    vtkSmartPointer<vtkActor2D> markers_; // the points marked, one size on screen
    vtkSmartPointer<vtkActor2D> tracedMarkers_; // the vertex traced, over the text
    vtkSmartPointer<vtkActor2D> backdrops_;
    vtkSmartPointer<vtkLegendBoxActor> legend_;
    vtkSmartPointer<vtkCallbackCommand> clippingRange_;
    vtkSmartPointer<vtkPlane> nearCut_; // the scene's near cut in the stage's coordinates
    bool cutting_ = false;
    std::string worldCaptionText_, effectsNote_; // as given, before fitting
    std::vector<Layer> layers_;
    std::vector<Layer> ghosts_; // the ghosted primitives again, faint, through the ghost's matrix
    std::vector<Label> labels_;
    // The frame axes' names and tick numbers, which change with the framing.
    std::vector<viewpipe::Label> frameLabelTexts_;
    std::vector<Label> frameLabels_;
    // "left out for room: ...", set as a tick number (placeSceneLabels).
    viewpipe::Label leftOutText_{Element::Frame, "", Vec3<double>::Zero(), true, true};
    Label leftOut_;
    report::SceneLabels placed_;
    // The traced vertex's marker and label (not part of the scene).
    std::optional<Marker> tracedMarker_;
    std::unique_ptr<viewpipe::Label> tracedLabel_;
    report::Theme theme_ = report::Theme::Dark;
    int fontSize_ = 18;
    int labelSize_ = 18;  // fontSize_, or the caption's size where the view sets it smaller (labelSizeIn)
    int minFontSize_ = 0; // 0: as fontSize_
    int minFontSize() const { return minFontSize_ > 0 ? minFontSize_ : fontSize_; }
    double legendFontSize_ = 0; // the label size the legend was last filled for; 0: to be filled
    double lineScale_ = 1;
    double canonicalOpacity_ = 0;
    bool textVisible_ = true;
    bool moving_ = false;
    // The user's view relative to the automatic framing.
    double userZoom_ = 1;
    // The zoom the text's layout allows for: a lesson step's or an export's (orbit); the wheel's moves no text.
    double layoutZoom_ = 1;
    Vec3<double> userPan_ = Vec3<double>::Zero();
    report::Framing framed_; // the last framing
    // Where frameOn fits the stage (layoutPicture's scene area), in pixels, y down; empty: the whole view.
    report::Box2 sceneArea_;
    std::array<report::Box2, 3> textBoxes_; // textBoxesShown() as the last fitCaptions() measured it
    report::PictureLayoutCache layoutCache_;
    std::vector<Vec2<double>> subject_, subjectShown_; // the framed subject's outline, for the text's layout (subjectOutline)
    std::array<double, 14> outlined_{}; // the framing's box and sizes and the camera's direction and up they are of
    report::LegendPlace legendPlace_ = report::LegendPlace::Best;
    bool ticksShown_ = true, notesShown_ = true;
    Mat4<double> shownMatrix_ = Mat4<double>::Identity();
};

} // namespace viewpipe::gui
