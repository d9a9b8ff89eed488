#pragma once

// Help > Guide: what a student opening ViewPipe for the first time needs, in
// a window that stays open beside the app (not modal): the two views, the
// stepper, each stage of Foley's N_per and N_par and of the OpenGL forms,
// the panels, effects, tracing, files and export, themes, and the keys.

#include <QDialog>

class QTextBrowser;

namespace viewpipe::gui {

class GuideDialog : public QDialog {
    Q_OBJECT
public:
    explicit GuideDialog(QWidget* parent = nullptr);

    // Shows the parent's guide, made on first use, and brings it to the front.
    static GuideDialog* showFor(QWidget* parent);

    QTextBrowser* browser() { return browser_; }

private:
    QTextBrowser* browser_;
};

} // namespace viewpipe::gui
