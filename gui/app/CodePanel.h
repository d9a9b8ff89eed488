#pragma once

// The camera as code (report/…/code.hpp) in the dialect chosen: legacy
// OpenGL, glm, DirectXMath, three.js or wgpu-matrix. Every number that stands
// for a camera parameter can be dragged (left, right), stepped (Up, Down),
// typed over (double-click, Enter), and says what it is in its tooltip; each
// change is forwarded as a whole candidate camera, a drag as one gesture.
// Code pasted into the panel sets the camera; Copy puts the code on the
// clipboard.

#include <QWidget>

#include <optional>

#include "viewpipe/pipeline.hpp"
#include "viewpipe/report/code.hpp"

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace viewpipe::gui {

class CodeView;

class CodePanel : public QWidget {
    Q_OBJECT
public:
    explicit CodePanel(QWidget* parent = nullptr);

    void setCamera(const CameraSpec<double>& camera);
    void showError(const QString& reason);
    void clearError();

    // For tests and scripting.
    CodeView* codeView() const { return view_; }
    QPlainTextEdit* pasteBox() const { return paste_; }
    void setDialect(report::Dialect dialect);
    // Sets the camera from code, as pasting it does.
    void applyCode(const QString& text);

signals:
    // `gesture` >= 0 while one drag goes on: its edits make one undoable edit.
    void cameraEdited(const viewpipe::CameraSpec<double>& camera, const QString& field, int gesture);

private:
    void regenerate();
    void setNumber(std::size_t index, double value, int gesture);

    QComboBox* dialects_ = nullptr;
    CodeView* view_ = nullptr;
    QPlainTextEdit* paste_ = nullptr;
    QLabel* note_ = nullptr;
    QLabel* error_ = nullptr;
    std::optional<gl::Camera<double>> camera_;
    report::CameraCode code_;
};

// The code, drawn in a fixed-pitch font with its numbers marked.
class CodeView : public QWidget {
    Q_OBJECT
public:
    explicit CodeView(QWidget* parent = nullptr);
    void setCode(const report::CameraCode& code);
    const report::CameraCode& code() const { return code_; }

    // Where number `index` is drawn, in widget coordinates; empty if there is none.
    QRect numberRect(std::size_t index) const;
    std::optional<std::size_t> selected() const { return selected_; }
    void select(std::size_t index);
    // The editor open over a number (double-click or Enter), if any.
    QLineEdit* editor() const { return editor_; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override;
    int heightForWidth(int width) const override;

signals:
    void numberChanged(std::size_t index, double value, int gesture);
    void numberTyped(std::size_t index, const QString& text);
    void pasted(const QString& text);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool event(QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool focusNextPrevChild(bool next) override;

private:
    std::optional<std::size_t> numberAt(const QPoint& point) const;
    void openEditor(std::size_t index);
    // Closes the editor over a number, typing its text in when `commit`.
    void closeEditor(bool commit);
    bool eventFilter(QObject* watched, QEvent* event) override;
    void step(std::size_t index, int steps, int gesture);

    report::CameraCode code_;
    std::optional<std::size_t> selected_;
    std::optional<std::size_t> hovered_;
    struct Drag {
        std::size_t index;
        int startX;
        double startValue;
        int gesture;
    };
    std::optional<Drag> drag_;
    int gestures_ = 0;
    QLineEdit* editor_ = nullptr;
};

} // namespace viewpipe::gui
