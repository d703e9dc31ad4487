// The trend view and data logging in the main window, against the --demo simulator (its ladder
// drives a sine of +-1000 with a 10 s period in R1).
#include "mainwindow.h"
#include "tablelogger.h"
#include "testutil.h"
#include "trendview.h"
#include "watchtablemodel.h"

#include <QAction>
#include <QChart>
#include <QDateTimeAxis>
#include <QFile>
#include <QLabel>
#include <QLineSeries>
#include <QSettings>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;

int rowOf(const WatchTableModel *model, const char *address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->item(r).address.toString() == address)
            return r;
    }
    return -1;
}

QList<QPointF> allPoints(const TrendView *view, int item)
{
    QList<QPointF> points;
    for (const QLineSeries *s : view->series(item))
        points += s->points();
    return points;
}

} // namespace

class TestUiTrend : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();

    void demoSineInTrend();
    void addFromWatchTableAndRemove();
    void pauseStopsAddingPoints();
    void windowLimitsTimeAxis();
    void stalePeriodMakesGap();
    void loggingWritesRows();
    void bufferDecimationKeepsPeaks();

private:
    QTemporaryDir m_settingsDir;
    MainWindow *m_window = nullptr;
};

void TestUiTrend::initTestCase()
{
    TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_trend"));
}

void TestUiTrend::init()
{
    m_window = new MainWindow;
    m_window->show();
    QSignalSpy ready(m_window, &MainWindow::demoReady);
    m_window->startDemo();
    QVERIFY(ready.wait(longWait));
    QVERIFY(m_window->openTool(QStringLiteral("trend")) == m_window->trendView());
}

void TestUiTrend::cleanup()
{
    delete m_window;
    m_window = nullptr;
}

void TestUiTrend::demoSineInTrend()
{
    TrendView *trend = m_window->trendView();
    // The demo puts its sine into the trend by itself.
    QCOMPARE(trend->itemCount(), 1);
    QCOMPARE(trend->itemName(0), QStringLiteral("Sine (R1)"));
    // 12 s of samples (polled every 200 ms) cover more than one 10 s period.
    QTRY_VERIFY_WITH_TIMEOUT(trend->spanMs() >= 12000, 30000);
    trend->refresh();
    const QList<QPointF> points = allPoints(trend, 0);
    QVERIFY2(points.size() >= 40, qPrintable(QString::number(points.size())));
    double lo = 0, hi = 0;
    int signChanges = 0;
    for (qsizetype i = 0; i < points.size(); ++i) {
        const double y = points.at(i).y();
        QVERIFY(y >= -1000 && y <= 1000);
        QCOMPARE(y, std::round(y)); // R1 is a signed integer
        lo = std::min(lo, y);
        hi = std::max(hi, y);
        if (i > 0 && ((points.at(i - 1).y() < 0) != (y < 0)))
            ++signChanges;
        if (i > 0)
            QVERIFY(points.at(i).x() >= points.at(i - 1).x());
    }
    // A whole period: close to both peaks and through zero twice.
    QVERIFY2(lo < -800 && hi > 800, qPrintable(QStringLiteral("%1..%2").arg(lo).arg(hi)));
    QVERIFY(signChanges >= 2);
    // x is wall-clock time in ms: the last point is recent, not in the future.
    QVERIFY(points.constLast().x() <= static_cast<double>(QDateTime::currentMSecsSinceEpoch()));
}

void TestUiTrend::addFromWatchTableAndRemove()
{
    TrendView *trend = m_window->trendView();
    WatchTableWidget *table = m_window->currentWatchTable();
    const int blink = rowOf(table->model(), "Y0");
    QVERIFY(blink >= 0);
    table->view()->selectRow(blink);
    QAction *add = nullptr;
    for (QAction *a : table->view()->actions()) {
        if (a->text() == QLatin1String("Add to &Trend"))
            add = a;
    }
    QVERIFY(add);
    add->trigger();
    QCOMPARE(trend->itemCount(), 2);
    QCOMPARE(trend->itemName(1), QStringLiteral("Blink (Y0)"));
    // Twice is refused, not duplicated.
    add->trigger();
    QCOMPARE(trend->itemCount(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(1).countIn(0, std::numeric_limits<qint64>::max()) >= 5,
                             longWait);
    trend->refresh();
    for (const QPointF &p : allPoints(trend, 1))
        QVERIFY(p.y() == 0 || p.y() == 1);
    trend->removeItem(0);
    QCOMPARE(trend->itemCount(), 1);
    QCOMPARE(trend->itemName(0), QStringLiteral("Blink (Y0)"));
    QVERIFY(trend->chart()->series().size() >= 1);
}

void TestUiTrend::pauseStopsAddingPoints()
{
    TrendView *trend = m_window->trendView();
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(0).size() >= 3, longWait);
    trend->setPaused(true);
    QVERIFY(trend->isPaused());
    const qsizetype frozen = trend->buffer(0).size();
    QVERIFY(trend->buffer(0).last().gap); // nothing seen while paused is bridged
    QTest::qWait(1000);                   // five poll cycles go by
    QCOMPARE(trend->buffer(0).size(), frozen);
    trend->setPaused(false);
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(0).size() > frozen + 2, longWait);
}

void TestUiTrend::windowLimitsTimeAxis()
{
    TrendView *trend = m_window->trendView();
    QTRY_VERIFY_WITH_TIMEOUT(trend->spanMs() >= 2000, longWait);
    trend->setWindowMs(10000);
    trend->refresh();
    auto range = [trend] {
        return trend->timeAxis()->min().msecsTo(trend->timeAxis()->max());
    };
    QCOMPARE(range(), qint64(10000));
    QVERIFY(!trend->isZoomed());
    trend->zoomBy(2.0);
    QVERIFY(trend->isZoomed());
    QVERIFY2(range() > 4000 && range() < 6000, qPrintable(QString::number(range())));
    // Zoomed, the axis stays put while new values come.
    const QDateTime zoomedMax = trend->timeAxis()->max();
    QTest::qWait(600);
    QCOMPARE(trend->timeAxis()->max(), zoomedMax);
    trend->resetZoom();
    QVERIFY(!trend->isZoomed());
    QCOMPARE(range(), qint64(10000));
    trend->setWindowMs(60000);
    QCOMPARE(range(), qint64(60000));
}

void TestUiTrend::stalePeriodMakesGap()
{
    TrendView *trend = m_window->trendView();
    WatchTableWidget *table = m_window->currentWatchTable();
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(0).size() >= 3, longWait);
    // A paused table marks its values stale: the trend must not draw them as fresh.
    table->setPaused(true);
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(0).last().gap, longWait);
    const qint64 staleFrom = trend->buffer(0).last().timeMs;
    QTest::qWait(800);
    table->setPaused(false);
    QTRY_VERIFY_WITH_TIMEOUT(!trend->buffer(0).last().gap, longWait);
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(0).last().timeMs > staleFrom + 500, longWait);
    trend->refresh();
    const QList<QLineSeries *> pieces = trend->series(0);
    QVERIFY2(pieces.size() >= 2, qPrintable(QString::number(pieces.size())));
    // No drawn point falls inside the stale stretch.
    const qint64 staleTo = [&] {
        const TrendBuffer &b = trend->buffer(0);
        for (qsizetype i = 0; i < b.size(); ++i) {
            if (!b.at(i).gap && b.at(i).timeMs > staleFrom)
                return b.at(i).timeMs;
        }
        return qint64(-1);
    }();
    QVERIFY(staleTo > staleFrom);
    for (const QPointF &p : allPoints(trend, 0)) {
        QVERIFY2(p.x() < static_cast<double>(staleFrom) || p.x() >= static_cast<double>(staleTo),
                 qPrintable(QString::number(p.x(), 'f', 0)));
    }
}

void TestUiTrend::loggingWritesRows()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("demo.csv"));
    WatchTableWidget *table = m_window->currentWatchTable();
    const WatchTableModel *model = table->model();
    const int sine = rowOf(model, "R1");
    const int blink = rowOf(model, "Y0");
    QVERIFY(sine >= 0 && blink >= 0);
    QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(sine), longWait);

    TableLogger *logger = m_window->tableLogger();
    // What the table showed when each row was written, to compare with the file.
    QStringList expectedSine;
    connect(logger, &TableLogger::rowWritten, this,
            [&] { expectedSine << model->valueText(sine); });
    QVERIFY(m_window->startLogging(path));
    QVERIFY(logger->isLogging());
    QTRY_VERIFY_WITH_TIMEOUT(logger->rowCount() >= 8, longWait);
    auto *status = m_window->findChild<QLabel *>(QStringLiteral("loggingStatus"));
    QVERIFY(status);
    QVERIFY2(status->text().startsWith(QLatin1String("Logging to demo.csv (")),
             qPrintable(status->text()));
    m_window->stopLogging();
    QVERIFY(!logger->isLogging());
    QVERIFY(!status->isVisible());

    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QStringList lines
        = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size() - 1, expectedSine.size());
    const QStringList header = lines.at(0).split(QLatin1Char(','));
    QCOMPARE(header.first(), QStringLiteral("timestamp"));
    QCOMPARE(header.last(), QStringLiteral("status"));
    QCOMPARE(header.at(1 + sine), QStringLiteral("Sine (R1)"));
    QCOMPARE(header.at(1 + blink), QStringLiteral("Blink (Y0)"));
    QDateTime previous;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList cells = lines.at(i).split(QLatin1Char(','));
        QCOMPARE(cells.size(), header.size());
        const QDateTime t = QDateTime::fromString(cells.first(), Qt::ISODateWithMs);
        QVERIFY2(t.isValid(), qPrintable(cells.first()));
        if (previous.isValid())
            QVERIFY(t >= previous);
        previous = t;
        QCOMPARE(cells.at(1 + sine), expectedSine.at(i - 1));
        QVERIFY(cells.at(1 + blink) == QLatin1String("0")
                || cells.at(1 + blink) == QLatin1String("1"));
        QCOMPARE(cells.last(), QStringLiteral("ok"));
    }
    // Stopped means closed: the window's close does not add anything.
    m_window->close();
    QCOMPARE(QFile(path).size(), f.size());
}

void TestUiTrend::bufferDecimationKeepsPeaks()
{
    TrendBuffer buffer(1000);
    // 1000 samples, a single spike in the middle; the ring keeps the newest 1000 only.
    for (int i = 0; i < 1200; ++i)
        buffer.append(i * 10, i == 700 ? 5000.0 : 1.0);
    QCOMPARE(buffer.size(), qsizetype(1000));
    QCOMPARE(buffer.at(0).timeMs, qint64(2000));
    const auto pieces = buffer.segments(2000, 11990, 100);
    QCOMPARE(pieces.size(), 1);
    QVERIFY(pieces.first().size() <= 110);
    bool spike = false;
    for (const QPointF &p : pieces.first())
        spike = spike || p.y() == 5000.0;
    QVERIFY(spike);
    // A gap splits the line; a second gap in a row adds nothing.
    buffer.appendGap(12000);
    buffer.appendGap(12001);
    buffer.append(12010, 2.0);
    buffer.append(12020, 3.0);
    QCOMPARE(buffer.segments(11000, 12020).size(), 2);
    QCOMPARE(buffer.segments(12005, 12020).constLast().size(), 2);
}

QTEST_MAIN(TestUiTrend)
#include "tst_ui_trend.moc"
