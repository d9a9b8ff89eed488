// The parameter panel under Xvfb, driven from the keyboard as a person does:
// a field holds exactly the double typed or read, or an exact expression as
// typed, an edit changes only its field, text that is neither is refused
// beside the field with its path, Escape restores the field, as the first
// Ctrl+Z does; Ctrl+Z / Ctrl+Shift+Z otherwise reach the document.

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QStandardPaths>
#include <QTextDocumentFragment>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QVTKOpenGLNativeWidget.h>
#include <QtTest>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

#include "build_paths.h"
#include "app_window.h"
#include "app/MainWindow.h"
#include "app/ParameterPanel.h"

using namespace viewpipe;
using namespace viewpipe::gui;

namespace {

using FieldValues = std::map<QString, std::vector<double>>;

QString scenePath(const QString& name)
{
    return QString(viewpipe::build::dataDir) + "/scenes/" + name;
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The numbers of every field of a camera, keyed by the panel's field names.
FieldValues fieldValues(const CameraSpec<double>& camera)
{
    auto list = [](const Vec3<double>& v) { return std::vector<double>{v.x(), v.y(), v.z()}; };
    if (const auto* s = std::get_if<foley::ViewSpec<double>>(&camera))
        return {{"view.vrp", list(s->vrp)},
                {"view.vpn", list(s->vpn)},
                {"view.vup", list(s->vup)},
                {"view.prp", list(s->prp)},
                {"view.window", {s->window.umin, s->window.umax, s->window.vmin, s->window.vmax}},
                {"view.front", {s->front}},
                {"view.back", {s->back}}};
    const auto& gl = std::get<gl::Camera<double>>(camera);
    FieldValues out = {{"camera.look_at.eye", list(gl.lookAt.eye)},
                       {"camera.look_at.center", list(gl.lookAt.center)},
                       {"camera.look_at.up", list(gl.lookAt.up)}};
    if (const auto* p = std::get_if<gl::Perspective<double>>(&gl.projection)) {
        out["camera.projection.fovy_deg"] = {p->fovyDegrees};
        out["camera.projection.aspect"] = {p->aspect};
        out["camera.projection.near"] = {p->zNear};
        out["camera.projection.far"] = {p->zFar};
        return out;
    }
    std::visit(
        [&out](const auto& box) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(box)>, gl::Perspective<double>>) {
                out["camera.projection.left"] = {box.left};
                out["camera.projection.right"] = {box.right};
                out["camera.projection.bottom"] = {box.bottom};
                out["camera.projection.top"] = {box.top};
                out["camera.projection.near"] = {box.zNear};
                out["camera.projection.far"] = {box.zFar};
            }
        },
        gl.projection);
    return out;
}

QLineEdit* fieldOf(MainWindow& window, const QString& field, int component = 0)
{
    const QList<QLineEdit*> boxes = window.parameters()->fields(field);
    if (component >= boxes.size())
        qFatal("no component %d of %s", component, qPrintable(field));
    return boxes[component];
}

// Selects the field's text and types over it; Return commits.
void type(QLineEdit* field, const QString& text, bool commit = true)
{
    field->setFocus();
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
    if (commit)
        QTest::keyClick(field, Qt::Key_Return);
}

// An edit written "component=text", e.g. "2=0" for the third box.
void typeEdit(MainWindow& window, const QString& field, const QString& edit)
{
    const int split = edit.indexOf('=');
    type(fieldOf(window, field, edit.left(split).toInt()), edit.mid(split + 1));
}

// Whether every box of these fields is wide enough for all its text (besides its frame and margins).
bool everyTextShowsWhole(MainWindow& window, const FieldValues& fields)
{
    for (const auto& entry : fields)
        for (const QLineEdit* box : window.parameters()->fields(entry.first))
            if (box->fontMetrics().horizontalAdvance(box->text()) + 8 > box->width())
                return false;
    return true;
}

// The visible label beside a field that shows `text`.
QLabel* labelShowing(ParameterPanel* panel, const QString& text)
{
    for (QLabel* label : panel->findChildren<QLabel*>())
        if (label->isVisible() && label->text() == text)
            return label;
    return nullptr;
}

QImage projectedPicture(MainWindow& window)
{
    window.renderNow();
    return window.findChild<QVTKOpenGLNativeWidget*>("projectedView")->grabFramebuffer();
}

std::string documentJson(MainWindow& window)
{
    return sceneToJson(window.document()->scene());
}

} // namespace

class ParameterTest : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        window_ = openWindow(scenePath("classical/house-dimetric.json"), {1600, 950});
        QVERIFY(window_);
        window_->showPanel("parameters"); // tabbed with the matrices
    }

    void cleanup() { closeWindow(window_); }

    // Editing Back changes nothing else: every other double is saved bit for bit.
    void editingOneFieldKeepsEveryOtherDouble()
    {
        MainWindow& w = *window_;
        const std::filesystem::path original = scenePath("classical/house-dimetric.json").toStdString();
        const FieldValues before = fieldValues(loadScene(original).camera);
        // The fields show the file's doubles in full, and its exact expressions as typed.
        QCOMPARE(fieldOf(w, "view.vpn", 0)->text(), QString("0.6644630243886747"));
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("16*sqrt(17)"));
        QTRY_VERIFY(everyTextShowsWhole(w, before));

        type(fieldOf(w, "view.back"), "-25");
        QTRY_VERIFY(everyTextShowsWhole(w, before));
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QTemporaryDir dir;
        const QString file = dir.filePath("edited.json");
        QVERIFY(w.sceneFiles()->saveScene(file));
        const FieldValues after = fieldValues(loadScene(file.toStdString()).camera);

        QCOMPARE(after.at("view.back").front(), -25.0);
        for (const auto& [field, values] : before) {
            if (field == "view.back")
                continue;
            for (std::size_t i = 0; i < values.size(); ++i)
                QVERIFY2(sameBits(after.at(field)[i], values[i]),
                         qPrintable(QString("%1[%2]: %3 became %4")
                                        .arg(field)
                                        .arg(i)
                                        .arg(values[i], 0, 'g', 17)
                                        .arg(after.at(field)[i], 0, 'g', 17)));
        }
    }

    void moreThanThreeDecimalsAreKept()
    {
        MainWindow& w = *window_;
        type(fieldOf(w, "view.vrp", 0), "0.0004");
        const double x = std::get<foley::ViewSpec<double>>(w.document()->scene().camera).vrp.x();
        QVERIFY(sameBits(x, std::strtod("0.0004", nullptr)));
        QCOMPARE(fieldOf(w, "view.vrp", 0)->text(), QString("0.0004"));
    }

    void textThatIsNotANumberIsRefused()
    {
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        int edits = 0;
        connect(panel, &ParameterPanel::cameraEdited, this, [&edits] { ++edits; });
        const std::string before = documentJson(w);
        const int undoCount = w.document()->undoStack()->count();

        type(fieldOf(w, "view.vrp", 0), "2x5");
        QCOMPARE(panel->errorText("view.vrp"), QString("view.vrp[0]: unexpected \"x\" at character 2 of \"2x5\""));
        QCOMPARE(documentJson(w), before);
        QCOMPARE(w.document()->undoStack()->count(), undoCount);
        QCOMPARE(edits, 0);

        type(fieldOf(w, "view.vrp", 0), "-4.5e1");
        QCOMPARE(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).vrp.x(), -45.0);
        QVERIFY(panel->errorText("view.vrp").isEmpty());
        QCOMPARE(edits, 1);

        const std::string accepted = documentJson(w);
        for (const QString text : {"nan", "inf", "1e999", "", "1,5", "4.5.1", "0x10"}) {
            type(fieldOf(w, "view.vrp", 0), text);
            QVERIFY2(panel->errorText("view.vrp").contains(QString("\"%1\"").arg(text)) ||
                         (text.isEmpty() && panel->errorText("view.vrp").contains("is empty")),
                     qPrintable(text + " -> " + panel->errorText("view.vrp")));
            QCOMPARE(documentJson(w), accepted);
        }
        QCOMPARE(edits, 1);
    }

    // Foley's view D has PRP n = 20√2 (CGPP, fig. 6.29): typed so, the field keeps the text, the scene
    // the nearest double and the text by its path; a save writes the text; undo and redo bring both back.
    void anExactExpressionIsKeptAsTypedSavedAndUndone()
    {
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        auto prpN = [&w] { return std::get<foley::ViewSpec<double>>(w.document()->scene().camera).prp.z(); };
        auto typed = [&w] { return w.document()->scene().typedExpressions; };
        using Typed = std::map<std::string, std::string>;
        const double before = prpN();
        const Typed preset = typed(); // the preset's roots: PRP n = 16 sqrt(17), front, back and window
        QCOMPARE(preset.at("view.prp[2]"), std::string("16*sqrt(17)"));
        // The file's expressions with some changed, or dropped (an empty text).
        auto presetWith = [&preset](const Typed& changes) {
            Typed expected = preset;
            for (const auto& [path, text] : changes)
                if (text.empty())
                    expected.erase(path);
                else
                    expected[path] = text;
            return expected;
        };
        // 20√2 = 28.28427124746190097603377448419396157...; strtod rounds it to the nearest double.
        const double nearest = std::strtod("28.28427124746190097603377448419396157", nullptr);

        type(fieldOf(w, "view.prp", 2), "20*sqrt(2)");
        QVERIFY2(panel->errorText("view.prp").isEmpty(), qPrintable(panel->errorText("view.prp")));
        QVERIFY(sameBits(prpN(), nearest));
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("20*sqrt(2)"));
        QCOMPARE(typed(), presetWith({{"view.prp[2]", "20*sqrt(2)"}}));
        QCOMPARE(w.document()->undoStack()->count(), 1);

        QTemporaryDir dir;
        const QString file = dir.filePath("view-d.json");
        QVERIFY(w.sceneFiles()->saveScene(file));
        QFile saved(file);
        QVERIFY(saved.open(QIODevice::ReadOnly));
        const QJsonArray prp = QJsonDocument::fromJson(saved.readAll()).object()["view"].toObject()["prp"].toArray();
        QCOMPARE(prp[2], QJsonValue("20*sqrt(2)"));
        QVERIFY(prp[0].isDouble()); // the others are numbers still
        const Scene reloaded = loadScene(file.toStdString());
        QVERIFY(sameBits(std::get<foley::ViewSpec<double>>(reloaded.camera).prp.z(), nearest));
        QCOMPARE(reloaded.typedExpressions, typed());

        // Undo and redo from the field: the number and the text together.
        QTest::keyClick(fieldOf(w, "view.prp", 2), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(sameBits(prpN(), before));
        QCOMPARE(typed(), preset);
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("16*sqrt(17)"));
        QTest::keyClick(fieldOf(w, "view.prp", 2), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(sameBits(prpN(), nearest));
        QCOMPARE(typed(), presetWith({{"view.prp[2]", "20*sqrt(2)"}}));
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("20*sqrt(2)"));

        // The same double typed as a number: the text goes, the number stays; one undoable edit.
        type(fieldOf(w, "view.prp", 2), "28.284271247461902");
        QVERIFY(sameBits(prpN(), nearest));
        QCOMPARE(typed(), presetWith({{"view.prp[2]", ""}}));
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("28.284271247461902"));
        QCOMPARE(w.document()->undoStack()->count(), 2);

        // The root sign as a person types it (one character, U+221A), in another field.
        QLineEdit* u = fieldOf(w, "view.prp", 0);
        type(u, "", false);
        QTest::sendKeyEvent(QTest::Click, u, Qt::Key_unknown, QString::fromUtf8("\u221A"), Qt::NoModifier);
        QTest::keyClicks(u, "2/2");
        QTest::keyClick(u, Qt::Key_Return);
        QCOMPARE(u->text(), QString::fromUtf8("\u221A2/2"));
        QVERIFY(sameBits(std::get<foley::ViewSpec<double>>(w.document()->scene().camera).prp.x(), std::sqrt(0.5)));
        QCOMPARE(typed(), presetWith({{"view.prp[2]", ""}, {"view.prp[0]", "\u221A2/2"}}));

        // Another field's edit keeps it; an edit of its number from elsewhere (a dialog, the camera as code)
        // drops it, and the field shows the number.
        type(fieldOf(w, "view.back"), "-25");
        QCOMPARE(typed(), presetWith({{"view.prp[2]", ""}, {"view.prp[0]", "\u221A2/2"}, {"view.back", ""}}));
        auto view = std::get<foley::ViewSpec<double>>(w.document()->scene().camera);
        view.prp.x() = 0.75;
        w.document()->setCamera(view, "elsewhere");
        QCOMPARE(typed(), presetWith({{"view.prp[2]", ""}, {"view.back", ""}}));
        QCOMPARE(fieldOf(w, "view.prp", 0)->text(), QString("0.75"));
    }

    // A bad expression is refused beside its field with its path and the core's reason; the scene, the
    // number, the text typed before and the undo stack stay; Escape shows the field's text again.
    void aBadExpressionIsRefusedWithItsPathAndReason()
    {
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        QLineEdit* n = fieldOf(w, "view.prp", 2);
        type(n, "20*sqrt(2)");
        const Scene accepted = w.document()->scene();
        const std::string json = documentJson(w);
        const int undoCount = w.document()->undoStack()->count();
        const std::vector<std::pair<QString, QString>> refused = {
            {"1/0", "view.prp[2]: division by zero at character 3 of \"1/0\""},
            {"sqrt(-1)", "view.prp[2]: the square root of -1, a negative number, at character 1 of \"sqrt(-1)\""},
            {"2 +* 3", "view.prp[2]: expected a number, sqrt(...) or ( at character 4 of \"2 +* 3\""},
            {"1e400*1e400", "view.prp[2]: \"1e400*1e400\" is out of the range of a double"}};
        for (const auto& [text, reason] : refused) {
            type(fieldOf(w, "view.prp", 2), text);
            QCOMPARE(panel->errorText("view.prp"), reason);
            QCOMPARE(fieldOf(w, "view.prp", 2)->text(), text); // to be mended
            QVERIFY(w.document()->scene() == accepted);
            QCOMPARE(documentJson(w), json);
            QCOMPARE(w.document()->undoStack()->count(), undoCount);
        }
        QTest::keyClick(fieldOf(w, "view.prp", 2), Qt::Key_Escape);
        QCOMPARE(fieldOf(w, "view.prp", 2)->text(), QString("20*sqrt(2)"));
        QVERIFY(panel->errorText("view.prp").isEmpty());
    }

    void everyFieldTakesValidValuesAndRefusesInvalidOnes_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("projectionType"); // OpenGL: switch to this projection first, -1 to keep
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("valid");
        // Edits of the field, all accepted but the last, which is refused: by the core,
        // or for VRP, which has no degenerate value, as out of range.
        QTest::addColumn<QStringList>("invalid");
        QTest::addColumn<QString>("reasonField"); // where the core puts its reason

        const QString house = "house.json"; // VRP 0, VPN (0,0,1), VUP (0,1,0), PRP (8,6,84), F 60, B 25
        QTest::newRow("VRP") << house << -1 << "view.vrp" << "0=1.5" << QStringList{"2=1e999"} << "view.vrp";
        QTest::newRow("VPN") << house << -1 << "view.vpn" << "0=0.25" << QStringList{"0=0", "2=0"} << "view.vpn";
        QTest::newRow("VUP") << house << -1 << "view.vup" << "2=0.5" << QStringList{"2=0", "1=0"} << "view.vup";
        QTest::newRow("PRP") << house << -1 << "view.prp" << "2=90" << QStringList{"2=50"} << "view.prp";
        QTest::newRow("window") << house << -1 << "view.window" << "1=40" << QStringList{"0=45"} << "view.window";
        // Beyond what the pictures draw (they drew the house 1e300 wide without its volume): refused.
        QTest::newRow("window beyond the pictures") << house << -1 << "view.window" << "1=1e8" << QStringList{"1=1e300"}
                                                    << "view.window";
        QTest::newRow("F") << house << -1 << "view.front" << "0=70" << QStringList{"0=25"} << "view.front";
        QTest::newRow("B") << house << -1 << "view.back" << "0=20" << QStringList{"0=65"} << "view.front";

        const QString perspective = "opengl-perspective.json"; // eye (40,30,100), center (8,8,42), near 30
        QTest::newRow("eye") << perspective << -1 << "camera.look_at.eye" << "0=41" << QStringList{"0=8", "2=42"}
                             << "camera.look_at.up";
        QTest::newRow("center") << perspective << -1 << "camera.look_at.center" << "1=9"
                                << QStringList{"0=40", "2=100"} << "camera.look_at.up";
        QTest::newRow("up") << perspective << -1 << "camera.look_at.up" << "0=0.5" << QStringList{"0=0", "1=0"}
                            << "camera.look_at.up";
        QTest::newRow("fovy") << perspective << -1 << "camera.projection.fovy_deg" << "0=60" << QStringList{"0=180"}
                              << "camera.projection.fovy_deg";
        QTest::newRow("aspect") << perspective << -1 << "camera.projection.aspect" << "0=2" << QStringList{"0=0"}
                                << "camera.projection.aspect";
        QTest::newRow("perspective near") << perspective << -1 << "camera.projection.near" << "0=20"
                                          << QStringList{"0=0"} << "camera.projection.near";
        QTest::newRow("perspective far") << perspective << -1 << "camera.projection.far" << "0=infinity"
                                         << QStringList{"0=30"} << "camera.projection.far";
        QTest::newRow("far beyond the pictures") << perspective << -1 << "camera.projection.far" << "0=1e6"
                                                 << QStringList{"0=1e12"} << "camera.projection.far";

        const QString ortho = "opengl-ortho.json"; // left -20, right 20, bottom -15, top 15, near 10, far 80
        QTest::newRow("ortho left") << ortho << -1 << "camera.projection.left" << "0=-25" << QStringList{"0=20"}
                                    << "camera.projection.right";
        QTest::newRow("ortho right") << ortho << -1 << "camera.projection.right" << "0=25" << QStringList{"0=-20"}
                                     << "camera.projection.right";
        QTest::newRow("ortho bottom") << ortho << -1 << "camera.projection.bottom" << "0=-10" << QStringList{"0=15"}
                                      << "camera.projection.top";
        QTest::newRow("ortho top") << ortho << -1 << "camera.projection.top" << "0=10" << QStringList{"0=-15"}
                                   << "camera.projection.top";
        QTest::newRow("ortho near") << ortho << -1 << "camera.projection.near" << "0=-5" << QStringList{"0=80"}
                                    << "camera.projection.far";
        QTest::newRow("ortho far") << ortho << -1 << "camera.projection.far" << "0=100" << QStringList{"0=10"}
                                   << "camera.projection.far";

        // glFrustum: the ortho scene switched to it (near 10, far 80; the box taken from the look-at distance
        // sqrt(2217) to the near plane: right 200 / sqrt(2217), bottom -150 / sqrt(2217), as doubles). glFrustum
        // refuses only left = right and bottom = top (left > right mirrors the picture).
        QTest::newRow("frustum left") << ortho << 0 << "camera.projection.left" << "0=-25"
                                      << QStringList{"0=20", "0=4.247634593412197"} << "camera.projection.right";
        QTest::newRow("frustum top") << ortho << 0 << "camera.projection.top" << "0=10"
                                     << QStringList{"0=-15", "0=-3.185725945059148"} << "camera.projection.top";
        QTest::newRow("frustum near") << ortho << 0 << "camera.projection.near" << "0=5" << QStringList{"0=-1"}
                                      << "camera.projection.near";
        QTest::newRow("frustum far") << ortho << 0 << "camera.projection.far" << "0=infinity"
                                     << QStringList{"0=10"} << "camera.projection.far";
    }

    void everyFieldTakesValidValuesAndRefusesInvalidOnes()
    {
        QFETCH(QString, scene);
        QFETCH(int, projectionType);
        QFETCH(QString, field);
        QFETCH(QString, valid);
        QFETCH(QStringList, invalid);
        QFETCH(QString, reasonField);
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        QVERIFY(w.sceneFiles()->openScene(scenePath(scene)));
        if (projectionType >= 0) {
            panel->findChild<QComboBox*>("camera.projection.type")->setCurrentIndex(projectionType);
            QCOMPARE(int(std::get<gl::Camera<double>>(w.document()->scene().camera).projection.index()),
                     projectionType);
        }

        // A valid value is taken exactly.
        const int split = valid.indexOf('=');
        const int component = valid.left(split).toInt();
        typeEdit(w, field, valid);
        QVERIFY2(panel->errorText(field).isEmpty(), qPrintable(panel->errorText(field)));
        const double taken = fieldValues(w.document()->scene().camera).at(field)[std::size_t(component)];
        QVERIFY(sameBits(taken, std::strtod(valid.mid(split + 1).toLatin1().constData(), nullptr)));

        // A degenerate value is refused: the reason beside the field, nothing else changes.
        for (int k = 0; k + 1 < invalid.size(); ++k) {
            typeEdit(w, field, invalid[k]);
            QVERIFY2(panel->errorText(field).isEmpty(), qPrintable(panel->errorText(field)));
        }
        const std::string before = documentJson(w);
        const int undoCount = w.document()->undoStack()->count();
        const QImage picture = projectedPicture(w);
        typeEdit(w, field, invalid.last());
        QVERIFY2(!panel->errorText(reasonField).isEmpty(), qPrintable(reasonField));
        QVERIFY(!panel->errorText(field).isEmpty());
        QCOMPARE(documentJson(w), before);
        QCOMPARE(w.document()->undoStack()->count(), undoCount);
        QVERIFY(projectedPicture(w) == picture);

        // Text that is neither a number nor an expression is refused by the panel itself, with its path.
        type(fieldOf(w, field, 0), "abc");
        const QString path = panel->fields(field).size() > 1 ? field + "[0]" : field;
        QCOMPARE(panel->errorText(field), path + ": expected a number, sqrt(...) or ( at character 1 of \"abc\"");
        QCOMPARE(documentJson(w), before);
        QCOMPARE(w.document()->undoStack()->count(), undoCount);
    }

    void escapeRestoresTheField()
    {
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        QLineEdit* x = fieldOf(w, "view.vrp", 0);
        type(x, "2x5");
        QVERIFY(!panel->errorText("view.vrp").isEmpty());
        QTest::keyClick(x, Qt::Key_Escape);
        QCOMPARE(x->text(), QString("8"));
        QVERIFY(panel->errorText("view.vrp").isEmpty());

        // Text not yet committed.
        type(x, "123", false);
        QTest::keyClick(x, Qt::Key_Escape);
        QCOMPARE(x->text(), QString("8"));

        // A number the core refuses (F below B).
        QLineEdit* front = fieldOf(w, "view.front");
        type(front, "-30");
        QVERIFY(!panel->errorText("view.front").isEmpty());
        QTest::keyClick(front, Qt::Key_Escape);
        QCOMPARE(front->text(), QString("24*sqrt(17)/5"));
        QVERIFY(panel->errorText("view.front").isEmpty());
        QVERIFY(!w.document()->undoStack()->canUndo());
    }

    void undoAndRedoShortcutsReachTheDocument()
    {
        MainWindow& w = *window_;
        auto vrpX = [&w] { return std::get<foley::ViewSpec<double>>(w.document()->scene().camera).vrp.x(); };
        QLineEdit* x = fieldOf(w, "view.vrp", 0);
        type(x, "3");
        QCOMPARE(vrpX(), 3.0);
        QCOMPARE(QApplication::focusWidget(), x);

        QTest::keyClick(x, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(vrpX(), 8.0);
        QCOMPARE(x->text(), QString("8"));
        QTest::keyClick(fieldOf(w, "view.vrp", 0), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(vrpX(), 3.0);
        QTest::keyClick(fieldOf(w, "view.vrp", 0), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(vrpX(), 8.0);
        QTest::keyClick(fieldOf(w, "view.vrp", 0), Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(vrpX(), 3.0);

        // Typing not applied: the first Ctrl+Z discards only the typing, the second undoes the last edit.
        x = fieldOf(w, "view.vrp", 0);
        type(x, "7", false);
        const int index = w.document()->undoStack()->index();
        QTest::keyClick(x, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(x->text(), QString("3"));
        QCOMPARE(vrpX(), 3.0);
        QCOMPARE(w.document()->undoStack()->index(), index);
        QTest::keyClick(fieldOf(w, "view.vrp", 0), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(vrpX(), 8.0);
    }

    // Every field says what it is, in Foley's or OpenGL's terms, which component
    // a box holds, and how to type a number.
    void everyFieldHasATooltip()
    {
        MainWindow& w = *window_;
        const std::map<QString, QString> named = {
            {"view.vrp", "View reference point: the origin of the viewing-reference coordinates (VRC), in world"},
            {"view.vpn", "View-plane normal"},
            {"view.vup", "View-up vector"},
            {"view.prp", "Projection reference point (PRP), in VRC (u, v, n)"},
            {"view.window", "umin, umax, vmin, vmax: the window on the view plane, in VRC"},
            {"view.front", "Front clipping plane distance along n from the VRP, in VRC"},
            {"view.back", "Back clipping plane distance along n from the VRP, in VRC"},
            {"camera.look_at.eye", "gluLookAt eye"},
            {"camera.look_at.center", "gluLookAt center"},
            {"camera.look_at.up", "gluLookAt up"},
            {"camera.projection.fovy_deg", "gluPerspective fovy: the vertical field of view, in degrees"},
            {"camera.projection.aspect", "gluPerspective aspect"},
            {"camera.projection.left", "glOrtho left"}};
        for (const QString scene : {"classical/house-dimetric.json", "opengl-perspective.json", "opengl-ortho.json"}) {
            QVERIFY(w.sceneFiles()->openScene(scenePath(scene)));
            for (const auto& entry : fieldValues(w.document()->scene().camera)) {
                QStringList tips;
                for (QLineEdit* box : w.parameters()->fields(entry.first))
                    tips.push_back(QTextDocumentFragment::fromHtml(box->toolTip()).toPlainText());
                QCOMPARE(std::size_t(tips.size()), entry.second.size());
                QCOMPARE(tips.removeDuplicates(), 0); // each box names its component
                for (const QString& tip : tips) {
                    QVERIFY2(tip.contains("'.' decimal point (C locale"), qPrintable(tip));
                    const auto it = named.find(entry.first);
                    QVERIFY2(it == named.end() || tip.contains(it->second), qPrintable(tip));
                }
            }
        }
        QVERIFY(QTextDocumentFragment::fromHtml(fieldOf(w, "camera.look_at.eye", 2)->toolTip())
                    .toPlainText()
                    .contains("eyeZ"));
    }

    void longReasonsShowWhole()
    {
        MainWindow& w = *window_;
        ParameterPanel* panel = w.parameters();
        QVERIFY(w.sceneFiles()->openScene(scenePath("house.json")));

        // VPN made parallel to VUP, then PRP n behind F: two long reasons of the core.
        typeEdit(w, "view.vpn", "1=1");
        foley::ViewSpec<double> parallel = std::get<foley::ViewSpec<double>>(w.document()->scene().camera);
        parallel.vpn.z() = 0;
        foley::ViewSpec<double> behind = std::get<foley::ViewSpec<double>>(w.document()->scene().camera);
        behind.prp.z() = 50;
        const std::vector<std::tuple<QString, QString, foley::ViewSpec<double>>> cases = {
            {"view.vpn", "2=0", parallel}, {"view.prp", "2=50", behind}};
        // At the dock's width, then at the narrowest that shows the fields.
        auto* dock = w.findChild<QDockWidget*>("parametersDock");
        const int narrowest = panel->minimumSizeHint().width() + dock->width() - panel->parentWidget()->width();
        for (const int width : {dock->width(), narrowest}) {
        w.resizeDocks({dock}, {width}, Qt::Horizontal);
        for (const auto& [field, edit, spec] : cases) {
            QString reason, reasonField;
            try {
                buildPipeline(CameraSpec<double>(spec));
                QFAIL("the core takes the specification");
            } catch (const InputError& e) {
                reason = QString::fromStdString(e.reason());
                reasonField = QString::fromStdString(e.field());
            }
            typeEdit(w, field, edit);
            // Said in the panel's names ("view.vpn" is VPN), a reason that goes on from its field's
            // name given it ("VUP: is parallel to view.vpn" read as a new user's slip).
            const QString shown = reasonField == "view.vup" ? "VUP " + QString(reason).replace("view.vpn", "VPN") : reason;
            QVERIFY2(reasonField != "view.vup" || shown.startsWith("VUP is parallel to VPN (angle 0 degrees"), qPrintable(shown));
            QCOMPARE(panel->errorText(reasonField), shown);
            if (field != reasonField)
                QCOMPARE(panel->errorText(field), shown); // beside the field edited, the same words
            QLabel* label = labelShowing(panel, shown);
            QVERIFY(label);
            QTRY_VERIFY(label->heightForWidth(label->width()) <= label->height());
            // Within the dock's visible width.
            QVERIFY(label->mapTo(panel, QPoint(label->width(), 0)).x() <= panel->parentWidget()->width());
            QTest::keyClick(fieldOf(w, field, 2), Qt::Key_Escape);
        }
        }
    }

private:
    std::unique_ptr<MainWindow> window_;
};

int main(int argc, char** argv)
{
    return runAppTests<ParameterTest>(argc, argv);
}

#include "parameter_test.moc"
