#pragma once

// Every field of the view (Foley) or of the OpenGL camera as text fields that
// hold exact doubles, shown in their shortest round-trip form, or the exact
// expression typed for them ("20*sqrt(2)", "√2/2", "1/3": the core's
// parseExact reads it; the scene keeps the text by field path and the double
// nearest its value). An edit replaces only the component edited in the last
// camera shown and is forwarded as a whole candidate camera with the scene's
// expressions; the core decides whether it is valid, and its message is shown
// next to the field it names. Text that is neither a number nor an expression
// is refused here, with the field's path and the reason beside the field, and
// nothing is forwarded.

#include <QMap>
#include <QWidget>

#include <map>
#include <string>

#include "viewpipe/pipeline.hpp"

class QBoxLayout;
class QComboBox;
class QLabel;
class QLineEdit;
class QVBoxLayout;

namespace viewpipe::gui {

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget* parent = nullptr);

    // Shows a camera's values, a field with an expression in `typed` (a scene's typedExpressions) as typed;
    // emits nothing.
    void setCamera(const CameraSpec<double>& camera, const std::map<std::string, std::string>& typed);
    void showError(const QString& field, const QString& reason);
    void clearErrors();

    // For tests and scripting: the text fields of a field ("view.front",
    // "view.vrp", "camera.projection.near", ...), one per component, and its error text.
    QList<QLineEdit*> fields(const QString& field) const;
    QString errorText(const QString& field) const;

signals:
    // `typed`: the scene's expressions with the edited field's text, or without it where a number was typed.
    void cameraEdited(const viewpipe::CameraSpec<double>& camera, const std::map<std::string, std::string>& typed,
                      const QString& field);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void rebuild(const CameraSpec<double>& camera);
    void addFields(const CameraSpec<double>& camera);
    // One box per component (their names), one box when there are none.
    void addRow(const QString& field, const QString& label, const QStringList& components, const QString& tip);
    QLabel* addName(const QString& label, const QString& tip);
    // The rows' names take the width of the widest: the fields line up.
    void alignNames();
    void addChoice(const CameraSpec<double>& camera, const std::string& field, const QString& tip);
    // Shows camera_ in every field but `except`.
    void fill(const QWidget* except);
    void commit(QLineEdit* box);
    void choose(const QString& field, int index);
    void emitEdit(const CameraSpec<double>& candidate, const std::map<std::string, std::string>& typed,
                  const QString& field);
    // The reason goes beside `field`, and beside `edited` when the core names another field;
    // `asWritten`: shown as it is, field paths not put in the panel's names.
    void refuse(const QString& edited, const QString& field, const QString& reason, bool asWritten = false);
    // A reason of the core as the panel says it: fields named by their labels ("VPN", not
    // "view.vpn"), and a reason that goes on from its field's name ("is parallel to …") given it.
    QString reasonText(const QString& field, const QString& reason) const;
    // The path of a box's number as a scene file names it ("view.prp[2]", "view.front").
    std::string pathOf(QLineEdit* box) const;
    // What a box shows for `value`: the expression typed for it, else the number.
    QString shownText(QLineEdit* box, double value) const;
    // The text of the value a box stands for in camera_.
    QString valueText(QLineEdit* box);
    // Escape: whether the box shows other text than its value, or a refusal, and putting the value back.
    bool isRestorable(QLineEdit* box);
    void restore(QLineEdit* box);

    QVBoxLayout* rows_ = nullptr;
    QWidget* body_ = nullptr;
    QLabel* generalError_ = nullptr;
    QMap<QString, QList<QLineEdit*>> boxes_;
    QMap<QString, QBoxLayout*> numbers_; // the layout of a field's boxes
    QMap<QString, QLabel*> errors_;
    QMap<QString, QString> labels_;
    QMap<QString, QComboBox*> choices_;
    QList<QLabel*> names_; // of the rows, one width for all
    QString layoutKey_;
    CameraSpec<double> camera_;
    std::map<std::string, std::string> typed_; // the expressions of the scene shown, by field path
    QString editing_; // the field whose candidate is being forwarded
    QString refused_; // the field whose refused edit the messages are about
    bool filling_ = false;
};

} // namespace viewpipe::gui
