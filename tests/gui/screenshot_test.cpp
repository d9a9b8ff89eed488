// Screenshot baselines: `viewpipe open --stage K --screenshot` of the default
// scene against reviewed images, with a threshold for rendering noise. A
// missing baseline is written to the build tree for review and the test fails;
// copy it to tests/baselines/ only after looking at it.

#include <QCoreApplication>
#include <QDir>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

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

} // namespace

class ScreenshotTest : public QObject {
    Q_OBJECT

private slots:
    void matchesBaseline_data()
    {
        QTest::addColumn<int>("stage");
        for (int k = 0; k <= 5; ++k)
            QTest::newRow(qPrintable(QString("stage %1").arg(k))) << k;
    }

    void matchesBaseline()
    {
        QFETCH(int, stage);
        QTemporaryDir dir;
        const QString shot = dir.filePath("shot.png");
        QProcess viewpipe;
        viewpipe.start(VIEWPIPE_EXE, {"open", QString(VIEWPIPE_DATA_DIR) + "/scenes/house.json", "--stage",
                                      QString::number(stage), "--screenshot", shot, "--size", "1280x800"});
        QVERIFY(viewpipe.waitForFinished(120000));
        QVERIFY2(viewpipe.exitCode() == 0, viewpipe.readAllStandardError().constData());
        const QImage image(shot);
        QCOMPARE(image.size(), QSize(1280, 800));
        QVERIFY2(contentShare(image) > 0.2, "the screenshot is nearly blank");

        const QString name = QString("house-stage-%1.png").arg(stage);
        const QImage baseline(QString(VIEWPIPE_BASELINE_DIR) + "/" + name);
        if (baseline.isNull()) {
            QDir().mkpath(VIEWPIPE_NEW_BASELINE_DIR);
            const QString fresh = QString(VIEWPIPE_NEW_BASELINE_DIR) + "/" + name;
            QFile::remove(fresh);
            QFile::copy(shot, fresh);
            QFAIL(qPrintable("no baseline: wrote " + fresh + "; look at it, then copy it to tests/baselines/"));
        }
        QCOMPARE(image.size(), baseline.size());
        const double share = differingShare(image, baseline, 48);
        qInfo("%s: %.4f%% of pixels differ", qPrintable(name), 100 * share);
        QVERIFY2(share < 0.005, qPrintable(QString("%1% of pixels differ from %2").arg(100 * share).arg(name)));
    }
};

QTEST_GUILESS_MAIN(ScreenshotTest)
#include "screenshot_test.moc"
