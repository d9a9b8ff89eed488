#include "CodePanel.h"
#include "PanelCombo.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QResizeEvent>
#include <QSettings>
#include <QToolTip>
#include <QVBoxLayout>

#include <cmath>
#include <utility>

#include "NumberText.h"

namespace viewpipe::gui {
namespace {

constexpr int kMargin = 6;
constexpr int kContinuationIndent = 4; // characters before a wrapped line's continuation

// The code's lines as the view shows them, wrapped to a width after a space
// or an opening parenthesis (never inside a number), continuations indented. The code's
// characters are bytes of UTF-8; the view counts in them too.
struct TextLayout {
    struct Line {
        std::size_t start, end; // byte offsets
        int indent;             // pixels
    };
    QFontMetrics metrics;
    std::vector<Line> lines;

    // width <= 0: no wrapping.
    TextLayout(const QFont& font, const std::string& text, int width) : metrics(font)
    {
        const int indent = kContinuationIndent * metrics.horizontalAdvance(' ');
        std::size_t start = 0;
        while (true) {
            const std::size_t newline = text.find('\n', start);
            const std::size_t end = newline == std::string::npos ? text.size() : newline;
            wrap(text, start, end, width, indent);
            if (newline == std::string::npos)
                break;
            start = newline + 1;
        }
    }
    int advance(const std::string& text, std::size_t from, std::size_t to) const
    {
        return metrics.horizontalAdvance(QString::fromUtf8(text.data() + from, int(to - from)));
    }
    std::size_t lineOf(std::size_t offset) const
    {
        std::size_t k = 0;
        while (k + 1 < lines.size() && lines[k + 1].start <= offset)
            ++k;
        return k;
    }

private:
    void wrap(const std::string& text, std::size_t start, std::size_t end, int width, int indent)
    {
        int lead = 0;
        while (width > 0 && advance(text, start, end) > width - lead) {
            // The last break that fits, else the first there is.
            std::size_t fits = std::string::npos, first = std::string::npos;
            for (std::size_t i = start + 1; i < end; ++i)
                if ((text[i - 1] == ' ' || text[i - 1] == '(') && text[i] != ' ' && text[i] != ')') {
                    if (first == std::string::npos)
                        first = i;
                    if (advance(text, start, i) <= width - lead)
                        fits = i;
                }
            const std::size_t at = fits != std::string::npos ? fits : first;
            if (at == std::string::npos)
                break;
            lines.push_back({start, at, lead});
            start = at;
            lead = indent;
        }
        lines.push_back({start, end, lead});
    }
};

} // namespace

CodeView::CodeView(QWidget* parent) : QWidget(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAccessibleName(tr("The camera as code"));
}

void CodeView::setCode(const report::CameraCode& code)
{
    code_ = code;
    if (selected_ && *selected_ >= code_.numbers.size())
        selected_.reset();
    hovered_.reset();
    updateGeometry();
    update();
}

QSize CodeView::sizeHint() const
{
    return {40 * fontMetrics().horizontalAdvance('0') + 2 * kMargin, heightForWidth(width())};
}

QSize CodeView::minimumSizeHint() const
{
    return {10 * fontMetrics().horizontalAdvance('0'), heightForWidth(width())};
}

bool CodeView::hasHeightForWidth() const
{
    return true;
}

int CodeView::heightForWidth(int width) const
{
    const TextLayout layout(font(), code_.text, width - 2 * kMargin);
    return int(layout.lines.size()) * layout.metrics.lineSpacing() + 2 * kMargin;
}

void CodeView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    updateGeometry(); // the lines wrap anew: the height follows
}

QRect CodeView::numberRect(std::size_t index) const
{
    if (index >= code_.numbers.size())
        return {};
    const report::CodeNumber& n = code_.numbers[index];
    const TextLayout layout(font(), code_.text, width() - 2 * kMargin);
    const std::size_t line = layout.lineOf(n.offset);
    const TextLayout::Line& l = layout.lines[line];
    const int x = l.indent + layout.advance(code_.text, l.start, n.offset);
    const int width = layout.advance(code_.text, n.offset, n.offset + n.length);
    return {kMargin + x, kMargin + int(line) * layout.metrics.lineSpacing(), width, layout.metrics.lineSpacing()};
}

std::optional<std::size_t> CodeView::numberAt(const QPoint& point) const
{
    for (std::size_t k = 0; k < code_.numbers.size(); ++k)
        if (numberRect(k).adjusted(-2, 0, 2, 0).contains(point))
            return k;
    return std::nullopt;
}

void CodeView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    const TextLayout layout(font(), code_.text, width() - 2 * kMargin);
    const QPalette& p = palette();
    painter.fillRect(rect(), p.color(QPalette::Base));
    for (std::size_t k = 0; k < code_.numbers.size(); ++k) {
        const QRect r = numberRect(k);
        const bool active = (selected_ && *selected_ == k && hasFocus()) || (hovered_ && *hovered_ == k) ||
                            (drag_ && drag_->index == k);
        QColor back = p.color(QPalette::Highlight);
        back.setAlpha(active ? 110 : 40);
        painter.fillRect(r.adjusted(-1, 0, 1, 0), back);
        painter.setPen(QPen(p.color(QPalette::Highlight), 1, Qt::DotLine));
        painter.drawLine(r.bottomLeft(), r.bottomRight());
    }
    painter.setPen(p.color(QPalette::Text));
    for (std::size_t k = 0; k < layout.lines.size(); ++k) {
        const TextLayout::Line& line = layout.lines[k];
        painter.drawText(kMargin + line.indent, kMargin + int(k) * layout.metrics.lineSpacing() + layout.metrics.ascent(),
                         QString::fromUtf8(code_.text.data() + line.start, int(line.end - line.start)));
    }
}

bool CodeView::event(QEvent* event)
{
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        if (const std::optional<std::size_t> k = numberAt(help->pos()))
            QToolTip::showText(help->globalPos(),
                               QString::fromStdString(code_.numbers[*k].tooltip) + "\n" +
                                   tr("Drag left or right to change it, or double-click to type a value."),
                               this, numberRect(*k));
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

void CodeView::step(std::size_t index, int steps, int gesture)
{
    const double from = drag_ ? drag_->startValue : code_.numbers[index].value;
    if (!std::isfinite(from))
        return; // an infinite far plane is typed, not dragged
    emit numberChanged(index, report::steppedValue(from, steps), gesture);
}

void CodeView::select(std::size_t index)
{
    if (index < code_.numbers.size())
        selected_ = index;
    update();
}

void CodeView::mousePressEvent(QMouseEvent* event)
{
    const std::optional<std::size_t> k = numberAt(event->pos());
    if (event->button() != Qt::LeftButton || !k)
        return QWidget::mousePressEvent(event);
    select(*k);
    drag_ = Drag{*k, event->pos().x(), code_.numbers[*k].value, ++gestures_};
}

void CodeView::mouseMoveEvent(QMouseEvent* event)
{
    if (drag_) {
        step(drag_->index, event->pos().x() - drag_->startX, drag_->gesture);
        return;
    }
    const std::optional<std::size_t> k = numberAt(event->pos());
    if (k != hovered_) {
        hovered_ = k;
        setCursor(k ? Qt::SizeHorCursor : Qt::ArrowCursor);
        update();
    }
}

void CodeView::mouseReleaseEvent(QMouseEvent* event)
{
    if (drag_ && event->button() == Qt::LeftButton) {
        drag_.reset();
        update();
    }
}

void CodeView::mouseDoubleClickEvent(QMouseEvent* event)
{
    drag_.reset();
    if (const std::optional<std::size_t> k = numberAt(event->pos()))
        openEditor(*k);
}

void CodeView::openEditor(std::size_t index)
{
    select(index);
    closeEditor(false);
    editor_ = new QLineEdit(this);
    editor_->setObjectName("codeNumberEditor");
    editor_->setText(numberText(code_.numbers[index].value));
    editor_->selectAll();
    const QRect r = numberRect(index);
    editor_->setGeometry(r.x() - 2, r.y(), std::max(r.width() + 40, fontMetrics().averageCharWidth() * 14),
                         r.height() + 4);
    editor_->installEventFilter(this);
    editor_->show();
    editor_->setFocus();
    // Enter or leaving the box types the value in, as the Parameters panel's fields do; Escape does not.
    connect(editor_, &QLineEdit::editingFinished, this, [this] { closeEditor(true); });
}

void CodeView::closeEditor(bool commit)
{
    if (!editor_)
        return;
    QLineEdit* editor = std::exchange(editor_, nullptr);
    editor->disconnect(this);
    editor->removeEventFilter(this);
    editor->hide();
    editor->deleteLater();
    setFocus();
    if (commit && selected_)
        emit numberTyped(*selected_, editor->text());
}

bool CodeView::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == editor_ && event->type() == QEvent::KeyPress) {
        // Handled here: passed on, Return would reach the view and open the editor again.
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter) {
            closeEditor(key != Qt::Key_Escape);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void CodeView::keyPressEvent(QKeyEvent* event)
{
    if (event->matches(QKeySequence::Paste)) {
        emit pasted(QApplication::clipboard()->text());
        return;
    }
    if (!selected_)
        return QWidget::keyPressEvent(event);
    switch (event->key()) {
    case Qt::Key_Up: step(*selected_, 1, -1); break;
    case Qt::Key_Down: step(*selected_, -1, -1); break;
    case Qt::Key_Return:
    case Qt::Key_Enter: openEditor(*selected_); break;
    default: QWidget::keyPressEvent(event);
    }
}

// Tab moves from number to number, then on to the next widget.
bool CodeView::focusNextPrevChild(bool next)
{
    const std::size_t count = code_.numbers.size();
    if (count > 0 && hasFocus()) {
        if (!selected_) {
            select(next ? 0 : count - 1);
            return true;
        }
        if ((next && *selected_ + 1 < count) || (!next && *selected_ > 0)) {
            select(next ? *selected_ + 1 : *selected_ - 1);
            return true;
        }
        selected_.reset();
    }
    return QWidget::focusNextPrevChild(next);
}

CodePanel::CodePanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    dialects_ = new QComboBox;
    dialects_->setObjectName("codeDialect");
    for (const report::Dialect d : report::kDialects)
        dialects_->addItem(QString::fromStdString(report::dialectTitle(d)));
    dialects_->setToolTip(tr("The library whose calls write the camera"));
    fitComboToItsRow(dialects_);
    auto* copy = new QPushButton(tr("&Copy"));
    copy->setObjectName("codeCopy");
    copy->setToolTip(tr("Put the code on the clipboard"));
    top->addWidget(new QLabel(tr("Dialect")));
    top->addWidget(dialects_, 1);
    top->addWidget(copy);
    layout->addLayout(top);

    note_ = new QLabel;
    note_->setWordWrap(true);
    layout->addWidget(note_);
    view_ = new CodeView;
    view_->setObjectName("codeView");
    layout->addWidget(view_); // its lines wrap to the panel's width, its height follows
    error_ = new QLabel;
    error_->setObjectName("codeError");
    error_->setWordWrap(true);
    error_->setStyleSheet("color: #d55e00");
    error_->hide();
    layout->addWidget(error_);

    auto* pasteNote = new QLabel(tr("Paste a call to set the camera, e.g. gluPerspective(45, 1.333, 0.1, 100):"));
    pasteNote->setWordWrap(true);
    layout->addWidget(pasteNote);
    paste_ = new QPlainTextEdit;
    paste_->setObjectName("codePaste");
    paste_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    paste_->setMaximumHeight(paste_->fontMetrics().lineSpacing() * 5);
    layout->addWidget(paste_);
    auto* apply = new QPushButton(tr("&Apply"));
    apply->setObjectName("codeApply");
    layout->addWidget(apply, 0, Qt::AlignRight);
    layout->addStretch(1);

    const int saved = QSettings().value("codeDialect", int(report::Dialect::Glm)).toInt();
    dialects_->setCurrentIndex(std::clamp(saved, 0, dialects_->count() - 1));
    connect(dialects_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
        QSettings().setValue("codeDialect", index);
        regenerate();
    });
    connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(QString::fromStdString(code_.text)); });
    connect(apply, &QPushButton::clicked, this, [this] { applyCode(paste_->toPlainText()); });
    connect(view_, &CodeView::pasted, this, &CodePanel::applyCode);
    connect(view_, &CodeView::numberChanged, this, &CodePanel::setNumber);
    connect(view_, &CodeView::numberTyped, this, [this](std::size_t index, const QString& text) {
        if (index >= code_.numbers.size())
            return;
        double value = 0;
        const QString reason = readNumber(text, code_.numbers[index].field == gl::kProjectionField + "far", value);
        if (!reason.isEmpty())
            return showError(QString::fromStdString(code_.numbers[index].field) + ": " + reason);
        setNumber(index, value, -1);
    });
}

void CodePanel::setDialect(report::Dialect dialect)
{
    dialects_->setCurrentIndex(int(dialect)); // in the order of report::kDialects
}

void CodePanel::setCamera(const CameraSpec<double>& camera)
{
    const auto* gl = std::get_if<gl::Camera<double>>(&camera);
    camera_ = gl ? std::optional<gl::Camera<double>>(*gl) : std::nullopt;
    clearError(); // a new camera: what was refused before no longer applies
    regenerate();
}

void CodePanel::regenerate()
{
    const bool code = camera_.has_value();
    view_->setVisible(code);
    paste_->setEnabled(code);
    note_->setText(code ? tr("Drag a marked number left or right, or double-click it to type. Each change is one "
                             "undoable edit.")
                        : tr("This scene's camera is a Foley view (VRP, VPN, VUP, PRP): no graphics API writes it "
                             "as code. Open a scene with a look-at camera, such as the presets under Graphics "
                             "APIs."));
    code_ = code ? report::cameraCode(*camera_, report::kDialects[dialects_->currentIndex()]) : report::CameraCode{};
    view_->setCode(code_);

}

void CodePanel::setNumber(std::size_t index, double value, int gesture)
{
    if (!camera_ || index >= code_.numbers.size())
        return;
    const std::string& field = code_.numbers[index].field;
    if (sameBits(value, code_.numbers[index].value))
        return; // the value it has: no edit
    try {
        const gl::Camera<double> candidate = report::withField(*camera_, field, value);
        clearError();
        emit cameraEdited(candidate, QString::fromStdString(field), gesture);
    } catch (const InputError& e) {
        showError(QString::fromUtf8(e.what()));
    }
}

void CodePanel::applyCode(const QString& text)
{
    if (!camera_)
        return;
    try {
        const gl::Camera<double> candidate = report::applyCode(*camera_, text.toStdString());
        clearError();
        emit cameraEdited(candidate, tr("pasted code"), -1);
    } catch (const InputError& e) {
        showError(QString::fromUtf8(e.what()));
    }
}

void CodePanel::showError(const QString& reason)
{
    error_->setText(reason);
    error_->show();
}

void CodePanel::clearError()
{
    error_->clear();
    error_->hide();
}

} // namespace viewpipe::gui
