// What a person checks by looking: distinct colors for distinct meanings in
// both themes, a legend naming what the scene shows, the z-fighting color on
// screen, a matrices panel that cuts nothing, an export folder outside the
// program's, a guide that names every stage, and tooltips on the controls.

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDirIterator>
#include <QFileInfo>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QAbstractTextDocumentLayout>
#include <QTextDocument>
#include <QTextTable>
#include <QTextLayout>
#include <QRegularExpression>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <vtkActor2DCollection.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkLegendBoxActor.h>
#include <vtkTextActor.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <set>

#include "build_paths.h"
#include "app_window.h"
#include "drawn_texts.h"
#include "files.h"
#include "app/AppPaths.h"
#include "app/ExportDialog.h"
#include "app/StoryboardView.h"
#include "app/GuideDialog.h"
#include "app/MainWindow.h"
#include "app/MatrixPanel.h"
#include "viewpipe/animation.hpp"
#include "viewpipe/math_text.hpp"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

const QString kScenes = QString(viewpipe::build::dataDir) + "/scenes";

// The largest difference of one channel, 0 to 1.
double difference(const report::Rgb& a, const report::Rgb& b)
{
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

vtkRenderer* renderer(MainWindow& window, const char* view)
{
    return window.findChild<QVTKOpenGLNativeWidget*>(view)->renderWindow()->GetRenderers()->GetFirstRenderer();
}

// The entries of the legend drawn in a view; fails the test if there is none.
QStringList legendEntries(MainWindow& window, const char* view)
{
    vtkActor2DCollection* actors = renderer(window, view)->GetActors2D();
    actors->InitTraversal();
    while (vtkActor2D* actor = actors->GetNextActor2D())
        if (auto* legend = vtkLegendBoxActor::SafeDownCast(actor)) {
            if (!legend->GetVisibility())
                continue;
            QStringList entries;
            for (int k = 0; k < legend->GetNumberOfEntries(); ++k)
                entries << legend->GetEntryString(k);
            return entries;
        }
    qWarning("no legend in %s", view);
    return {};
}

// A view as drawn now.
QImage viewImage(MainWindow& window, const char* view)
{
    window.renderNow();
    return window.findChild<QVTKOpenGLNativeWidget*>(view)->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
}

// Whether a pixel is within a few levels of a color (lines drawn opaque keep theirs exactly).
bool near(QRgb c, const report::Rgb& color)
{
    const int r = int(std::lround(255 * color.r)), g = int(std::lround(255 * color.g)), b = int(std::lround(255 * color.b));
    return std::max({std::abs(qRed(c) - r), std::abs(qGreen(c) - g), std::abs(qBlue(c) - b)}) <= 24;
}

// Pixels of a view near a color; with `unlike`, only those where that picture's are not.
int pixelsOf(const QImage& image, const report::Rgb& color, const QImage* unlike = nullptr)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += near(image.pixel(x, y), color) && !(unlike && near(unlike->pixel(x, y), color));
    return count;
}

int pixelsOf(MainWindow& window, const char* view, const report::Rgb& color)
{
    return pixelsOf(viewImage(window, view), color);
}

} // namespace

class LookTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QSettings().remove("exportFolder"); }

    void cleanupTestCase() { QSettings().remove("exportFolder"); }

    void meaningsHaveTheirOwnColors()
    {
        for (const report::Theme theme : {report::Theme::Dark, report::Theme::Light}) {
            const report::Rgb dop = report::elementColor(Element::Dop, theme);
            const report::Rgb vanishing = report::elementColor(Element::Vanishing, theme);
            const report::Rgb fighting = report::elementColor(Element::ZFighting, theme);
            QVERIFY(difference(dop, vanishing) > 0.25);
            QVERIFY(difference(dop, fighting) > 0.25);
            QVERIFY(difference(vanishing, fighting) > 0.25);
            for (const bool projected : {false, true}) {
                const report::Rgb background = report::backgroundColor(theme, projected);
                for (const report::Rgb& c : {dop, vanishing, fighting})
                    QVERIFY(difference(c, background) > 0.3);
            }
        }
    }

    void legendNamesWhatTheSceneShows()
    {
        MainWindow window;
        window.setPopupsEnabled(false);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.sceneFiles()->openScene(kScenes + "/depth-corridor.json"));
        window.renderNow();
        for (const char* view : {"worldView", "projectedView"}) {
            const QStringList entries = legendEntries(window, view);
            QVERIFY2(entries.filter("z-fighting").size() == 1, qPrintable(entries.join(", ")));
            QVERIFY2(entries.filter("depth bands").size() == 1, qPrintable(entries.join(", ")));
        }
        QVERIFY(legendEntries(window, "projectedView").filter("vanishing").size() == 1);

        QVERIFY(window.sceneFiles()->openScene(kScenes + "/house.json"));
        window.renderNow();
        const QStringList house = legendEntries(window, "worldView");
        QVERIFY2(house.filter("DOP").size() == 1, qPrintable(house.join(", ")));
        QVERIFY2(house.filter("z-fighting").isEmpty(), qPrintable(house.join(", ")));
        QVERIFY(house.filter("depth bands").isEmpty());
    }

    void zFightingShowsInItsColor()
    {
        MainWindow window;
        window.setPopupsEnabled(false);
        window.resize(1600, 950);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (const report::Theme theme : {report::Theme::Dark, report::Theme::Light}) {
            window.setTheme(theme);
            const report::Rgb fighting = report::elementColor(Element::ZFighting, theme);
            QVERIFY(window.sceneFiles()->openScene(kScenes + "/depth-corridor.json"));
            QVERIFY2(pixelsOf(window, "worldView", fighting) > 30, "the world view shows no z-fighting color");
            QVERIFY2(pixelsOf(window, "projectedView", fighting) > 30, "the projected view shows no z-fighting color");
            QVERIFY(window.sceneFiles()->openScene(kScenes + "/house.json")); // nothing fights: the color means z-fighting only
            QVERIFY(pixelsOf(window, "worldView", fighting) < 10);
            QVERIFY(pixelsOf(window, "projectedView", fighting) < 10);
        }
    }

    // The stage's matrix moves every prop on the GPU, which clips what lies
    // behind the eye: an element partly behind it shows its front part (it
    // used to vanish whole). The eye stands inside the house here.
    // Every built-in scene at every stage: no two texts drawn in the world view
    // overlap, none covers the legend, and all lie inside the view.
    void labelsNeverOverlap()
    {
        auto window = openWindow(kScenes + "/house.json", {1600, 950});
        QVERIFY(window);
        int labels = 0;
        const int pictures = showEveryBuiltInStage(*window, [&](const QString& where) {
            vtkRenderer* view = renderer(*window, "worldView");
            const std::string trouble = textTrouble(view);
            QVERIFY2(trouble.empty(), qPrintable(where + ": " + QString::fromStdString(trouble)));
            labels += int(drawnTexts(view).texts.size());
        });
        QVERIFY2(pictures > 100 && labels > 10 * pictures, qPrintable(QString("%1 pictures, %2 texts").arg(pictures).arg(labels)));
        closeWindow(window);
    }

    void elementsPartlyBehindTheEyeShowTheirFrontPart()
    {
        // Text is drawn in the edges' color too: none is drawn, and the pixels the house adds to the picture
        // without it, seen through the same camera (each scene is framed on its own subject), are counted.
        const QString camera = R"("camera": {"look_at": {"eye": [8, 6, 40], "center": [8, 6, 0], "up": [0, 1, 0]},
            "projection": {"type": "perspective", "fovy_deg": 70, "aspect": 1.5, "near": 2, "far": 60}})";
        const QString withHouse = QDir::temp().filePath("viewpipe-look-eye-in-house.json");
        const QString without = QDir::temp().filePath("viewpipe-look-eye-alone.json");
        QVERIFY(writeFile(withHouse, ("{" + camera + R"(, "objects": [{"type": "house"}]})").toUtf8()));
        QVERIFY(writeFile(without, ("{" + camera + R"(, "objects": []})").toUtf8()));
        MainWindow window;
        window.setPopupsEnabled(false);
        window.resize(1600, 950);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.setTheme(report::Theme::Light); // the canonical outline is black, the edges not quite
        window.painter()->setTextVisible(false);
        const report::Rgb edges = report::elementColor(Element::Objects, report::Theme::Light);
        QVERIFY(window.sceneFiles()->openScene(withHouse));
        const auto stages = window.document()->pipeline().stages;
        const PolygonMesh house = houseMesh();
        int checked = 0;
        for (int k = 1; k <= int(stages.size()); ++k) {
            const Mat4<double> m = cumulativeAt(stages, k);
            if (std::none_of(house.vertices.begin(), house.vertices.end(),
                             [&](const Vec3<double>& p) { return (m * p.homogeneous()).w() <= 0; }))
                continue;
            QVERIFY(window.sceneFiles()->openScene(withHouse));
            window.stepper()->goToStage(k, false);
            const QImage drawn = viewImage(window, "worldView");
            vtkNew<vtkCamera> seen;
            seen->DeepCopy(renderer(window, "worldView")->GetActiveCamera());
            QVERIFY(window.sceneFiles()->openScene(without));
            window.stepper()->goToStage(k, false);
            renderer(window, "worldView")->GetActiveCamera()->DeepCopy(seen);
            const QImage alone = viewImage(window, "worldView");
            const int added = pixelsOf(drawn, edges, &alone);
            QVERIFY2(added > 30, qPrintable(QString("stage %1: the house adds %2 pixels of its edges").arg(k).arg(added)));
            ++checked;
        }
        QVERIFY2(checked > 0, "no stage puts a vertex behind the eye");
    }

    void matricesPanelCutsNothing()
    {
        MainWindow window;
        window.setPopupsEnabled(false);
        window.resize(1280, 720);
        window.setFontSize(12); // a little larger than the default, as on a projector
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.sceneFiles()->openScene(kScenes + "/classical/house-oblique.json"));
        window.stepper()->goToStage(window.stepper()->stageCount(), false); // S_par, with the longest notes
        window.showPanel("matrices");
        QVERIFY(window.matrices()->stageText().contains("<i>S</i><sub>par</sub>")); // S_par, set as math
        auto* scroll = window.findChild<QDockWidget*>("matricesDock")->findChild<QScrollArea*>();
        QTest::qWait(200); // the layout settles
        QVERIFY(scroll->viewport()->width() > 100);
        QCOMPARE(scroll->horizontalScrollBar()->maximum(), 0); // all of it fits the panel's width
    }

    // At twice the text the matrices' columns keep a space between their numbers
    // (a fixed 3 px read "0" and "−20" as "0−20"), and a minus is a minus sign.
    void matrixNumbersKeepApartAtLargerText()
    {
        MainWindow window;
        window.setPopupsEnabled(false);
        window.resize(1280, 720);
        window.setFontSize(20, false); // the default 10 points at 200 %
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.showPanel("matrices");
        auto* matrices = window.findChild<QLabel*>("matrices");
        QVERIFY(matrices);
        const QFontMetricsF metrics(matrices->font());
        int rows = 0;
        for (const QString scene : {"/house-corner.json", "/apis/direct3d.json"}) {
        QVERIFY(window.sceneFiles()->openScene(kScenes + scene));
        for (int stage = 1; stage <= window.stepper()->stageCount(); ++stage) {
            window.stepper()->goToStage(stage, false);
            QVERIFY2(!matrices->text().contains(QRegularExpression("'>(&nbsp;)*-[0-9]")), qPrintable(matrices->text()));
            QTextDocument document;
            document.setDefaultFont(matrices->font());
            document.setHtml(matrices->text());
            document.size(); // laid out
            for (QTextFrame* frame : document.rootFrame()->childFrames()) {
                auto* table = qobject_cast<QTextTable*>(frame);
                if (!table)
                    continue;
                // Where a cell's text begins and ends on the page.
                QAbstractTextDocumentLayout* layout = document.documentLayout();
                auto extent = [&](const QTextTableCell& cell) {
                    double left = 1e9, right = -1e9;
                    for (QTextFrame::iterator it = cell.begin(); !it.atEnd(); ++it) {
                        const QTextBlock block = it.currentBlock();
                        if (!block.isValid() || block.text().trimmed().isEmpty())
                            continue;
                        const QTextLine line = block.layout()->lineAt(0);
                        const QPointF at = layout->blockBoundingRect(block).topLeft() - block.layout()->boundingRect().topLeft();
                        // The space before the number is the gap, not the text.
                        const double lead = line.cursorToX(block.text().size() - block.text().trimmed().size());
                        left = std::min(left, at.x() + lead);
                        right = std::max(right, at.x() + line.naturalTextRect().right());
                    }
                    return std::pair<double, double>(left, right);
                };
                for (int r = 0; r < table->rows(); ++r)
                    for (int c = 0; c + 1 < table->columns(); ++c) {
                        const QTextTableCell a = table->cellAt(r, c), b = table->cellAt(r, c + 1);
                        if (a.column() != c || b.column() != c + 1)
                            continue; // the caption's row spans the columns
                        const double gap = extent(b).first - extent(a).second;
                        QVERIFY2(gap >= metrics.horizontalAdvance(' '),
                                 qPrintable(QString("stage %1, row %2: columns %3 and %4 are %5 px apart, a space is %6 px")
                                                .arg(stage).arg(r).arg(c).arg(c + 1).arg(gap)
                                                .arg(metrics.horizontalAdvance(' '))));
                        ++rows;
                    }
            }
        }
        }
        QVERIFY(rows > 100);
    }

    void exportFolderIsTheUsersAndRemembered()
    {
        const QString program = QCoreApplication::applicationDirPath();
        {
            ExportDialog dialog(5, report::Theme::Dark);
            const QString folder = QString::fromStdString(dialog.options().out.string());
            QVERIFY2(!folder.startsWith(program), qPrintable(folder));
            QVERIFY2(!folder.startsWith(QDir::currentPath()), qPrintable(folder));
            QCOMPARE(folder, ExportDialog::defaultFolder());
            QVERIFY(folder.endsWith("/ViewPipe"));
            const QString pictures = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
            if (!pictures.isEmpty())
                QVERIFY(folder.startsWith(pictures));
        }
        QTemporaryDir chosen;
        {
            ExportDialog dialog(5, report::Theme::Dark);
            dialog.findChild<QLineEdit*>("exportFolder")->setText(chosen.path());
            dialog.accept();
        }
        ExportDialog again(5, report::Theme::Dark);
        QCOMPARE(QString::fromStdString(again.options().out.string()), chosen.path());
    }

    // Found: Save, Import, Export as Web Page and Save My Answers opened in the program's folder; and
    // where the user has no Documents folder, Open showed the home folder with "Documents" as the file's name.
    void fileDialogsOpenInTheUsersFolderThenTheLastOne()
    {
        QSettings().remove("dialogFolder");
        const QString program = QCoreApplication::applicationDirPath();
        const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        const QString users = QDir(documents).exists() ? documents : QDir::homePath();
        QCOMPARE(dialogPath("lesson-results.json"), QDir(users).filePath("lesson-results.json"));
        QVERIFY2(QDir(dialogPath()).exists(), qPrintable(dialogPath()));
        QVERIFY(!dialogPath().startsWith(program) && dialogPath() != QDir::currentPath());
        QTemporaryDir chosen;
        rememberDialogFolder(chosen.filePath("house.json"));
        QCOMPARE(dialogPath("sheet.png"), QDir(chosen.path()).filePath("sheet.png"));
        QSettings().remove("dialogFolder");
    }

    void guideNamesEveryStage()
    {
        // Every stage of the scenes shipped, with the divide, and of glFrustum.
        std::set<std::string> symbols;
        QDirIterator files(kScenes, {"*.json"}, QDir::Files, QDirIterator::Subdirectories);
        std::vector<Scene> scenes;
        while (files.hasNext())
            scenes.push_back(loadScene(files.next().toStdString()));
        scenes.push_back(parseScene(R"({"camera": {"look_at": {"eye": [0, 0, 5], "center": [0, 0, 0], "up": [0, 1, 0]},
                                                "projection": {"type": "frustum", "left": -1, "right": 2, "bottom": -1,
                                                               "top": 1, "near": 1, "far": 10}},
                                     "objects": []})",
                                    "."));
        for (const Scene& scene : scenes)
            for (const bool divide : {false, true})
                for (const auto& stage :
                     buildPipeline(scene.camera, withEffect(scene.effects, EffectKind::Divide, divide)).stages)
                    symbols.insert(stage.symbol());
        QVERIFY(symbols.count("SH_frustum") && symbols.count("S_par") && symbols.count("M"));

        QWidget parent;
        GuideDialog* guide = GuideDialog::showFor(&parent);
        QVERIFY(guide->isVisible());
        QVERIFY(!guide->isModal());
        QCOMPARE(GuideDialog::showFor(&parent), guide); // one guide, brought to the front
        const QString text = guide->browser()->toPlainText();
        for (const std::string& symbol : symbols) {
            // As math: SH_frustum is SH with "frustum" below it, T(-VRP) has a minus sign, NDC_vulkan_reversed is
            // NDC with "Vulkan, reversed" below it.
            QString written;
            for (const MathRun& run : mathRuns("$" + symbolMath(symbol) + "$"))
                written += QString::fromStdString(run.text);
            QVERIFY2(text.contains(written), symbol.c_str());
        }
        for (const char* words : {"Matrices", "Parameters", "Accuracy", "Depth", "Ctrl+Z", "Ctrl+Y", "Ctrl+E", "Ctrl+K",
                                  "Left", "Play"})
            QVERIFY2(text.contains(words), words);
    }

    // View ▸ Leave Out offers what export --hide names and leaves it out of every view: the labels go
    // (no label text drawn), the world axes' lines go, the caption goes; checked again, they come back
    // as they were (the stage at rest: a first version drew the props made anew at the world's matrix).
    void theViewMenuLeavesOutWhatExportHides()
    {
        auto window = openWindow(kScenes + "/house.json", {1600, 1000});
        QVERIFY(window);
        window->stepper()->goToStage(3, false);
        QMenu* leaveOut = nullptr;
        for (QMenu* menu : window->findChildren<QMenu*>())
            if (menu->title() == "Leave &Out")
                leaveOut = menu;
        QVERIFY(leaveOut);
        QStringList offered;
        for (const QAction* action : leaveOut->actions())
            offered << action->objectName();
        QStringList names;
        for (const std::string& name : hideNames())
            names << QString::fromStdString("view.hide." + name);
        QCOMPARE(offered, names);
        auto texts = [&] {
            window->renderNow();
            QStringList shown;
            for (const DrawnText& text : drawnTexts(renderer(*window, "worldView")).texts)
                shown << QString::fromStdString(text.text);
            shown.sort(); // the props are made anew: in another order
            return shown;
        };
        const QStringList before = texts();
        QVERIFY2(before.contains("PRP") && before.contains("VRP"), qPrintable(before.join(" | ")));
        window->actions()->action("view.hide.labels")->trigger();
        QVERIFY(window->views()->hidden().count("labels"));
        const QStringList without = texts();
        QVERIFY2(!without.contains("PRP") && !without.contains("VRP"), qPrintable(without.join(" | ")));
        const auto primitives = [&](Element element) {
            const EvaluatedScene& drawn = *window->views()->storyboard()->scene();
            return std::count_if(drawn.primitives.begin(), drawn.primitives.end(), [&](const Primitive& p) { return p.element == element; });
        };
        window->actions()->action("view.hide.world_axes")->trigger();
        window->setStoryboardShown(true); // the storyboard draws what the views draw
        QCOMPARE(primitives(Element::WorldAxes), 0L);
        QVERIFY(primitives(Element::Objects) > 0);
        window->setStoryboardShown(false);
        window->actions()->action("view.hide.caption")->trigger();
        QCOMPARE(window->painter()->worldCaption(), std::string());
        for (const char* name : {"labels", "world_axes", "caption"})
            window->actions()->action(std::string("view.hide.") + name)->trigger();
        QVERIFY(window->views()->hidden().empty());
        const QStringList after = texts();
        QVERIFY2(after == before, qPrintable(before.join(" | ") + "\n" + after.join(" | ")));
        QVERIFY(!window->painter()->worldCaption().empty());
        closeWindow(window);
    }

    // View ▸ World View Legend puts the legend where it is asked, hides it, and the choice is kept.
    void theLegendGoesWhereTheViewMenuSays()
    {
        auto window = openWindow(kScenes + "/house.json", {1600, 1000});
        QVERIFY(window);
        const auto restore = qScopeGuard([] { QSettings().remove("worldLegend"); });
        window->stepper()->goToStage(4, false);
        QAction* none = nullptr;
        QAction* below = nullptr;
        for (const QMenu* menu : window->findChildren<QMenu*>())
            if (menu->title() == "&World View Legend")
                for (QAction* action : menu->actions()) {
                    if (action->text() == "Hidden")
                        none = action;
                    if (action->text() == "Below")
                        below = action;
                }
        QVERIFY(none && below);
        below->trigger();
        window->renderNow();
        const DrawnTexts placed = drawnTexts(renderer(*window, "worldView"));
        QVERIFY(placed.legend);
        QVERIFY2((*placed.legend)[2] < 0.2 * renderer(*window, "worldView")->GetSize()[1], "at the bottom");
        QCOMPARE(QSettings().value("worldLegend").toString(), QString("below"));
        none->trigger();
        window->renderNow();
        QVERIFY(!drawnTexts(renderer(*window, "worldView")).legend);
        closeWindow(window);
    }

    // The dialog is made from export's tables: every format and everything --hide names is offered, and
    // what is chosen is what export is asked for.
    void exportDialogOffersEveryFormatAndOption()
    {
        ExportDialog dialog(5, report::Theme::Light);
        for (const ExportFormat& format : exportFormats()) {
            auto* box = dialog.findChild<QCheckBox*>(QString::fromStdString("format-" + format.name));
            QVERIFY2(box, format.name.c_str());
            box->setChecked(format.name == "tikz" || format.name == "svg");
        }
        for (const std::string& name : hideNames()) {
            auto* box = dialog.findChild<QCheckBox*>(QString::fromStdString("hide-" + name));
            QVERIFY2(box, name.c_str());
            box->setChecked(name == "legend" || name == "projectors");
        }
        const ExportOptions o = dialog.options();
        QCOMPARE(o.formats, (std::set<std::string>{"svg", "tikz"}));
        QCOMPARE(o.hidden, (std::set<std::string>{"legend", "projectors"}));
        QCOMPARE(o.textScale, 100);
        QCOMPARE(o.digits, 4);
        QCOMPARE(o.zoom, 1.0);
        QVERIFY(o.legend == report::LegendPlace::Best);
        QVERIFY(o.framing == report::FramingMode::Together);
        QVERIFY(!o.storyboard);
        auto* layout = dialog.findChild<QComboBox*>("layout");
        QVERIFY(layout);
        layout->setCurrentIndex(1);
        QVERIFY(dialog.options().storyboard);
    }

    // File > Export Stages starts from what the window shows: what View > Leave Out leaves out, and the
    // storyboard where it is shown.
    void theExportDialogStartsFromTheView()
    {
        auto window = openWindow(kScenes + "/house.json", {1600, 1000});
        QVERIFY(window);
        window->actions()->action("view.hide.projectors")->trigger();
        window->setStoryboardShown(true);
        std::optional<ExportOptions> offered;
        QTimer::singleShot(200, [&] {
            if (auto* dialog = qobject_cast<ExportDialog*>(QApplication::activeModalWidget())) {
                offered = dialog->options();
                dialog->reject();
            }
        });
        window->actions()->action("file.exportStages")->trigger();
        QVERIFY(offered);
        QCOMPARE(offered->hidden, std::set<std::string>{"projectors"});
        QVERIFY(offered->storyboard);
        window->actions()->action("view.hide.projectors")->trigger();
        closeWindow(window);
    }

    void everyControlSaysWhatItIs()
    {
        ExportDialog dialog(5, report::Theme::Dark);
        MatrixPanel panel;
        for (QWidget* parent : {static_cast<QWidget*>(&dialog), static_cast<QWidget*>(&panel)})
            for (QWidget* control : parent->findChildren<QWidget*>())
                if (qobject_cast<QAbstractSpinBox*>(control->parentWidget())) // a spin box's own line edit
                    continue;
                else if (qobject_cast<QAbstractButton*>(control) || qobject_cast<QLineEdit*>(control) ||
                    qobject_cast<QAbstractSpinBox*>(control) || qobject_cast<QComboBox*>(control) ||
                    (qobject_cast<QLabel*>(control) && parent == &panel))
                    QVERIFY2(!control->toolTip().isEmpty(), qPrintable(control->metaObject()->className() +
                                                                       QString(" ") + control->objectName()));
    }
};

int main(int argc, char** argv)
{
    return runAppTests<LookTest>(argc, argv);
}

#include "look_test.moc"
