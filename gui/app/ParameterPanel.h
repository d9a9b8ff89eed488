#pragma once

// Every field of the view (Foley) or of the OpenGL camera as spin boxes.
// Edits are forwarded as a whole candidate camera; the core decides whether it
// is valid, and its message is shown next to the field it names.

#include <QMap>
#include <QWidget>

#include "viewpipe/pipeline.hpp"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;

namespace viewpipe::gui {

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget* parent = nullptr);

    // Shows a camera's values; emits nothing.
    void setCamera(const CameraSpec<double>& camera);
    void showError(const QString& field, const QString& reason);
    void clearErrors();

    // For tests and scripting: the spin boxes of a field ("view.front",
    // "view.vrp", "camera.projection.near", ...), and its error text.
    QList<QDoubleSpinBox*> spinBoxes(const QString& field) const;
    QString errorText(const QString& field) const;

signals:
    void cameraEdited(const viewpipe::CameraSpec<double>& camera, const QString& field);

private:
    void rebuild(const CameraSpec<double>& camera);
    void addRow(const QString& field, const QString& label, const QList<double>& values, const QString& tip);
    void addChoice(const QString& field, const QString& label, const QStringList& items, int current);
    CameraSpec<double> read() const;
    void emitEdit(const QString& field);
    QList<double> values(const QString& field) const;

    QFormLayout* form_ = nullptr;
    QWidget* body_ = nullptr;
    QLabel* generalError_ = nullptr;
    QMap<QString, QList<QDoubleSpinBox*>> boxes_;
    QMap<QString, QLabel*> errors_;
    QMap<QString, QComboBox*> choices_;
    QString layoutKey_;
    bool filling_ = false;
};

} // namespace viewpipe::gui
