#pragma once

// File > Export Stages: every option of `viewpipe export`, in a dialog, its
// formats from export's table (exportFormats). The
// folder proposed is the last one exported into (QSettings "exportFolder"),
// else ViewPipe in the user's pictures.

#include <QDialog>

#include "export/Exporter.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace viewpipe::gui {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    ExportDialog(int stageCount, report::Theme theme, QWidget* parent = nullptr);

    // The options as entered; throws InputError for a bad stage list.
    ExportOptions options() const;
    // Starts from what the window shows: what it leaves out (View > Leave Out) and its layout.
    void startFrom(const std::set<std::string>& hidden, bool storyboard);

    // The pictures folder (else documents, else home) + "/ViewPipe".
    static QString defaultFolder();

private:
    int stageCount_;
    QLineEdit* folder_;
    QSpinBox* width_;
    QSpinBox* height_;
    QSpinBox* scale_;
    QLineEdit* stages_;
    QComboBox* theme_;
    QComboBox* framing_;
    QComboBox* layout_;
    QCheckBox* transparent_;
    QSpinBox* textScale_;
    QComboBox* legend_;
    QDoubleSpinBox* zoom_;
    std::vector<std::pair<std::string, QCheckBox*>> hide_, formats_; // by export's names
    QSpinBox* digits_;
    QCheckBox* animate_;
    QSpinBox* fps_;
};

// How a name export --hide takes reads in the app ("world axes", "PRP").
QString hideText(const std::string& name);

} // namespace viewpipe::gui
