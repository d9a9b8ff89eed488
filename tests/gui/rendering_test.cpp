// Rendering through the viewpipe executable: screenshots of the app
// (`viewpipe open --stage K --screenshot`) and exported stages (`viewpipe
// export`) of Foley's house against reviewed images, with a threshold for
// rendering noise. A missing baseline is written to the build tree for review
// and the test fails; copy it to tests/baselines/ only after looking at it.
// Also the export's other outputs: SVG, PDF, LaTeX, JSON, the animation, and
// its atomicity.

#include <QCoreApplication>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <cmath>
#include <csignal>
#include <tuple>
#include <vector>

#include "build_paths.h"
#include "viewpipe/math_text.hpp"
#include "files.h"

namespace {

// Share of pixels whose largest channel difference exceeds `tolerance`.
double differingShare(const QImage& a, const QImage& b, int tolerance)
{
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    qint64 differing = 0;
    for (int row = 0; row < x.height(); ++row) {
        const QRgb* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
        const QRgb* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
        for (int col = 0; col < x.width(); ++col) {
            const int d = std::max({std::abs(qRed(p[col]) - qRed(q[col])), std::abs(qGreen(p[col]) - qGreen(q[col])),
                                    std::abs(qBlue(p[col]) - qBlue(q[col]))});
            differing += d > tolerance;
        }
    }
    return double(differing) / (double(x.width()) * x.height());
}

// Share of pixels that differ from the most common color: a blank or black
// picture has almost none.
double contentShare(const QImage& image)
{
    const QImage x = image.convertToFormat(QImage::Format_RGB32);
    QHash<QRgb, qint64> counts;
    for (int row = 0; row < x.height(); row += 2)
        for (int col = 0; col < x.width(); col += 2)
            ++counts[reinterpret_cast<const QRgb*>(x.constScanLine(row))[col]];
    qint64 most = 0, all = 0;
    for (qint64 c : counts) {
        most = std::max(most, c);
        all += c;
    }
    return 1.0 - double(most) / double(all);
}

struct Run {
    int exitCode;
    QString out, err;
};

Run runViewpipe(const QStringList& arguments, const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment())
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(::viewpipe::build::viewpipeExe, arguments);
    if (!process.waitForFinished(300000))
        return {-1, "", "timed out"};
    return {process.exitCode(), process.readAllStandardOutput(), process.readAllStandardError()};
}

const QString kHouse = QString(::viewpipe::build::dataDir) + "/scenes/house.json";

// Pixels that differ from white (the light theme's background) by more than a little.
constexpr int kDrawn = 40;
std::vector<bool> drawnPixels(const QImage& image)
{
    const QImage x = image.convertToFormat(QImage::Format_RGB32);
    std::vector<bool> drawn(std::size_t(x.width()) * std::size_t(x.height()));
    for (int row = 0; row < x.height(); ++row)
        for (int col = 0; col < x.width(); ++col) {
            const QRgb c = reinterpret_cast<const QRgb*>(x.constScanLine(row))[col];
            drawn[std::size_t(row) * std::size_t(x.width()) + std::size_t(col)] =
                std::min({qRed(c), qGreen(c), qBlue(c)}) < 255 - kDrawn;
        }
    return drawn;
}

// The smaller of the two shares: of one picture's drawn pixels, those within 2 pixels of one drawn in the other.
double drawnAgreement(const QImage& a, const QImage& b)
{
    const int w = a.width(), h = a.height();
    const std::vector<bool> da = drawnPixels(a), db = drawnPixels(b);
    auto within = [&](const std::vector<bool>& of, const std::vector<bool>& in) {
        qint64 count = 0, near = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                if (!of[std::size_t(y) * std::size_t(w) + std::size_t(x)])
                    continue;
                ++count;
                bool found = false;
                for (int dy = -2; dy <= 2 && !found; ++dy)
                    for (int dx = -2; dx <= 2 && !found; ++dx) {
                        const int u = x + dx, v = y + dy;
                        found = u >= 0 && v >= 0 && u < w && v < h && in[std::size_t(v) * std::size_t(w) + std::size_t(u)];
                    }
                near += found;
            }
        return count ? double(near) / double(count) : 0.0;
    };
    return std::min(within(da, db), within(db, da));
}

// pdflatex, which `make test` installs, compiles `file` in `folder`.
bool compilesWithPdflatex(const QString& folder, const QString& file)
{
    const QString pdflatex = QStandardPaths::findExecutable("pdflatex");
    if (pdflatex.isEmpty()) {
        qWarning("pdflatex is missing: scripts/install-deps.sh --test installs TeX Live");
        return false;
    }
    QProcess tex;
    tex.setWorkingDirectory(folder);
    tex.start(pdflatex, {"-interaction=nonstopmode", "-halt-on-error", file});
    if (!tex.waitForFinished(120000) || tex.exitCode() != 0) {
        qWarning("%s", tex.readAllStandardOutput().right(2000).constData());
        return false;
    }
    return true;
}

// Compares an image with tests/baselines/<name>; a missing baseline is written
// to the build tree for review.
void compareWithBaseline(const QString& file, const QString& name)
{
    const QImage image(file);
    QVERIFY2(!image.isNull(), qPrintable("cannot read " + file));
    QVERIFY2(contentShare(image) > 0.02, qPrintable(name + " is nearly blank"));
    const QImage baseline(QString(::viewpipe::build::baselineDir) + "/" + name);
    if (baseline.isNull()) {
        const QString fresh = QString(::viewpipe::build::newBaselineDir) + "/" + name;
        QDir().mkpath(QFileInfo(fresh).path());
        QFile::remove(fresh);
        QFile::copy(file, fresh);
        QFAIL(qPrintable("no baseline: wrote " + fresh + "; look at it, then copy it to tests/baselines/"));
    }
    QCOMPARE(image.size(), baseline.size());
    const double share = differingShare(image, baseline, 48);
    qInfo("%s: %.4f%% of pixels differ", qPrintable(name), 100 * share);
    QVERIFY2(share < 0.005, qPrintable(QString("%1% of pixels differ from %2").arg(100 * share).arg(name)));
}

QString readAll(const QString& file)
{
    QFile f(file);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// The font warnings in the log pdflatex wrote for `file` in `folder`: sizes it substituted, shapes it lacked.
QStringList fontWarnings(const QString& folder, const QString& file)
{
    QStringList warnings;
    const QString log = readAll(folder + "/" + QFileInfo(file).completeBaseName() + ".log");
    for (const QString& line : log.split('\n'))
        if (line.contains("Font Warning") || line.contains("not available"))
            warnings << line;
    return warnings;
}

// A PDF's text as pdftotext (poppler-utils, which `make test` installs) reads it, page by page.
QString pdfText(const QString& pdf)
{
    QProcess text;
    text.start(QStandardPaths::findExecutable("pdftotext"), {"-layout", pdf, "-"});
    return text.waitForFinished(60000) && text.exitCode() == 0 ? QString::fromUtf8(text.readAllStandardOutput()) : QString();
}

// A PDF's page count, as pdfinfo reads it.
int pdfPages(const QString& pdf)
{
    QProcess info;
    info.start(QStandardPaths::findExecutable("pdfinfo"), {pdf});
    if (!info.waitForFinished(60000) || info.exitCode() != 0)
        return -1;
    const QRegularExpressionMatch pages =
        QRegularExpression("^Pages:\\s+(\\d+)", QRegularExpression::MultilineOption).match(info.readAllStandardOutput());
    return pages.hasMatch() ? pages.captured(1).toInt() : -1;
}

QString writeScene(const QTemporaryDir& dir, const QString& name, const QByteArray& json)
{
    const QString file = dir.filePath(name);
    if (!writeFile(file, json))
        qFatal("cannot write %s", qPrintable(file));
    return file;
}

} // namespace

class RenderingTest : public QObject {
    Q_OBJECT

private slots:
    void appScreenshotMatchesBaseline_data()
    {
        QTest::addColumn<int>("stage");
        for (int k = 0; k <= 5; ++k)
            QTest::newRow(qPrintable(QString("stage %1").arg(k))) << k;
    }

    void appScreenshotMatchesBaseline()
    {
        QFETCH(int, stage);
        QTemporaryDir dir;
        const QString shot = dir.filePath("shot.png");
        const Run r = runViewpipe({"open", kHouse, "--stage", QString::number(stage), "--screenshot", shot, "--size",
                                "1280x800"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(shot).size(), QSize(1280, 800));
        QVERIFY2(contentShare(QImage(shot)) > 0.2, "the screenshot is nearly blank");
        compareWithBaseline(shot, QString("house-stage-%1.png").arg(stage));
    }

    // `open` without a scene shows the house from its corner, where every stage moves (the
    // matrices are checked by hand in foley_test): the same window as naming that file.
    void openWithoutASceneShowsTheDefaultScene()
    {
        QTemporaryDir dir;
        const QString given = dir.filePath("given.png"), byDefault = dir.filePath("default.png");
        const QStringList shot = {"--stage", "3", "--size", "800x500"};
        const Run named = runViewpipe(QStringList{"open", QString(::viewpipe::build::dataDir) + "/scenes/house-corner.json",
                                                  "--screenshot", given} + shot);
        QVERIFY2(named.exitCode == 0, qPrintable(named.err));
        const Run unnamed = runViewpipe(QStringList{"open", "--screenshot", byDefault} + shot);
        QVERIFY2(unnamed.exitCode == 0, qPrintable(unnamed.err));
        QVERIFY2(contentShare(QImage(given)) > 0.2, "the screenshot is nearly blank");
        QCOMPARE(QImage(byDefault), QImage(given));
    }

    // `open --layout storyboard` opens on every stage at once (View > Storyboard): not the two
    // views' picture; a layout it does not know is refused by name, exit 2.
    void openShowsTheStoryboard()
    {
        QTemporaryDir dir;
        const QString views = dir.filePath("views.png"), board = dir.filePath("board.png");
        const QStringList shot = {"--size", "1280x800"};
        const Run plain = runViewpipe(QStringList{"open", kHouse, "--screenshot", views} + shot);
        QVERIFY2(plain.exitCode == 0, qPrintable(plain.err));
        const Run r = runViewpipe(QStringList{"open", kHouse, "--layout", "storyboard", "--screenshot", board} + shot);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(contentShare(QImage(board)) > 0.2, "the screenshot is nearly blank");
        QVERIFY(QImage(board) != QImage(views));
        const Run refused = runViewpipe({"open", kHouse, "--layout", "grid", "--screenshot", board});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("--layout"), qPrintable(refused.err));
    }

    // Foley's house's export (PNG, 1280x720, light theme) against reviewed images.
    void exportMatchesBaselines()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("slides");
        const Run r = runViewpipe({"export", kHouse, "--out", out, "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList expected = {"00-world.png", "01-t-vrp.png", "02-r.png",     "03-t-prp.png",
                                      "04-sh-per.png", "05-s-per.png", "matrices.json", "matrices.tex"};
        QCOMPARE(QDir(out).entryList(QDir::Files | QDir::Hidden, QDir::Name), expected);
        for (const QString& name : expected.mid(0, 6)) {
            QCOMPARE(QImage(out + "/" + name).size(), QSize(1280, 720));
            compareWithBaseline(out + "/" + name, "export/house-" + name);
        }
        // matrices.json is the same object as `pipeline --json`.
        const Run json = runViewpipe({"pipeline", kHouse, "--json"});
        QCOMPARE(QJsonDocument::fromJson(readAll(out + "/matrices.json").toUtf8()),
                 QJsonDocument::fromJson(json.out.toUtf8()));
    }

    // Effects are drawn into exported pictures: the same stage of the corridor
    // with and without its effects differs (depth bands, z-fighting faces, the
    // note), and the depth effect adds its resolution plot, whose curve for the
    // scene's buffer is drawn in its red.
    void exportDrawsEffects()
    {
        QTemporaryDir dir;
        const QString corridor = QString(::viewpipe::build::dataDir) + "/scenes/depth-corridor.json";
        QJsonObject plain = QJsonDocument::fromJson(readAll(corridor).toUtf8()).object();
        plain.remove("effects");
        const QString plainScene = dir.filePath("plain.json");
        QVERIFY(writeFile(plainScene, QJsonDocument(plain).toJson()));
        Run r = runViewpipe({"export", corridor, "--out", dir.filePath("effects"), "--stages", "4", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runViewpipe({"export", plainScene, "--out", dir.filePath("plain"), "--stages", "4", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QDir(dir.filePath("effects")).entryList(QDir::Files, QDir::Name),
                 QStringList({"04-p-depth.png", "depth-resolution.png", "matrices.json", "matrices.tex"}));
        QVERIFY(!QFile::exists(dir.filePath("plain/depth-resolution.png")));
        const QImage with(dir.filePath("effects/04-p-depth.png")), without(dir.filePath("plain/04-p-depth.png"));
        QVERIFY(contentShare(with) > 0.02);
        const double changed = differingShare(with, without, 40);
        qInfo("effects change %.2f%% of the exported stage", 100 * changed);
        QVERIFY(changed > 0.002);

        const QImage plot = QImage(dir.filePath("effects/depth-resolution.png")).convertToFormat(QImage::Format_RGB32);
        QCOMPARE(plot.size(), QSize(1280, 720)); // the export's size (found: always 1200 x 700, its text 13 px)
        int red = 0;
        for (int y = 0; y < plot.height(); ++y)
            for (int x = 0; x < plot.width(); ++x) {
                const QRgb c = plot.pixel(x, y);
                red += qRed(c) > 200 && qGreen(c) < 60 && qBlue(c) < 60;
            }
        QVERIFY2(red > 1500, qPrintable(QString::number(red)));
    }

    // True vector figures: lines and faces as paths, labels as text, no
    // picture inside; each, rasterized, draws what the PNG of the same stage
    // draws (drawn pixels agree to 90 % after a 2-pixel dilation).
    void exportWritesVectorFormats()
    {
        QTemporaryDir dir;
        const QString glPerspective = QString(::viewpipe::build::dataDir) + "/scenes/opengl-perspective.json";
        // The title, the figure's accessible name, reads its scripts as spoken.
        for (const auto& [scene, stage, name, title] :
             {std::tuple{kHouse, QString("0"), QString("00-world"), QString("World")},
              std::tuple{kHouse, QString("4"), QString("04-sh-per"), QString("SH sub per")},
              std::tuple{glPerspective, QString("4"), QString("04-p-depth"), QString("P sub depth")}}) {
            const QString out = dir.filePath(name);
            const Run r = runViewpipe({"export", scene, "--out", out, "--stages", stage, "--format", "png,svg,pdf", "--quiet"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QImage png(out + "/" + name + ".png");
            QVERIFY(!png.isNull());

            // SVG: well-formed XML, no embedded picture, shapes as paths, the labels as text.
            QXmlStreamReader xml(readAll(out + "/" + name + ".svg"));
            QStringList texts;
            QString svgTitle;
            int images = 0, paths = 0;
            while (!xml.atEnd()) {
                if (xml.readNext() != QXmlStreamReader::StartElement)
                    continue;
                if (xml.name() == QLatin1String("title"))
                    svgTitle = xml.readElementText();
                images += xml.name() == QLatin1String("image");
                paths += xml.name() == QLatin1String("path") || xml.name() == QLatin1String("polyline");
                if (xml.name() == QLatin1String("text"))
                    texts << xml.readElementText().simplified();
            }
            QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
            QCOMPARE(images, 0);
            QVERIFY2(paths > 50, qPrintable(QString::number(paths)));
            QVERIFY2(texts.contains("CW") && texts.contains("x"), qPrintable(texts.join("|"))); // the axis name x, in italics
            QVERIFY2(svgTitle.contains(title) && !svgTitle.contains('_') && !svgTitle.contains('$'), qPrintable(svgTitle));
            QSvgRenderer svg(out + "/" + name + ".svg");
            QImage fromSvg(png.size(), QImage::Format_RGB32);
            fromSvg.fill(Qt::white);
            QPainter painter(&fromSvg);
            svg.render(&painter);
            painter.end();
            const double svgAgreement = drawnAgreement(png, fromSvg);
            qInfo("%s: SVG and PNG agree on %.1f %% of drawn pixels", qPrintable(name), 100 * svgAgreement);
            QVERIFY2(svgAgreement >= 0.9, qPrintable(name + " svg: " + QString::number(svgAgreement)));

            // PDF: vector (no image), its fonts embedded, small; rasterized by poppler, the PNG's drawing.
            const QByteArray pdf = [&] {
                QFile f(out + "/" + name + ".pdf");
                f.open(QIODevice::ReadOnly);
                return f.readAll();
            }();
            QVERIFY(pdf.startsWith("%PDF-") && pdf.trimmed().endsWith("%%EOF"));
            QVERIFY(!pdf.contains("/Subtype /Image"));
            QVERIFY(pdf.contains("/FontFile2")); // TrueType font programs, embedded
            QVERIFY2(pdf.size() <= 100 * 1024, qPrintable(QString::number(pdf.size())));
            const QString pdftoppm = QStandardPaths::findExecutable("pdftoppm");
            QVERIFY2(!pdftoppm.isEmpty(), "pdftoppm (Debian package poppler-utils, installed by make test) is missing");
            QProcess raster;
            raster.start(pdftoppm, {"-png", "-r", "72", "-singlefile", out + "/" + name + ".pdf", out + "/from-pdf"});
            QVERIFY(raster.waitForFinished(60000) && raster.exitCode() == 0);
            const QImage fromPdf(out + "/from-pdf.png");
            QCOMPARE(fromPdf.size(), png.size());
            const double pdfAgreement = drawnAgreement(png, fromPdf);
            qInfo("%s: PDF and PNG agree on %.1f %% of drawn pixels", qPrintable(name), 100 * pdfAgreement);
            QVERIFY2(pdfAgreement >= 0.9, qPrintable(name + " pdf: " + QString::number(pdfAgreement)));
        }
    }

    // TikZ: one standalone document per stage and figures.tex with them all, each compiling with pdflatex as written,
    // with every font at the size asked for (no substitution warnings).
    void exportWritesTikzThatCompiles()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("tikz");
        const Run r = runViewpipe({"export", kHouse, "--out", out, "--stages", "0,4,5", "--format", "tikz", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString world = readAll(out + "/00-world-tikz.tex");
        QVERIFY(world.contains("\\definecolor{vpDOP}") && world.contains("vp DOP/.style="));
        // Each label's math in the label's own font, as the other pictures set it: italic letters slanted.
        QVERIFY(world.contains("{PRP}") && world.contains("{VRP}") && world.contains("{front ({\\slshape F})}") &&
                world.contains("{{\\slshape x}}"));
        QVERIFY(!world.contains("$")); // no math font: every text in the figure's own
        const QString figures = readAll(out + "/figures.tex");
        QVERIFY(figures.contains("\\input{05-s-per-tikz}"));
        for (const char* file : {"00-world-tikz.tex", "05-s-per-tikz.tex", "figures.tex"}) {
            QVERIFY2(compilesWithPdflatex(out, file), qPrintable(file));
            const QStringList warnings = fontWarnings(out, file);
            QVERIFY2(warnings.isEmpty(), qPrintable(file + QString(": ") + warnings.join('\n')));
        }
        // Each figure numbered once, by the document: "Figure 3: S_per – scale ...", not "Figure 3: 5. S_per".
        const QString captions = pdfText(out + "/figures.pdf");
        QVERIFY2(captions.contains(QRegularExpression("Figure 3: S ?per – scale")), qPrintable(captions));
        const QRegularExpression twice("Figure \\d+: \\d+\\.");
        QVERIFY2(!captions.contains(twice), qPrintable(twice.match(captions).captured()));

        // At S_per each label's leader ends on its own box, as in the PNG and SVG: no leader runs into another label.
        const QString sper = readAll(out + "/05-s-per-tikz.tex");
        QVERIFY(sper.contains("\\draw[vp leader"));
        QVERIFY(!sper.contains("-- (vp label")); // not to a node's border, which TeX sets where the placement did not

        // The README's Beamer example, three figures, as it says to make them.
        const QString slides = dir.filePath("slides");
        QVERIFY(QDir().mkpath(slides));
        QVERIFY(QFile::copy(QString(::viewpipe::build::sourceDir) + "/docs/examples/beamer.tex", slides + "/beamer.tex"));
        const Run made = runViewpipe({"export", kHouse, "--out", slides + "/figures", "--stages", "1,4,5", "--format",
                                      "tikz", "--size", "800x450", "--quiet"});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
        QVERIFY(compilesWithPdflatex(slides, "beamer.tex"));
        const QStringList warnings = fontWarnings(slides, "beamer.tex");
        QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join('\n')));
        QCOMPARE(pdfPages(slides + "/beamer.pdf"), 3);
    }

    // A stage's name is math wherever it is shown: Vulkan's reversed depth stage is NDC with the subscript
    // "Vulkan, reversed" in the figures, their captions, the SVG and matrices.tex, never "vulkan_reversed".
    void stageNamesAreMathInEveryExport()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("vulkan");
        const Run r = runViewpipe({"export", QString(::viewpipe::build::dataDir) + "/scenes/apis/vulkan-reversed-infinite.json",
                                   "--out", out, "--format", "svg,tikz", "--size", "640x360", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList texts = QDir(out).entryList({"*.tex", "*.svg"}, QDir::Files);
        QVERIFY(texts.size() > 10);
        for (const QString& file : texts) {
            const QString text = readAll(out + "/" + file);
            QVERIFY2(!text.contains("vulkan_reversed") && !text.contains("vulkan\\_reversed"), qPrintable(file));
        }
        QVERIFY(readAll(out + "/figures.tex").contains("\\mathit{NDC}_{\\text{Vulkan, reversed}}"));
        QVERIFY(readAll(out + "/matrices.tex").contains("\\mathit{NDC}_{\\text{Vulkan, reversed}}"));
        QVERIFY(compilesWithPdflatex(out, "figures.tex"));
        const QString captions = pdfText(out + "/figures.pdf");
        QVERIFY2(captions.contains("Vulkan, reversed") && !captions.contains("vulkan"), qPrintable(captions));
    }

    // The seeds' glOrtho example (seed 001): entries 1/25, -1/5, 1/20, -3/2, -1/4.
    void latexPrintsExactFractions()
    {
        QTemporaryDir dir;
        const QString scene = writeScene(dir, "ortho.json", R"({"camera": {"look_at": {"eye": [0, 0, 0],
            "center": [0, 0, -1], "up": [0, 1, 0]}, "projection": {"type": "ortho", "left": -20, "right": 30,
            "bottom": 10, "top": 50, "near": 15, "far": -25}}})");
        const Run r = runViewpipe({"export", scene, "--out", dir.filePath("out"), "--stages", "0", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString tex = readAll(dir.filePath("out/matrices.tex"));
        const QString projection = tex.mid(tex.indexOf("P =\n\\begin{bmatrix}"));
        QVERIFY2(projection.contains("\\frac{1}{25} & 0 & 0 & -\\frac{1}{5} \\\\\n"), qPrintable(projection));
        QVERIFY(projection.contains("0 & \\frac{1}{20} & 0 & -\\frac{3}{2} \\\\\n"));
        QVERIFY(projection.contains("0 & 0 & \\frac{1}{20} & -\\frac{1}{4} \\\\\n"));

        // cos 45 degrees in R as Foley writes it: sqrt2/2.
        const QString oblique = writeScene(dir, "oblique.json", R"({"view": {"projection": "parallel",
            "vrp": [0, 0, 0], "vpn": [1, 0, 1], "vup": [0, 1, 0], "prp": [0, 0, 10], "window": [-1, 1, -1, 1],
            "front": 1, "back": -1}})");
        QVERIFY(runViewpipe({"export", oblique, "--out", dir.filePath("oblique"), "--stages", "0", "--quiet"}).exitCode == 0);
        const QString rotation = readAll(dir.filePath("oblique/matrices.tex"));
        QVERIFY2(rotation.contains("\\frac{\\sqrt{2}}{2} & 0 & -\\frac{\\sqrt{2}}{2} & 0"), qPrintable(rotation));

        // Each file compiles on its own, on one page, and within a document that loads the standalone package.
        for (const char* folder : {"out", "oblique"}) {
            QVERIFY2(compilesWithPdflatex(dir.filePath(folder), "matrices.tex"), folder);
            QVERIFY2(fontWarnings(dir.filePath(folder), "matrices.tex").isEmpty(), folder);
            QCOMPARE(pdfPages(dir.filePath(folder) + "/matrices.pdf"), 1);
        }
        QVERIFY(writeFile(dir.filePath("check.tex"),
                          "\\documentclass{article}\n\\usepackage{amsmath}\n\\usepackage{standalone}\n\\begin{document}\n"
                          "Before.\n\\input{out/matrices.tex}\n\\input{oblique/matrices.tex}\nAfter.\n\\end{document}\n"));
        QVERIFY(compilesWithPdflatex(dir.path(), "check.tex"));
        const QString both = pdfText(dir.filePath("check.pdf"));
        QVERIFY2(both.contains("Before.") && both.contains("After.") && both.count("The composite") == 2, qPrintable(both));
    }

    void exportAnimates()
    {
        QTemporaryDir dir;
        const Run r = runViewpipe({"export", kHouse, "--out", dir.filePath("a"), "--stages", "5", "--animate", "--fps",
                                "4", "--size", "320x180", "--quiet"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile video(dir.filePath("a/animation.mp4"));
        QVERIFY(video.open(QIODevice::ReadOnly));
        QVERIFY(video.read(12).mid(4, 4) == "ftyp"); // an MP4 container
        QVERIFY(video.size() > 1000);
        QVERIFY(!QDir(dir.filePath("a")).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot).contains("frames"));
    }

    void exportWorksWithoutADisplay()
    {
        QTemporaryDir dir;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.remove("DISPLAY");
        const Run r = runViewpipe({"export", kHouse, "--out", dir.filePath("headless"), "--stages", "1", "--quiet"},
                               environment);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(contentShare(QImage(dir.filePath("headless/01-t-vrp.png"))) > 0.02);
    }

    // A screenshot of the app needs no display either (none, or one that does not answer); the window alone
    // is refused in words, not aborted.
    void openWorksWithoutADisplayForAScreenshot()
    {
        QTemporaryDir dir;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.remove("DISPLAY");
        const QString file = dir.filePath("stage2.png");
        const Run shot = runViewpipe({"open", kHouse, "--stage", "2", "--screenshot", file, "--size", "1280x720"}, environment);
        QVERIFY2(shot.exitCode == 0, qPrintable(shot.err));
        QCOMPARE(QImage(file).size(), QSize(1280, 720));
        QVERIFY(contentShare(QImage(file)) > 0.05);
        const Run window = runViewpipe({"open", kHouse}, environment);
        QCOMPARE(window.exitCode, 2);
        QVERIFY2(window.err.contains("DISPLAY: is not set"), qPrintable(window.err));
        // A display named that does not answer is as none (Qt aborted on it, exit 134).
        environment.insert("DISPLAY", ":4321");
        QFile::remove(file);
        const Run silent = runViewpipe({"open", kHouse, "--stage", "2", "--screenshot", file, "--size", "1280x720"}, environment);
        QVERIFY2(silent.exitCode == 0, qPrintable(silent.err));
        QCOMPARE(QImage(file).size(), QSize(1280, 720));
        const Run refused = runViewpipe({"open", kHouse}, environment);
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("DISPLAY: is :4321, which does not answer"), qPrintable(refused.err));
    }

    // The CAD sheet: four views, each quadrant drawn, one scale (the front and
    // top views of the house are equally wide).
    void cadSheetHasFourViewsAtOneScale()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("sheet.png");
        const Run r = runViewpipe({"sheet", kHouse, "--out", file, "--size", "800x600"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QImage sheet(file);
        QCOMPARE(sheet.size(), QSize(800, 600));
        auto width = [&sheet](int top) { // columns with ink in the left half, rows top..top+300
            int first = 400, last = -1;
            for (int y = top + 40; y < top + 290; ++y)
                for (int x = 0; x < 400; ++x)
                    if (qGray(sheet.pixel(x, y)) < 240)
                        first = std::min(first, x), last = std::max(last, x);
            return last - first;
        };
        for (const QRect& quadrant : {QRect(0, 0, 400, 300), QRect(400, 0, 400, 300), QRect(0, 300, 400, 300),
                                      QRect(400, 300, 400, 300)})
            QVERIFY(contentShare(sheet.copy(quadrant)) > 0.1);
        QVERIFY(std::abs(width(0) - width(300)) <= 2);
        QVERIFY(width(0) > 100);
    }

    void exportIsAtomic()
    {
        QTemporaryDir dir;
        // Bad options: exit 2, nothing created.
        Run r = runViewpipe({"export", kHouse, "--out", dir.filePath("bad"), "--format", "png,bmp"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains("--format: unknown format \"bmp\""));
        QVERIFY(!QDir(dir.filePath("bad")).exists());

        // An interrupted export leaves the previous files as they were and no partial ones.
        const QString out = dir.filePath("slides");
        QDir().mkpath(out);
        QVERIFY(writeFile(out + "/00-world.png", "previous"));
        QProcess process;
        process.start(::viewpipe::build::viewpipeExe, {"export", kHouse, "--out", out, "--animate", "--quiet"});
        QVERIFY(process.waitForStarted());
        QTest::qWait(2500);
        ::kill(pid_t(process.processId()), SIGINT);
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 130);
        QCOMPARE(QDir(out).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot), QStringList{"00-world.png"});
        QCOMPARE(readAll(out + "/00-world.png"), QString("previous"));
    }

    // A lesson as a problem sheet: foley-nper's nine questions and their solutions on at most eight A4 pages, the
    // solutions after the questions, on a page of their own. Every built-in lesson's paper fits its pages.
    void lessonProblemSheet()
    {
        QTemporaryDir out;
        const QString lessonPath = QString(::viewpipe::build::dataDir) + "/lessons/foley-nper.json";
        const Run run = runViewpipe({"lesson", "export", lessonPath, "--out", out.path(), "--format", "sheet"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QCOMPARE(run.out, out.path() + "/sheet.pdf\n");
        const auto tool = [](const QString& name, const QStringList& arguments) {
            QProcess process;
            process.start(QStandardPaths::findExecutable(name), arguments);
            process.waitForFinished(60000);
            return QString::fromUtf8(process.readAllStandardOutput());
        };
        const QString sheet = out.filePath("sheet.pdf");
        const int pages = QRegularExpression("Pages:\\s+(\\d+)").match(tool("pdfinfo", {sheet})).captured(1).toInt();
        QVERIFY2(pages >= 2 && pages <= 8, qPrintable(QString::number(pages)));
        const QString text = tool("pdftotext", {sheet, "-"});
        const int solutions = text.indexOf("Solutions");
        QVERIFY2(solutions > 0, qPrintable(text));
        const QString problems = text.left(solutions);
        for (int k = 1; k <= 9; ++k)
            QVERIFY2(problems.contains(QString("Question %1.").arg(k)), qPrintable(problems));
        QVERIFY2(!problems.contains("Answer"), qPrintable(problems));
        QCOMPARE(text.mid(solutions).count("Answer:"), 9);
        const int firstPage = problems.count('\f') + 1;
        const QString solutionsPage = tool("pdftotext", {"-f", QString::number(firstPage), "-l", QString::number(firstPage), sheet, "-"});
        QVERIFY2(solutionsPage.trimmed().startsWith("Solutions"), qPrintable(solutionsPage));
        tool("pdftoppm", {"-png", "-r", "50", "-f", QString::number(firstPage), "-l", QString::number(firstPage), "-singlefile", sheet,
                          out.filePath("solutions")});
        QVERIFY(contentShare(QImage(out.filePath("solutions.png"))) > 0.02);

        // Every built-in lesson: each slide on one page (a step's, and its answer's), the handout on at most
        // ten pages, the sheet on at most eight.
        const QFileInfoList lessons = QDir(QString(::viewpipe::build::dataDir) + "/lessons").entryInfoList({"*.json"}, QDir::Files);
        QVERIFY(lessons.size() >= 5);
        for (const QFileInfo& lesson : lessons) {
            const QString folder = out.filePath(lesson.completeBaseName());
            const Run made = runViewpipe({"lesson", "export", lesson.filePath(), "--out", folder, "--format", "pdf,sheet", "--quiet"});
            QVERIFY2(made.exitCode == 0, qPrintable(lesson.fileName() + ": " + made.err));
            QFile file(lesson.filePath());
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QJsonArray steps = QJsonDocument::fromJson(file.readAll()).object()["steps"].toArray();
            int slides = 0;
            for (const QJsonValue& step : steps)
                slides += step.toObject().contains("question") ? 2 : 1;
            const auto pagesOf = [&](const QString& pdf) {
                return QRegularExpression("Pages:\\s+(\\d+)").match(tool("pdfinfo", {folder + "/" + pdf})).captured(1).toInt();
            };
            QCOMPARE(pagesOf("slides.pdf"), slides);
            QVERIFY2(pagesOf("handout.pdf") <= 10, qPrintable(lesson.fileName()));
            QVERIFY2(pagesOf("sheet.pdf") <= 8, qPrintable(lesson.fileName()));
        }
    }

    // A lesson on paper: handout.pdf, each step the room it needs and the
    // answer key after them, and slides.pdf, 16:9, one slide per step and one
    // more for each answer. No answer shows before the key.
    void lessonHandoutAndSlides()
    {
        QTemporaryDir out;
        const QString lessonPath = QString(::viewpipe::build::dataDir) + "/lessons/foley-nper.json";
        // Formats are a list, as export's: the page beside the paper, made in one go.
        const Run run = runViewpipe({"lesson", "export", lessonPath, "--out", out.path(), "--format", "pdf,html"});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(run.out, out.path() + "/handout.pdf\n" + out.path() + "/lesson.html\n" + out.path() + "/slides.pdf\n");
        QCOMPARE(QDir(out.path()).entryList(QDir::Files | QDir::Hidden | QDir::AllDirs | QDir::NoDotAndDotDot),
                 QStringList({"handout.pdf", "lesson.html", "slides.pdf"}));
        auto tool = [](const QString& name, const QStringList& arguments) {
            QProcess process;
            process.start(QStandardPaths::findExecutable(name), arguments);
            process.waitForFinished(60000);
            return QString::fromUtf8(process.readAllStandardOutput());
        };
        auto pages = [&](const QString& pdf) {
            const QString info = tool("pdfinfo", {pdf});
            const QRegularExpressionMatch match = QRegularExpression("Pages:\\s+(\\d+)").match(info);
            return match.hasMatch() ? match.captured(1).toInt() : -1;
        };
        auto pageSize = [&](const QString& pdf) {
            const QRegularExpressionMatch match =
                QRegularExpression("Page size:\\s+([\\d.]+) x ([\\d.]+)").match(tool("pdfinfo", {pdf}));
            return QSizeF(match.captured(1).toDouble(), match.captured(2).toDouble());
        };
        // The lesson: 9 steps, each with a question.
        constexpr int kSteps = 9;
        const QString handout = out.path() + "/handout.pdf", slides = out.path() + "/slides.pdf";
        QCOMPARE(pages(slides), 2 * kSteps);
        const QSizeF slide = pageSize(slides);
        QVERIFY2(std::abs(slide.width() / slide.height() - 16.0 / 9.0) < 1e-3, qPrintable(QString::number(slide.width())));
        const QSizeF a4 = pageSize(handout);
        QVERIFY(std::abs(a4.width() - 595.28) < 1 && std::abs(a4.height() - 841.89) < 1);
        // Each step the room it needs: the nine questions and their key on at most ten pages.
        const int handoutPages = pages(handout);
        QVERIFY2(handoutPages >= 4 && handoutPages <= 10, qPrintable(QString::number(handoutPages)));
        QFile lessonFile(lessonPath);
        QVERIFY(lessonFile.open(QIODevice::ReadOnly));
        const QJsonArray steps = QJsonDocument::fromJson(lessonFile.readAll()).object()["steps"].toArray();
        const QString whole = tool("pdftotext", {handout, "-"});
        const int keyAt = whole.indexOf("Answer key");
        QVERIFY2(keyAt > 0, qPrintable(whole));
        const QString asked = whole.left(keyAt), key = whole.mid(keyAt);
        for (int step = 1; step <= kSteps; ++step) {
            QVERIFY2(asked.contains(QString("Step %1 of 9").arg(step)), qPrintable(asked));
            QVERIFY2(asked.contains(QString("Question %1.").arg(step)), qPrintable(asked));
            // The step's text, which may give the answer away, waits for the key.
            const QString opening = steps[step - 1].toObject()["caption"].toString().left(30);
            QVERIFY2(!asked.simplified().contains(opening.simplified()), qPrintable(opening));
        }
        QVERIFY2(!asked.contains("Answer"), qPrintable(asked));
        // The key begins on a page of its own.
        const QString keyPage = tool("pdftotext", {"-f", QString::number(whole.left(keyAt).count('\f') + 1), "-l",
                                                   QString::number(whole.left(keyAt).count('\f') + 1), handout, "-"});
        QVERIFY2(keyPage.trimmed().startsWith("Answer key"), qPrintable(keyPage));
        // Question 6's entry is an exact fraction (-dop_x/dop_z = -8/84 = -2/21), typeset as one.
        QVERIFY2(key.contains("Answer: −") && key.contains("21"), qPrintable(key));
        // The slide after a question holds its answer; the question's slide does not.
        const QString asking = tool("pdftotext", {"-f", "1", "-l", "1", slides, "-"});
        const QString answered = tool("pdftotext", {"-f", "2", "-l", "2", slides, "-"});
        QVERIFY2(asking.contains("Question 1.") && !asking.contains("Answer"), qPrintable(asking));
        QVERIFY2(answered.contains("Answer:") && answered.contains("Step 1 of 9"), qPrintable(answered));
        // The figures are drawn: a page rasterized is far from blank.
        tool("pdftoppm", {"-png", "-r", "40", "-f", "2", "-l", "2", "-singlefile", slides, out.path() + "/slide"});
        const QImage picture(out.path() + "/slide.png");
        QVERIFY(!picture.isNull());
        QVERIFY2(contentShare(picture) > 0.05, qPrintable(QString::number(contentShare(picture))));

        // A bad format is refused before anything is made.
        const Run bad = runViewpipe({"lesson", "export", lessonPath, "--out", out.path() + "/none", "--format", "docx"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--format: must be html, pdf or sheet"), qPrintable(bad.err));
        QVERIFY(!QDir(out.path() + "/none").exists());

        // Math outside the subset is refused as the lesson is read, naming its field (so a file outside the
        // lesson is never read through \\input); text pdflatex still cannot set is bad input, named by its step.
        const QString house = QString(::viewpipe::build::dataDir) + "/scenes/house.json";
        for (const auto& [caption, reason] : {std::pair<QString, QString>{"$\\\\nosuchmacro$", "steps[1].caption: has math with \\nosuchmacro"},
                                              {"$\\\\input{/etc/hostname}$", "steps[1].caption: has math with \\input"},
                                              {"Char 日 here", "steps[1].caption: has the character 日 (U+65E5)"},
                                              {"🙂", "steps[1].caption: has the character 🙂 (U+1F642)"}}) {
            const QString broken = out.path() + "/broken.json";
            QFile file(broken);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(QString(R"({"title": "t", "steps": [{"scene": "%1", "caption": "fine"},
                                  {"scene": "%1", "caption": "%2"}]})").arg(house, caption).toUtf8());
            file.close();
            const Run refused = runViewpipe({"lesson", "export", broken, "--out", out.path() + "/none", "--format", "pdf", "--quiet"});
            QCOMPARE(refused.exitCode, 2);
            QVERIFY2(refused.err.contains(broken + ": " + reason), qPrintable(refused.err));
            QVERIFY(!QDir(out.path() + "/none").exists());
        }

        // What lesson check accepts, pdflatex sets: every sign and letter beyond ASCII, in prose and in \text{…}.
        QString every = "Char α here, $\\text{β ≠ γ}$, é ü ß Å ÿ:";
        for (const ::viewpipe::TextSymbol& symbol : ::viewpipe::textSymbols())
            every += QString(" ") + QString::fromUtf8(symbol.utf8);
        QJsonObject step{{"scene", house}, {"caption", every}};
        const QString accepted = out.path() + "/accepted.json";
        QFile acceptedFile(accepted);
        QVERIFY(acceptedFile.open(QIODevice::WriteOnly));
        acceptedFile.write(QJsonDocument(QJsonObject{{"title", "Über α"}, {"steps", QJsonArray{step}}}).toJson());
        acceptedFile.close();
        const Run checked = runViewpipe({"lesson", "check", accepted});
        QVERIFY2(checked.exitCode == 0, qPrintable(checked.err));
        const Run set = runViewpipe({"lesson", "export", accepted, "--out", out.path() + "/accepted", "--format", "pdf", "--quiet"});
        QVERIFY2(set.exitCode == 0, qPrintable(set.err));
        const QString text = tool("pdftotext", {out.path() + "/accepted/handout.pdf", "-"});
        // (pdftotext writes accents as combining marks, and Ω as the ohm sign.)
        QVERIFY2(text.contains("Char α here") && text.contains("Φ X Ψ") && text.contains("± × ÷"), qPrintable(text));
    }
};

QTEST_MAIN(RenderingTest)
#include "rendering_test.moc"
