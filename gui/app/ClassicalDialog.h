#pragma once

// View > Classical Projection: choose a class of seed 001 and its parameters;
// the dialog gives the view that realizes it for the scene's objects.

#include <QDialog>

#include "viewpipe/classical.hpp"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace viewpipe::gui {

class ClassicalDialog : public QDialog {
    Q_OBJECT
public:
    ClassicalDialog(const Vec3<double>& boxMin, const Vec3<double>& boxMax, QWidget* parent = nullptr);

    // The view for the chosen class; throws InputError for bad parameters.
    foley::ViewSpec<double> view() const;
    QString kindName() const;
    void setKind(ClassicalKind kind);

private:
    void update();

    Vec3<double> boxMin_, boxMax_;
    QComboBox* kind_;
    QDoubleSpinBox* azimuth_;
    QDoubleSpinBox* elevation_;
    QDoubleSpinBox* receding_;
    QDoubleSpinBox* angle_;
    QLabel* result_;
};

} // namespace viewpipe::gui
