#include "ExportDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace viewpipe::gui {

ExportDialog::ExportDialog(int stageCount, Theme theme, QWidget* parent) : QDialog(parent), stageCount_(stageCount)
{
    setWindowTitle(tr("Export Stages"));
    auto* form = new QFormLayout(this);

    folder_ = new QLineEdit(QDir::current().filePath("slides"));
    auto* browse = new QPushButton(tr("Browse…"));
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Export into"), folder_->text());
        if (!dir.isEmpty())
            folder_->setText(dir);
    });
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(folder_);
    folderRow->addWidget(browse);
    form->addRow(tr("Folder"), folderRow);

    auto spin = [](int low, int high, int value) {
        auto* box = new QSpinBox;
        box->setRange(low, high);
        box->setValue(value);
        return box;
    };
    width_ = spin(64, 8192, 1280);
    height_ = spin(64, 8192, 720);
    auto* size = new QHBoxLayout;
    size->addWidget(width_);
    size->addWidget(height_);
    form->addRow(tr("Size (W × H)"), size);
    scale_ = spin(1, 4, 1);
    form->addRow(tr("Scale (high-DPI)"), scale_);
    stages_ = new QLineEdit("all");
    stages_->setToolTip(tr("all, or a list such as 0,2,4-5"));
    form->addRow(tr("Stages"), stages_);
    theme_ = new QComboBox;
    theme_->addItems({tr("light"), tr("dark")});
    theme_->setCurrentIndex(theme == Theme::Dark ? 1 : 0);
    form->addRow(tr("Theme"), theme_);
    framing_ = new QComboBox;
    framing_->addItems({tr("each stage framed on its own"), tr("one framing for all stages")});
    form->addRow(tr("Framing"), framing_);
    transparent_ = new QCheckBox(tr("Transparent background"));
    form->addRow(QString(), transparent_);
    png_ = new QCheckBox("PNG");
    png_->setChecked(true);
    svg_ = new QCheckBox("SVG");
    pdf_ = new QCheckBox("PDF");
    auto* formats = new QHBoxLayout;
    formats->addWidget(png_);
    formats->addWidget(svg_);
    formats->addWidget(pdf_);
    form->addRow(tr("Formats"), formats);
    animate_ = new QCheckBox(tr("Animation (MP4)"));
    fps_ = spin(1, 120, 30);
    auto* animation = new QHBoxLayout;
    animation->addWidget(animate_);
    animation->addWidget(fps_);
    form->addRow(tr("Animation, fps"), animation);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

ExportOptions ExportDialog::options() const
{
    ExportOptions o;
    o.out = folder_->text().toStdString();
    o.width = width_->value();
    o.height = height_->value();
    o.scale = scale_->value();
    o.stages = parseStages(stages_->text().trimmed().toStdString(), stageCount_);
    o.theme = theme_->currentIndex() == 1 ? Theme::Dark : Theme::Light;
    o.fixedFraming = framing_->currentIndex() == 1;
    o.transparent = transparent_->isChecked();
    o.formats.clear();
    if (png_->isChecked())
        o.formats.insert("png");
    if (svg_->isChecked())
        o.formats.insert("svg");
    if (pdf_->isChecked())
        o.formats.insert("pdf");
    o.animate = animate_->isChecked();
    o.fps = fps_->value();
    return o;
}

} // namespace viewpipe::gui
