#include "ParameterPanel.h"
#include "PanelCombo.h"

#include <QApplication>
#include <QComboBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QStyle>
#include <QStyleOptionFrame>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "NumberText.h"
#include "viewpipe/camera_choices.hpp"
#include "viewpipe/exact.hpp"
#include "viewpipe/format.hpp"

namespace viewpipe::gui {
namespace {

const QString kProjectionPrefix = QString::fromStdString(gl::kProjectionField);

QString layoutKeyOf(const CameraSpec<double>& camera)
{
    if (std::holds_alternative<foley::ViewSpec<double>>(camera))
        return "foley";
    const auto& projection = std::get<gl::Camera<double>>(camera).projection;
    return "gl-" + QString::fromStdString(projectionName(projectionKind(projection)));
}

// The numbers a field stands for in a camera, one per component; none for a
// field the camera does not have.
QList<double*> numbersOf(CameraSpec<double>& camera, const QString& field)
{
    auto vec = [](Vec3<double>& v) { return QList<double*>{&v.x(), &v.y(), &v.z()}; };
    if (auto* s = std::get_if<foley::ViewSpec<double>>(&camera)) {
        if (field == "view.vrp")
            return vec(s->vrp);
        if (field == "view.vpn")
            return vec(s->vpn);
        if (field == "view.vup")
            return vec(s->vup);
        if (field == "view.prp")
            return vec(s->prp);
        if (field == "view.window")
            return {&s->window.umin, &s->window.umax, &s->window.vmin, &s->window.vmax};
        if (field == "view.front")
            return {&s->front};
        if (field == "view.back")
            return {&s->back};
        return {};
    }
    auto& gl = std::get<gl::Camera<double>>(camera);
    if (field == "camera.look_at.eye")
        return vec(gl.lookAt.eye);
    if (field == "camera.look_at.center")
        return vec(gl.lookAt.center);
    if (field == "camera.look_at.up")
        return vec(gl.lookAt.up);
    if (!field.startsWith(kProjectionPrefix))
        return {};
    const QString name = field.mid(kProjectionPrefix.size());
    return std::visit(
        [&name](auto& p) -> QList<double*> {
            if constexpr (std::is_same_v<std::decay_t<decltype(p)>, gl::Perspective<double>>) {
                if (name == "fovy_deg")
                    return {&p.fovyDegrees};
                if (name == "aspect")
                    return {&p.aspect};
            } else {
                if (name == "left")
                    return {&p.left};
                if (name == "right")
                    return {&p.right};
                if (name == "bottom")
                    return {&p.bottom};
                if (name == "top")
                    return {&p.top};
            }
            if (name == "near")
                return {&p.zNear};
            if (name == "far")
                return {&p.zFar};
            return {};
        },
        gl.projection);
}

// The width a line edit needs to show all its text, as QLineEdit::sizeHint
// counts it: the text, 2-pixel margins and the cursor, in the style's frame.
int wholeTextWidth(const QLineEdit* box)
{
    QStyleOptionFrame option;
    option.initFrom(box);
    option.lineWidth = box->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, &option, box);
    const QSize text(box->fontMetrics().horizontalAdvance(box->text()) + 5, box->fontMetrics().height());
    return box->style()->sizeFromContents(QStyle::CT_LineEdit, &option, text, box).width();
}

// A field's boxes side by side, or one under another when side by side (an
// equal share of the width each) some text would not show whole.
class NumbersLayout : public QBoxLayout {
public:
    NumbersLayout() : QBoxLayout(LeftToRight) {}

    void setGeometry(const QRect& rect) override
    {
        if (!turning_) {
            int widest = 0;
            for (int i = 0; i < count(); ++i)
                if (const auto* box = qobject_cast<const QLineEdit*>(itemAt(i)->widget()))
                    widest = std::max({widest, wholeTextWidth(box), box->minimumWidth()});
            const int sideBySide = count() * widest + spacing() * (count() - 1);
            // A margin before turning back, wider than a scroll bar: stacked boxes can make the dock's
            // scroll bar appear, taking that width, and side by side make it go, turning them to and fro.
            const int margin = QApplication::style()->pixelMetric(QStyle::PM_ScrollBarExtent) + 16;
            const Direction wanted = sideBySide + (direction() == TopToBottom ? margin : 0) <= rect.width()
                                         ? LeftToRight
                                         : TopToBottom;
            if (direction() != wanted) {
                turning_ = true; // the layouts around answer by laying this one out again
                setDirection(wanted);
                turning_ = false;
            }
        }
        QBoxLayout::setGeometry(rect);
    }

private:
    bool turning_ = false;
};

QString tooltip(const QString& title, const QString& text)
{
    return "<p><b>" + title.toHtmlEscaped() + "</b> — " + text.toHtmlEscaped() + "</p>";
}

} // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    generalError_ = new QLabel;
    generalError_->setObjectName("generalError");
    generalError_->setWordWrap(true);
    generalError_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    generalError_->setStyleSheet("color: #e5484d; font-weight: bold;");
    generalError_->hide();
    layout->addWidget(generalError_);
    body_ = new QWidget;
    layout->addWidget(body_);
    layout->addStretch();
}

void ParameterPanel::rebuild(const CameraSpec<double>& camera)
{
    // The new form is made whole before it is shown: its fields show with it, at once.
    auto* body = new QWidget;
    boxes_.clear();
    numbers_.clear();
    errors_.clear();
    labels_.clear();
    choices_.clear();
    names_.clear();
    // Rows in a box layout, not a QFormLayout: it gives every wrapped reason the height of its text.
    rows_ = new QVBoxLayout(body);
    rows_->setContentsMargins(0, 0, 0, 0);
    layoutKey_ = layoutKeyOf(camera);
    addFields(camera);
    alignNames();
    // The old form may hold the sender of the signal being handled: replace it later.
    delete layout()->replaceWidget(body_, body); // the old form's layout item is ours to delete
    body->show();
    body_->hide();
    body_->deleteLater();
    body_ = body;
}

void ParameterPanel::addFields(const CameraSpec<double>& camera)
{
    if (std::holds_alternative<foley::ViewSpec<double>>(camera)) {
        addChoice(camera, "view.projection",
                  tooltip(tr("Projection"), tr("perspective: the center of projection is the PRP; parallel: the "
                                               "direction of projection runs from the PRP to the window's center "
                                               "(CW).")));
        const QStringList xyz = {"x", "y", "z"};
        addRow("view.vrp", "VRP", xyz,
               tr("View reference point: the origin of the viewing-reference coordinates (VRC), in world "
                  "coordinates."));
        addRow("view.vpn", "VPN", xyz,
               tr("View-plane normal: the direction of the VRC's n axis, in world coordinates; any length but "
                  "zero."));
        addRow("view.vup", "VUP", xyz,
               tr("View-up vector: its projection on the view plane is the VRC's v axis, in world coordinates; "
                  "any length but zero, not parallel to the VPN."));
        addRow("view.prp", "PRP", {"u", "v", "n"},
               tr("Projection reference point (PRP), in VRC (u, v, n): the center of projection; for a parallel "
                  "projection, the start of the direction of projection towards the window's center."));
        addRow("view.window", tr("Window"), {"umin", "umax", "vmin", "vmax"},
               tr("umin, umax, vmin, vmax: the window on the view plane, in VRC; umin < umax, vmin < vmax."));
        addRow("view.front", tr("Front F"), {},
               tr("Front clipping plane distance along n from the VRP, in VRC (the plane n = F); F > B."));
        addRow("view.back", tr("Back B"), {},
               tr("Back clipping plane distance along n from the VRP, in VRC (the plane n = B); B < F."));
        return;
    }
    const auto& gl = std::get<gl::Camera<double>>(camera);
    addRow("camera.look_at.eye", tr("Eye"), {"eyeX", "eyeY", "eyeZ"},
           tr("gluLookAt eye: the position of the eye, in world coordinates."));
    addRow("camera.look_at.center", tr("Center"), {"centerX", "centerY", "centerZ"},
           tr("gluLookAt center: the point looked at, in world coordinates; not the eye."));
    addRow("camera.look_at.up", tr("Up"), {"upX", "upY", "upZ"},
           tr("gluLookAt up: the up direction, in world coordinates; any length but zero, not parallel to "
              "center − eye."));
    addChoice(camera, "camera.api",
              tooltip(tr("API"), tr("Whose conventions the projection follows: OpenGL's depth runs from -1 (near) to "
                                    "1 (far), the others' from 0 to 1, and Vulkan's y points down. A stage after "
                                    "the projection takes OpenGL's clip coordinates to the API's.")));
    addChoice(camera, "camera.handedness",
              tooltip(tr("Handedness"), tr("Right-handed (gluLookAt, glm::lookAtRH): eye axes s, u, -f. "
                                           "Left-handed (XMMatrixLookAtLH, glm::lookAtLH): eye axes up × f, u, f; "
                                           "with the same numbers the picture is mirrored.")));
    addChoice(camera, "camera.depth",
              tooltip(tr("Depth"), tr("Reversed depth exchanges near and far in the depth range: with a float "
                                      "depth buffer, precision then stays nearly even with distance.")));
    addChoice(camera, "camera.projection.type",
              tooltip(tr("Projection"), tr("The projection matrix: a frustum, orthographic or a perspective by its "
                                           "field of view (OpenGL's glFrustum, glOrtho, gluPerspective; the "
                                           "fields below are named as OpenGL names them). Switching keeps near, "
                                           "far and the size of the near plane's rectangle.")));
    if (std::holds_alternative<gl::Perspective<double>>(gl.projection)) {
        addRow("camera.projection.fovy_deg", tr("fovy (deg)"), {},
               tr("gluPerspective fovy: the vertical field of view, in degrees; 0 < fovy < 180."));
        addRow("camera.projection.aspect", tr("Aspect"), {},
               tr("gluPerspective aspect: the width of the field of view divided by its height (no unit)."));
        addRow("camera.projection.near", tr("Near"), {},
               tr("gluPerspective zNear: the distance from the eye to the near clipping plane, in eye "
                  "coordinates (world units); greater than 0."));
        addRow("camera.projection.far", tr("Far"), {},
               tr("gluPerspective zFar: the distance from the eye to the far clipping plane, in eye coordinates "
                  "(world units); greater than 0 and not zNear (nearer than zNear, depth runs backwards, as "
                  "glFrustum allows), or infinity for no far plane."));
        return;
    }
    if (std::holds_alternative<gl::Frustum<double>>(gl.projection)) {
        const QString edge = tr("glFrustum %1: the %2 edge of the near plane's rectangle (%3 = %1 at z = "
                                "−nearVal), in eye coordinates.");
        addRow("camera.projection.left", tr("Left"), {}, edge.arg("left", tr("left"), "x"));
        addRow("camera.projection.right", tr("Right"), {}, edge.arg("right", tr("right"), "x"));
        addRow("camera.projection.bottom", tr("Bottom"), {}, edge.arg("bottom", tr("bottom"), "y"));
        addRow("camera.projection.top", tr("Top"), {}, edge.arg("top", tr("top"), "y"));
        addRow("camera.projection.near", tr("Near"), {},
               tr("glFrustum nearVal: the distance from the eye to the near clipping plane, in eye coordinates "
                  "(world units); greater than 0."));
        addRow("camera.projection.far", tr("Far"), {},
               tr("glFrustum farVal: the distance from the eye to the far clipping plane, in eye coordinates "
                  "(world units); greater than 0 and not nearVal (nearer than nearVal, depth runs backwards, as "
                  "glFrustum's reference allows), or infinity for no far plane."));
        return;
    }
    const QString plane = tr("glOrtho %1: the %2 clipping plane %3 = %1, in eye coordinates (world units).");
    addRow("camera.projection.left", tr("Left"), {}, plane.arg("left", tr("left"), "x"));
    addRow("camera.projection.right", tr("Right"), {}, plane.arg("right", tr("right"), "x"));
    addRow("camera.projection.bottom", tr("Bottom"), {}, plane.arg("bottom", tr("bottom"), "y"));
    addRow("camera.projection.top", tr("Top"), {}, plane.arg("top", tr("top"), "y"));
    addRow("camera.projection.near", tr("Near"), {},
           tr("glOrtho nearVal: the distance from the eye to the near clipping plane z = −nearVal, in eye "
              "coordinates (world units); may be negative, not equal to farVal."));
    addRow("camera.projection.far", tr("Far"), {},
           tr("glOrtho farVal: the distance from the eye to the far clipping plane z = −farVal, in eye "
              "coordinates (world units); not equal to nearVal."));
}

void ParameterPanel::addRow(const QString& field, const QString& label, const QStringList& components,
                            const QString& tip)
{
    const QString entry = "<p>" +
                          tr("Type a number with a '.' decimal point (C locale, whatever the system's), e.g. "
                             "0.25, -45 or 1.5e-3, or an exact expression such as 20*sqrt(2), √2/2 or 1/3 "
                             "(+ - * /, sqrt() or √, parentheses), kept as typed; Return applies it, Escape "
                             "restores the value.")
                              .toHtmlEscaped() +
                          "</p>";
    auto* row = new QHBoxLayout;
    row->addWidget(addName(label, tooltip(label, tip)));
    auto* numbers = new NumbersLayout;
    row->addLayout(numbers, 1);
    QList<QLineEdit*> boxes;
    for (int i = 0; i < std::max(1, int(components.size())); ++i) {
        auto* box = new QLineEdit;
        box->setObjectName(field);
        box->setToolTip(tooltip(components.isEmpty() ? label : label + ": " + components[i], tip) + entry);
        box->setMinimumWidth(50);
        box->installEventFilter(this);
        connect(box, &QLineEdit::editingFinished, this, [this, box] { commit(box); });
        numbers->addWidget(box);
        boxes.push_back(box);
    }
    rows_->addLayout(row);
    // The reason spans the panel's width under its field and wraps: it is shown whole.
    auto* error = new QLabel;
    error->setWordWrap(true);
    error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error->setStyleSheet("color: #e5484d;");
    error->hide();
    rows_->addWidget(error);
    boxes_[field] = boxes;
    numbers_[field] = numbers;
    errors_[field] = error;
    labels_[field] = label;
}

QLabel* ParameterPanel::addName(const QString& label, const QString& tip)
{
    auto* name = new QLabel(label);
    name->setToolTip(tip);
    names_.push_back(name);
    return name;
}

void ParameterPanel::alignNames()
{
    int width = 0;
    for (const QLabel* name : names_)
        width = std::max(width, name->sizeHint().width());
    for (QLabel* name : names_)
        name->setMinimumWidth(width);
}

void ParameterPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::FontChange)
        alignNames(); // the names have their new font already
    QWidget::changeEvent(event);
}

// A choice of the camera's (cameraChoices: its title and options), with the app's tooltip.
void ParameterPanel::addChoice(const CameraSpec<double>& camera, const std::string& field, const QString& tip)
{
    const std::vector<CameraChoice> choices = cameraChoices(camera);
    const auto choice =
        std::find_if(choices.begin(), choices.end(), [&](const CameraChoice& c) { return c.field == field; });
    if (choice == choices.end())
        return; // not this camera's
    QStringList items;
    for (const std::string& option : choice->options)
        items << QString::fromStdString(option);
    const QString label = QString::fromStdString(choice->title);
    auto* combo = new QComboBox;
    combo->setObjectName(QString::fromStdString(field));
    combo->addItems(items);
    fitComboToItsRow(combo);
    combo->setToolTip(tip);
    connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            [this, name = combo->objectName()](int index) { choose(name, index); });
    auto* row = new QHBoxLayout;
    row->addWidget(addName(label, tip));
    row->addWidget(combo, 1);
    rows_->addLayout(row);
    choices_[combo->objectName()] = combo;
}

void ParameterPanel::setCamera(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed)
{
    camera_ = camera;
    typed_ = typed;
    if (layoutKeyOf(camera) != layoutKey_) {
        filling_ = true; // hiding the old form moves the focus: no edit from its fields
        rebuild(camera);
        filling_ = false;
    }
    fill(nullptr);
    clearErrors();
}

void ParameterPanel::fill(const QWidget* except)
{
    filling_ = true;
    for (auto it = boxes_.cbegin(); it != boxes_.cend(); ++it) {
        const QList<double*> numbers = numbersOf(camera_, it.key());
        for (int i = 0; i < it.value().size() && i < numbers.size(); ++i) {
            QLineEdit* box = it.value()[i];
            const QString text = shownText(box, *numbers[i]);
            if (box == except || box->text() == text)
                continue;
            box->setText(text);
            box->setCursorPosition(0); // the leading digits show when the box is narrow
        }
    }
    for (QBoxLayout* numbers : numbers_)
        numbers->invalidate(); // their texts decide between side by side and one under another
    for (const CameraChoice& choice : cameraChoices(camera_))
        if (QComboBox* combo = choices_.value(QString::fromStdString(choice.field))) {
            for (int k = 0; k < combo->count() && k < int(choice.options.size()); ++k) // as the API names them
                if (const QString option = QString::fromStdString(choice.options[std::size_t(k)]); combo->itemText(k) != option)
                    combo->setItemText(k, option);
            if (combo != except)
                combo->setCurrentIndex(choice.chosen);
        }
    filling_ = false;
}

void ParameterPanel::commit(QLineEdit* box)
{
    if (filling_)
        return;
    const QString field = box->objectName();
    const int component = boxes_.value(field).indexOf(box);
    CameraSpec<double> candidate = camera_;
    double* number = numbersOf(candidate, field).value(component);
    if (!number)
        return;
    // The candidate is the camera shown with this one number replaced: text
    // left in other fields (refused or not applied) is not part of it.
    fill(box);
    double value = 0;
    // Far may be infinity where the projection allows it (not glOrtho's).
    const auto* glCamera = std::get_if<gl::Camera<double>>(&camera_);
    const bool infinityAllowed = field == kProjectionPrefix + "far" && glCamera &&
                                 !std::holds_alternative<gl::Ortho<double>>(glCamera->projection);
    const std::string path = pathOf(box);
    std::map<std::string, std::string> typed = typed_;
    typed.erase(path); // a number typed replaces an expression
    if (!readNumber(box->text(), infinityAllowed, value).isEmpty()) {
        // Not a number: an exact expression, as a scene file may hold it, read by the core.
        const std::string text = box->text().trimmed().toStdString();
        try {
            value = double(parseExact(text));
        } catch (const std::exception& e) {
            refuse(field, field, QString::fromStdString(path + ": " + e.what()), true);
            return;
        }
        if (!std::isfinite(value)) {
            refuse(field, field, QString::fromStdString(path) + ": " + tr("\"%1\" is out of the range of a double")
                                                                           .arg(QString::fromStdString(text)),
                   true);
            return;
        }
        typed[path] = text;
    }
    if (sameBits(value, *number) && typed == typed_) {
        if (box->text() != valueText(box))
            box->setText(valueText(box));
        if (refused_ == field)
            clearErrors();
        return;
    }
    *number = value;
    emitEdit(candidate, typed, field);
}

void ParameterPanel::choose(const QString& field, int index)
{
    if (filling_)
        return;
    CameraSpec<double> candidate;
    try {
        candidate = withChoice(camera_, field.toStdString(), index);
    } catch (const InputError& e) {
        refuse(field, QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
        return;
    }
    fill(choices_.value(field));
    emitEdit(candidate, typed_, field);
}

void ParameterPanel::emitEdit(const CameraSpec<double>& candidate, const std::map<std::string, std::string>& typed,
                              const QString& field)
{
    editing_ = field;
    emit cameraEdited(candidate, typed, field);
    editing_.clear();
}

void ParameterPanel::showError(const QString& field, const QString& reason)
{
    refuse(editing_, field, reason);
}

void ParameterPanel::refuse(const QString& edited, const QString& field, const QString& reason, bool asWritten)
{
    clearErrors();
    QString key = field;
    key.remove(QRegularExpression("\\[\\d+\\]$"));
    const QString text = asWritten ? reason : reasonText(key, reason);
    // Away from its field the reason says which it is about.
    const QString name = labels_.value(key, field);
    const QString named = text.startsWith(name) ? text : name + ": " + text;
    QLabel* label = errors_.value(key);
    if (label) {
        label->setText(text);
        label->show();
    } else {
        generalError_->setText(named);
        generalError_->show();
    }
    if (QLabel* beside = errors_.value(edited); beside && beside != label) {
        beside->setText(named);
        beside->show();
    }
    refused_ = edited.isEmpty() ? key : edited;
}

QString ParameterPanel::reasonText(const QString& field, const QString& reason) const
{
    QString text = reason;
    QStringList paths = labels_.keys();
    std::sort(paths.begin(), paths.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
    for (const QString& path : paths) // whole paths only: "view.vp" is no part of "view.vpn"
        text.replace(QRegularExpression("(?<![\\w.])" + QRegularExpression::escape(path) + "(?![\\w])"), labels_.value(path));
    if (!text.isEmpty() && text.front().isLower())
        text = labels_.value(field, field) + " " + text;
    return text;
}

void ParameterPanel::clearErrors()
{
    for (QLabel* label : errors_)
        label->hide();
    generalError_->hide();
    refused_.clear();
}

std::string ParameterPanel::pathOf(QLineEdit* box) const
{
    const QList<QLineEdit*> boxes = boxes_.value(box->objectName());
    const std::string field = box->objectName().toStdString();
    return boxes.size() > 1 ? field + "[" + std::to_string(boxes.indexOf(box)) + "]" : field;
}

QString ParameterPanel::shownText(QLineEdit* box, double value) const
{
    const auto typed = typed_.find(pathOf(box));
    return typed != typed_.end() ? QString::fromStdString(typed->second) : numberText(value);
}

QString ParameterPanel::valueText(QLineEdit* box)
{
    const QString field = box->objectName();
    const double* number = numbersOf(camera_, field).value(boxes_.value(field).indexOf(box));
    return number ? shownText(box, *number) : box->text();
}

bool ParameterPanel::isRestorable(QLineEdit* box)
{
    return box->text() != valueText(box) || refused_ == box->objectName();
}

void ParameterPanel::restore(QLineEdit* box)
{
    box->setText(valueText(box));
    box->setCursorPosition(0);
    if (refused_ == box->objectName())
        clearErrors();
}

bool ParameterPanel::eventFilter(QObject* watched, QEvent* event)
{
    auto* box = qobject_cast<QLineEdit*>(watched);
    if (!box || (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress))
        return QWidget::eventFilter(watched, event);
    const auto* key = static_cast<QKeyEvent*>(event);
    // Typing not applied yet: Escape, and the first Ctrl+Z, discard it (the next Ctrl+Z undoes the last edit).
    const bool discards = isRestorable(box) && ((key->key() == Qt::Key_Escape && key->modifiers() == Qt::NoModifier) ||
                                                key->matches(QKeySequence::Undo));
    if (event->type() == QEvent::ShortcutOverride) {
        if (discards) {
            event->accept(); // the field's (below), not the window's shortcut
            return false;
        }
        // Undo and redo are the document's: the field's own text undo would swallow them.
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo) ||
            (key->key() == Qt::Key_Y && key->modifiers() == Qt::ControlModifier)) {
            event->ignore();
            return true;
        }
        return false;
    }
    if (discards) {
        restore(box);
        return true;
    }
    return false;
}

QList<QLineEdit*> ParameterPanel::fields(const QString& field) const
{
    return boxes_.value(field);
}

QString ParameterPanel::errorText(const QString& field) const
{
    const QLabel* label = errors_.value(field);
    return label && !label->isHidden() ? label->text() : QString();
}

} // namespace viewpipe::gui
