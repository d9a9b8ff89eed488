#include "ExportDialog.h"

#include "AppPaths.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>

namespace viewpipe::gui {

QString ExportDialog::defaultFolder()
{
    for (const auto location : {QStandardPaths::PicturesLocation, QStandardPaths::DocumentsLocation}) {
        const QString folder = QStandardPaths::writableLocation(location);
        if (!folder.isEmpty())
            return folder + "/ViewPipe";
    }
    return QDir::homePath() + "/ViewPipe";
}

ExportDialog::ExportDialog(int stageCount, report::Theme theme, QWidget* parent) : QDialog(parent), stageCount_(stageCount)
{
    setWindowTitle(tr("Export Stages"));
    auto* form = new QFormLayout(this);

    folder_ = new QLineEdit(QSettings().value("exportFolder", defaultFolder()).toString());
    folder_->setObjectName("exportFolder");
    folder_->setToolTip(tr("The folder the pictures are written into (created if missing)"));
    auto* browse = new QPushButton(tr("Browse…"));
    browse->setToolTip(tr("Choose the folder"));
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
    width_->setToolTip(tr("Width of each picture, in pixels"));
    height_ = spin(64, 8192, 720);
    height_->setToolTip(tr("Height of each picture, in pixels"));
    auto* size = new QHBoxLayout;
    size->addWidget(width_);
    size->addWidget(height_);
    form->addRow(tr("Size (W × H)"), size);
    scale_ = spin(1, 4, 1);
    scale_->setToolTip(tr("Pixels per unit of size: 2 doubles the pixels (and the text) for high-DPI slides"));
    form->addRow(tr("Scale (high-DPI)"), scale_);
    stages_ = new QLineEdit("all");
    stages_->setToolTip(tr("The stages to export: all, or a list such as 0,2,4-5 (0 is the world)"));
    form->addRow(tr("Stages"), stages_);
    theme_ = new QComboBox;
    theme_->addItems({tr("light"), tr("dark")});
    theme_->setCurrentIndex(theme == report::Theme::Dark ? 1 : 0);
    theme_->setToolTip(tr("Light for slides and print, dark for the screen"));
    form->addRow(tr("Theme"), theme_);
    framing_ = new QComboBox;
    framing_->addItem(tr("with the stage before where the step keeps sizes"), int(report::FramingMode::Together));
    framing_->addItem(tr("each stage framed on its own"), int(report::FramingMode::PerStage));
    framing_->addItem(tr("one framing for all stages"), int(report::FramingMode::Fixed));
    framing_->setToolTip(tr("With the stage before, a translation or rotation shows where it moved the scene "
                            "from; on its own, each stage as large as it goes; one framing for all keeps sizes "
                            "comparable from stage to stage"));
    form->addRow(tr("Framing"), framing_);
    layout_ = new QComboBox;
    layout_->setObjectName("layout");
    layout_->addItem(tr("a file of each stage"), false);
    layout_->addItem(tr("every stage at once (storyboard)"), true);
    layout_->setToolTip(tr("A picture of each stage per format, or one storyboard per format "
                           "(storyboard.png, .svg, .pdf, storyboard-tikz.tex)"));
    form->addRow(tr("Layout"), layout_);
    transparent_ = new QCheckBox(tr("Transparent background"));
    transparent_->setToolTip(tr("PNG pictures without a background, to lay over a slide"));
    form->addRow(QString(), transparent_);
    textScale_ = spin(50, 400, 100);
    textScale_->setSuffix(" %");
    textScale_->setToolTip(tr("Text size: at 100 %, labels 2.4 % of the picture's width (8 pt in a 12 cm column)"));
    form->addRow(tr("Text size"), textScale_);
    legend_ = new QComboBox;
    for (const report::LegendPlace place : report::legendPlaces())
        legend_->addItem(legendPlaceTitle(place), int(place));
    legend_->setToolTip(tr("Where the legend goes"));
    form->addRow(tr("Legend"), legend_);
    zoom_ = new QDoubleSpinBox;
    zoom_->setRange(0.1, 10);
    zoom_->setSingleStep(0.1);
    zoom_->setValue(1);
    zoom_->setSuffix(" ×");
    zoom_->setToolTip(tr("The subject this many times larger than framed"));
    form->addRow(tr("Zoom"), zoom_);
    // What the pictures may leave out, as export --hide names it.
    auto* hidden = new QGridLayout;
    const std::vector<std::string> names = hideNames();
    for (std::size_t k = 0; k < names.size(); ++k) {
        auto* box = new QCheckBox(hideText(names[k]));
        box->setObjectName(QString::fromStdString("hide-" + names[k]));
        box->setToolTip(tr("Leave %1 out of the pictures").arg(box->text()));
        hidden->addWidget(box, int(k / 4), int(k % 4));
        hide_.emplace_back(names[k], box);
    }
    form->addRow(tr("Leave out"), hidden);
    // Every format export writes, from its table.
    auto* formats = new QGridLayout;
    const std::vector<ExportFormat> table = exportFormats();
    for (std::size_t k = 0; k < table.size(); ++k) {
        auto* box = new QCheckBox(QString::fromStdString(table[k].name).toUpper());
        box->setObjectName(QString::fromStdString("format-" + table[k].name));
        box->setToolTip(QString::fromStdString(table[k].description));
        box->setChecked(table[k].name == "png");
        formats->addWidget(box, int(k / 3), int(k % 3));
        formats_.emplace_back(table[k].name, box);
    }
    form->addRow(tr("Formats"), formats);
    digits_ = spin(1, 17, 4);
    digits_->setToolTip(tr("Significant digits of inexact entries in matrices.tex"));
    form->addRow(tr("Digits"), digits_);
    animate_ = new QCheckBox(tr("Animation (MP4)"));
    animate_->setToolTip(tr("Also a video of the stages moving one into the next"));
    fps_ = spin(1, 120, 30);
    fps_->setToolTip(tr("Frames per second of the video"));
    auto* animation = new QHBoxLayout;
    animation->addWidget(animate_);
    animation->addWidget(fps_);
    form->addRow(tr("Animation, fps"), animation);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    buttons->button(QDialogButtonBox::Ok)->setToolTip(tr("Write the files into the folder"));
    buttons->button(QDialogButtonBox::Cancel)->setToolTip(tr("Close without exporting"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    // Proposed next time: the last folder exported into.
    connect(this, &QDialog::accepted, this, [this] { QSettings().setValue("exportFolder", folder_->text()); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

QString hideText(const std::string& name)
{
    return QString::fromStdString(viewpipe::hideTitle(name));
}

void ExportDialog::startFrom(const std::set<std::string>& hidden, bool storyboard)
{
    for (const auto& [name, box] : hide_)
        box->setChecked(hidden.count(name) > 0);
    layout_->setCurrentIndex(storyboard ? 1 : 0);
}

ExportOptions ExportDialog::options() const
{
    ExportOptions o;
    o.presets = scenesDirectory().toStdString();
    o.out = folder_->text().toStdString();
    o.width = width_->value();
    o.height = height_->value();
    o.scale = scale_->value();
    o.stages = parseStages(stages_->text().trimmed().toStdString(), stageCount_);
    o.theme = theme_->currentIndex() == 1 ? report::Theme::Dark : report::Theme::Light;
    o.framing = report::FramingMode(framing_->currentData().toInt());
    o.storyboard = layout_->currentData().toBool();
    o.transparent = transparent_->isChecked();
    o.textScale = textScale_->value();
    o.legend = report::LegendPlace(legend_->currentData().toInt());
    o.zoom = zoom_->value();
    for (const auto& [name, box] : hide_)
        if (box->isChecked())
            o.hidden.insert(name);
    o.formats.clear();
    for (const auto& [name, box] : formats_)
        if (box->isChecked())
            o.formats.insert(name);
    o.digits = digits_->value();
    o.animate = animate_->isChecked();
    o.fps = fps_->value();
    return o;
}

} // namespace viewpipe::gui
