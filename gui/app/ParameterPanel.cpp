#include "ParameterPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QRegularExpression>
#include <QVBoxLayout>

#include <cmath>

namespace viewpipe::gui {
namespace {

QList<double> list(const Vec3<double>& v)
{
    return {v.x(), v.y(), v.z()};
}

Vec3<double> vec(const QList<double>& v)
{
    return {v[0], v[1], v[2]};
}

QString layoutKeyOf(const CameraSpec<double>& camera)
{
    if (std::holds_alternative<foley::ViewSpec<double>>(camera))
        return "foley";
    return "gl-" + QString::fromStdString(gl::projectionName(std::get<gl::Camera<double>>(camera).projection));
}

// Switching an OpenGL camera between a box (frustum, ortho) and gluPerspective
// keeps near, far and the near-plane rectangle's size.
gl::ProjectionSpec<double> convertProjection(const gl::ProjectionSpec<double>& from, int type)
{
    double left = -1, right = 1, bottom = -1, top = 1, zNear = 1, zFar = 100;
    if (const auto* p = std::get_if<gl::Perspective<double>>(&from)) {
        top = p->zNear * std::tan(p->fovyDegrees * M_PI / 360);
        bottom = -top;
        right = top * p->aspect;
        left = -right;
        zNear = p->zNear;
        zFar = std::isinf(p->zFar) ? 1000 * p->zNear : p->zFar;
    } else {
        std::visit(
            [&](const auto& box) {
                if constexpr (!std::is_same_v<std::decay_t<decltype(box)>, gl::Perspective<double>>) {
                    left = box.left, right = box.right, bottom = box.bottom, top = box.top;
                    zNear = box.zNear, zFar = std::isinf(box.zFar) ? 1000 * box.zNear : box.zFar;
                }
            },
            from);
    }
    if (type == 0)
        return gl::Frustum<double>{left, right, bottom, top, zNear, zFar};
    if (type == 1)
        return gl::Ortho<double>{left, right, bottom, top, zNear, zFar};
    const double fovy = 2 * std::atan2((top - bottom) / 2, zNear) * 180 / M_PI;
    return gl::Perspective<double>{fovy, (right - left) / (top - bottom), zNear, zFar};
}

} // namespace

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    generalError_ = new QLabel;
    generalError_->setObjectName("generalError");
    generalError_->setWordWrap(true);
    generalError_->setStyleSheet("color: #e5484d; font-weight: bold;");
    generalError_->hide();
    layout->addWidget(generalError_);
    body_ = new QWidget;
    layout->addWidget(body_);
    layout->addStretch();
}

void ParameterPanel::rebuild(const CameraSpec<double>& camera)
{
    // The old form may hold the sender of the signal being handled: replace it later.
    auto* body = new QWidget;
    layout()->replaceWidget(body_, body);
    body_->hide();
    body_->deleteLater();
    body_ = body;
    boxes_.clear();
    errors_.clear();
    choices_.clear();
    form_ = new QFormLayout(body_);
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    layoutKey_ = layoutKeyOf(camera);

    if (const auto* spec = std::get_if<foley::ViewSpec<double>>(&camera)) {
        addChoice("view.projection", tr("Projection"), {tr("perspective"), tr("parallel")},
                  spec->projection == foley::Projection::Perspective ? 0 : 1);
        addRow("view.vrp", "VRP", list(spec->vrp), tr("View reference point (world x, y, z)"));
        addRow("view.vpn", "VPN", list(spec->vpn), tr("View-plane normal (world)"));
        addRow("view.vup", "VUP", list(spec->vup), tr("View-up vector (world)"));
        addRow("view.prp", "PRP", list(spec->prp), tr("Projection reference point (VRC u, v, n)"));
        addRow("view.window", tr("Window"), {spec->window.umin, spec->window.umax, spec->window.vmin, spec->window.vmax},
               tr("umin, umax, vmin, vmax on the view plane"));
        addRow("view.front", tr("Front F"), {spec->front}, tr("Front clipping plane, n in VRC"));
        addRow("view.back", tr("Back B"), {spec->back}, tr("Back clipping plane, n in VRC"));
        return;
    }
    const auto& gl = std::get<gl::Camera<double>>(camera);
    addRow("camera.look_at.eye", tr("Eye"), list(gl.lookAt.eye), tr("gluLookAt eye"));
    addRow("camera.look_at.center", tr("Center"), list(gl.lookAt.center), tr("gluLookAt center"));
    addRow("camera.look_at.up", tr("Up"), list(gl.lookAt.up), tr("gluLookAt up"));
    addChoice("camera.projection.type", tr("Projection"), {"glFrustum", "glOrtho", "gluPerspective"},
              int(gl.projection.index()));
    if (const auto* p = std::get_if<gl::Perspective<double>>(&gl.projection)) {
        addRow("camera.projection.fovy_deg", tr("fovy (deg)"), {p->fovyDegrees}, tr("Vertical field of view"));
        addRow("camera.projection.aspect", tr("Aspect"), {p->aspect}, tr("Width / height"));
        addRow("camera.projection.near", tr("Near"), {p->zNear}, tr("Distance to the near plane"));
        addRow("camera.projection.far", tr("Far"), {p->zFar}, tr("Distance to the far plane"));
        return;
    }
    std::visit(
        [&](const auto& box) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(box)>, gl::Perspective<double>>) {
                addRow("camera.projection.left", tr("Left"), {box.left}, "");
                addRow("camera.projection.right", tr("Right"), {box.right}, "");
                addRow("camera.projection.bottom", tr("Bottom"), {box.bottom}, "");
                addRow("camera.projection.top", tr("Top"), {box.top}, "");
                addRow("camera.projection.near", tr("Near"), {box.zNear}, "");
                addRow("camera.projection.far", tr("Far"), {box.zFar}, "");
            }
        },
        gl.projection);
}

void ParameterPanel::addRow(const QString& field, const QString& label, const QList<double>& values,
                            const QString& tip)
{
    auto* row = new QWidget;
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    QList<QDoubleSpinBox*> boxes;
    for (double value : values) {
        auto* box = new QDoubleSpinBox;
        box->setObjectName(field);
        box->setRange(-1e7, 1e7);
        box->setDecimals(3);
        box->setKeyboardTracking(false);
        box->setValue(value);
        box->setToolTip(tip);
        box->setMinimumWidth(60);
        box->setButtonSymbols(QAbstractSpinBox::NoButtons);
        connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this, field] { emitEdit(field); });
        h->addWidget(box);
        boxes.push_back(box);
    }
    auto* error = new QLabel;
    error->setWordWrap(true);
    error->setStyleSheet("color: #e5484d;");
    error->hide();
    auto* cell = new QWidget;
    auto* v = new QVBoxLayout(cell);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(row);
    v->addWidget(error);
    form_->addRow(label, cell);
    boxes_[field] = boxes;
    errors_[field] = error;
}

void ParameterPanel::addChoice(const QString& field, const QString& label, const QStringList& items, int current)
{
    auto* combo = new QComboBox;
    combo->setObjectName(field);
    combo->addItems(items);
    combo->setCurrentIndex(current);
    connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this, field] { emitEdit(field); });
    form_->addRow(label, combo);
    choices_[field] = combo;
}

void ParameterPanel::setCamera(const CameraSpec<double>& camera)
{
    filling_ = true;
    if (layoutKeyOf(camera) != layoutKey_)
        rebuild(camera);
    auto fill = [this](const QString& field, const QList<double>& values) {
        const QList<QDoubleSpinBox*> boxes = boxes_.value(field);
        for (int i = 0; i < boxes.size() && i < values.size(); ++i)
            boxes[i]->setValue(values[i]);
    };
    if (const auto* spec = std::get_if<foley::ViewSpec<double>>(&camera)) {
        choices_["view.projection"]->setCurrentIndex(spec->projection == foley::Projection::Perspective ? 0 : 1);
        fill("view.vrp", list(spec->vrp));
        fill("view.vpn", list(spec->vpn));
        fill("view.vup", list(spec->vup));
        fill("view.prp", list(spec->prp));
        fill("view.window", {spec->window.umin, spec->window.umax, spec->window.vmin, spec->window.vmax});
        fill("view.front", {spec->front});
        fill("view.back", {spec->back});
    } else {
        const auto& gl = std::get<gl::Camera<double>>(camera);
        fill("camera.look_at.eye", list(gl.lookAt.eye));
        fill("camera.look_at.center", list(gl.lookAt.center));
        fill("camera.look_at.up", list(gl.lookAt.up));
        if (const auto* p = std::get_if<gl::Perspective<double>>(&gl.projection)) {
            fill("camera.projection.fovy_deg", {p->fovyDegrees});
            fill("camera.projection.aspect", {p->aspect});
            fill("camera.projection.near", {p->zNear});
            fill("camera.projection.far", {p->zFar});
        } else {
            std::visit(
                [&](const auto& box) {
                    if constexpr (!std::is_same_v<std::decay_t<decltype(box)>, gl::Perspective<double>>) {
                        fill("camera.projection.left", {box.left});
                        fill("camera.projection.right", {box.right});
                        fill("camera.projection.bottom", {box.bottom});
                        fill("camera.projection.top", {box.top});
                        fill("camera.projection.near", {box.zNear});
                        fill("camera.projection.far", {box.zFar});
                    }
                },
                gl.projection);
        }
    }
    clearErrors();
    filling_ = false;
}

QList<double> ParameterPanel::values(const QString& field) const
{
    QList<double> out;
    for (const QDoubleSpinBox* box : boxes_.value(field))
        out.push_back(box->value());
    return out;
}

CameraSpec<double> ParameterPanel::read() const
{
    if (layoutKey_ == "foley") {
        foley::ViewSpec<double> spec;
        spec.projection = choices_["view.projection"]->currentIndex() == 0 ? foley::Projection::Perspective
                                                                          : foley::Projection::Parallel;
        spec.vrp = vec(values("view.vrp"));
        spec.vpn = vec(values("view.vpn"));
        spec.vup = vec(values("view.vup"));
        spec.prp = vec(values("view.prp"));
        const QList<double> w = values("view.window");
        spec.window = {w[0], w[1], w[2], w[3]};
        spec.front = values("view.front")[0];
        spec.back = values("view.back")[0];
        return spec;
    }
    gl::Camera<double> camera;
    camera.lookAt = {vec(values("camera.look_at.eye")), vec(values("camera.look_at.center")),
                     vec(values("camera.look_at.up"))};
    auto one = [this](const char* key) { return values(QString("camera.projection.") + key)[0]; };
    if (layoutKey_ == "gl-perspective")
        camera.projection = gl::Perspective<double>{one("fovy_deg"), one("aspect"), one("near"), one("far")};
    else if (layoutKey_ == "gl-frustum")
        camera.projection =
            gl::Frustum<double>{one("left"), one("right"), one("bottom"), one("top"), one("near"), one("far")};
    else
        camera.projection =
            gl::Ortho<double>{one("left"), one("right"), one("bottom"), one("top"), one("near"), one("far")};
    const int type = choices_["camera.projection.type"]->currentIndex();
    if (type != int(camera.projection.index()))
        camera.projection = convertProjection(camera.projection, type);
    return camera;
}

void ParameterPanel::emitEdit(const QString& field)
{
    if (filling_)
        return;
    emit cameraEdited(read(), field);
}

void ParameterPanel::showError(const QString& field, const QString& reason)
{
    clearErrors();
    QString key = field;
    key.remove(QRegularExpression("\\[\\d+\\]$"));
    if (QLabel* label = errors_.value(key)) {
        label->setText(reason);
        label->show();
        return;
    }
    generalError_->setText(field + ": " + reason);
    generalError_->show();
}

void ParameterPanel::clearErrors()
{
    for (QLabel* label : errors_)
        label->hide();
    generalError_->hide();
}

QList<QDoubleSpinBox*> ParameterPanel::spinBoxes(const QString& field) const
{
    return boxes_.value(field);
}

QString ParameterPanel::errorText(const QString& field) const
{
    const QLabel* label = errors_.value(field);
    return label && !label->isHidden() ? label->text() : QString();
}

} // namespace viewpipe::gui
