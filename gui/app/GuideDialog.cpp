#include "GuideDialog.h"
#include "MathText.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QRegularExpression>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "viewpipe/math_text.hpp"

// The guide's page is a resource of this static library: linked in only where named.
static void initGuideResource()
{
    Q_INIT_RESOURCE(app);
}

namespace viewpipe::gui {
namespace {

// The guide with each bold stage symbol (<b>SH_per</b>) set as the stage list sets it, as math.
QString guideWithSymbols()
{
    initGuideResource();
    QFile file(":/viewpipe/guide.html");
    file.open(QIODevice::ReadOnly);
    QString html = QString::fromUtf8(file.readAll());
    // A symbol has a subscript (SH_per), a negated point (T(-VRP)), or is one of the one-letter stages.
    static const QRegularExpression symbol(R"(<b>([A-Z][A-Za-z]*(?:_[a-z0-9_]+|\(-[A-Za-z]+\))|R|M)</b>)");
    for (QRegularExpressionMatch m = symbol.match(html); m.hasMatch(); m = symbol.match(html, m.capturedStart() + 1)) {
        const QString math = "<b>" + mathHtml("$" + symbolMath(m.captured(1).toStdString()) + "$") + "</b>";
        html.replace(m.capturedStart(), m.capturedLength(), math);
    }
    return html;
}

} // namespace

GuideDialog::GuideDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName("guideDialog");
    setWindowTitle(tr("ViewPipe Guide"));
    setModal(false);
    auto* layout = new QVBoxLayout(this);
    browser_ = new QTextBrowser;
    browser_->setObjectName("guideText");
    browser_->setHtml(guideWithSymbols());
    layout->addWidget(browser_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->button(QDialogButtonBox::Close)->setToolTip(tr("Close the guide"));
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    layout->addWidget(buttons);
    resize(720, 760);
}

GuideDialog* GuideDialog::showFor(QWidget* parent)
{
    auto* guide = parent->findChild<GuideDialog*>(QString(), Qt::FindDirectChildrenOnly);
    if (!guide)
        guide = new GuideDialog(parent);
    guide->show();
    guide->raise();
    guide->activateWindow();
    return guide;
}

} // namespace viewpipe::gui
