#include "ClassicalDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>

namespace viewpipe::gui {

ClassicalDialog::ClassicalDialog(const Vec3<double>& boxMin, const Vec3<double>& boxMax, QWidget* parent)
    : QDialog(parent), boxMin_(boxMin), boxMax_(boxMax)
{
    setWindowTitle(tr("Classical Projection"));
    auto* form = new QFormLayout(this);
    kind_ = new QComboBox;
    const QStringList families = {tr("multiview"), tr("multiview"), tr("multiview"), tr("axonometric"),
                                  tr("axonometric"), tr("axonometric"), tr("oblique"), tr("oblique"),
                                  tr("oblique"), tr("perspective"), tr("perspective"), tr("perspective")};
    const auto& kinds = allClassicalKinds();
    for (std::size_t i = 0; i < kinds.size(); ++i)
        kind_->addItem(QString("%1 (%2)").arg(QString::fromStdString(classicalName(kinds[i])), families[int(i)]));
    form->addRow(tr("Class"), kind_);
    auto spin = [](double low, double high, double value, const QString& suffix) {
        auto* box = new QDoubleSpinBox;
        box->setRange(low, high);
        box->setDecimals(2);
        box->setValue(value);
        box->setSuffix(suffix);
        return box;
    };
    azimuth_ = spin(-180, 180, 30, "°");
    elevation_ = spin(-89, 89, 25, "°");
    receding_ = spin(0.05, 2, 0.75, "");
    angle_ = spin(-180, 180, 30, "°");
    form->addRow(tr("Azimuth (axonometric)"), azimuth_);
    form->addRow(tr("Elevation (axonometric)"), elevation_);
    form->addRow(tr("Receding factor (oblique)"), receding_);
    form->addRow(tr("Receding angle (oblique)"), angle_);
    result_ = new QLabel;
    result_->setWordWrap(true);
    form->addRow(result_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Apply"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
    for (QDoubleSpinBox* box : {azimuth_, elevation_, receding_, angle_})
        connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &ClassicalDialog::update);
    connect(kind_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &ClassicalDialog::update);
    setKind(ClassicalKind::Isometric);
}

void ClassicalDialog::setKind(ClassicalKind kind)
{
    const auto& kinds = allClassicalKinds();
    kind_->setCurrentIndex(int(std::find(kinds.begin(), kinds.end(), kind) - kinds.begin()));
    update();
}

QString ClassicalDialog::kindName() const
{
    return QString::fromStdString(classicalName(allClassicalKinds()[std::size_t(kind_->currentIndex())]));
}

foley::ViewSpec<double> ClassicalDialog::view() const
{
    const ClassicalKind kind = allClassicalKinds()[std::size_t(kind_->currentIndex())];
    ClassicalParameters p;
    if (kind == ClassicalKind::Trimetric)
        p.azimuthDegrees = azimuth_->value();
    if (kind == ClassicalKind::Dimetric || kind == ClassicalKind::Trimetric)
        p.elevationDegrees = elevation_->value();
    p.receding = receding_->value();
    p.angleDegrees = angle_->value();
    return classicalView(kind, boxMin_, boxMax_, p);
}

void ClassicalDialog::update()
{
    const ClassicalKind kind = allClassicalKinds()[std::size_t(kind_->currentIndex())];
    azimuth_->setEnabled(kind == ClassicalKind::Trimetric);
    elevation_->setEnabled(kind == ClassicalKind::Dimetric || kind == ClassicalKind::Trimetric);
    receding_->setEnabled(kind == ClassicalKind::Oblique);
    angle_->setEnabled(kind == ClassicalKind::Cavalier || kind == ClassicalKind::Cabinet || kind == ClassicalKind::Oblique);
    try {
        const foley::ViewSpec<double> spec = view();
        const Classification c = classify(CameraSpec<double>(spec));
        QString text = QString::fromStdString(c.description);
        if (c.foreshortening)
            text += tr("; foreshortening x %1, y %2, z %3")
                        .arg((*c.foreshortening)[0], 0, 'g', 4)
                        .arg((*c.foreshortening)[1], 0, 'g', 4)
                        .arg((*c.foreshortening)[2], 0, 'g', 4);
        if (!c.vanishingPoints.empty())
            text += tr("; %1 vanishing points").arg(c.vanishingPoints.size());
        result_->setText(text);
    } catch (const InputError& e) {
        result_->setText(QString::fromStdString(e.what()));
    }
}

} // namespace viewpipe::gui
