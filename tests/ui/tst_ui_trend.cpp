// The trend view and data logging in the main window, against the --demo simulator (its ladder
// drives a sine of +-1000 with a 10 s period in R1).
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"
#include "ui/connection/connectionmanager.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/trend/tablelogger.h"
#include "ui/trend/trendtimeticks.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablemodel.h"

#include <QAction>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QDateTimeAxis>
#include <QFile>
#include <QLabel>
#include <QLineSeries>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QValueAxis>

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

QAction *addToTrendAction(WatchTableWidget *table)
{
    for (QAction *a : table->view()->actions()) {
        if (a->text() == QLatin1String("Add to &Trend"))
            return a;
    }
    return nullptr;
}

void selectRows(WatchTableWidget *table, const QList<int> &rows)
{
    table->view()->clearSelection();
    for (int r : rows)
        table->view()->selectionModel()->select(table->viewIndex(table->model()->index(r, 0)),
                                                QItemSelectionModel::Select
                                                    | QItemSelectionModel::Rows);
}

// True when the tick distance of `ticks` is 1, 2 or 5 times a power of ten and every tick is a
// whole multiple of it.
bool niceTicks(const QList<double> &ticks, QString *why)
{
    if (ticks.size() < 2) {
        *why = QStringLiteral("%1 tick(s)").arg(ticks.size());
        return false;
    }
    const double step = ticks.at(1) - ticks.at(0);
    const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    const double mantissa = step / power;
    if (std::abs(mantissa - 1) > 1e-6 && std::abs(mantissa - 2) > 1e-6
        && std::abs(mantissa - 2.5) > 1e-6 && std::abs(mantissa - 5) > 1e-6) {
        *why = QStringLiteral("step %1").arg(step);
        return false;
    }
    for (double t : ticks) {
        if (std::abs(t / step - std::round(t / step)) > 1e-6) {
            *why = QStringLiteral("tick %1 with step %2").arg(t).arg(step);
            return false;
        }
    }
    return true;
}

// The lowest and highest value drawn for an item inside the time axis (a line also holds the
// sample just outside each end, so that it reaches the edge).
QPair<double, double> rangeOf(const TrendView *view, int item)
{
    const double from = static_cast<double>(view->timeAxis()->min().toMSecsSinceEpoch());
    const double to = static_cast<double>(view->timeAxis()->max().toMSecsSinceEpoch());
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    for (const QPointF &p : allPoints(view, item)) {
        if (p.x() < from || p.x() > to)
            continue;
        lo = std::min(lo, p.y());
        hi = std::max(hi, p.y());
    }
    return {lo, hi};
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
    void seriesWithDifferentRangesGetTheirOwnAxes();
    void cursorReadoutShowsValuesUnderTheMouse();
    void addingSeveralItemsNamesThemAll();
    void loggingWritesRows();
    void loggingTwoFormatsAndAnOutage();
    void bufferDecimationKeepsPeaks();
    void doubleWordsPlotAsTheTableShowsThem();
    void timeTicksAreRound();
    void zoomedTimeLabelsAreRound();
    void valueStepsKeepThreeLabels();

private:
    QTemporaryDir m_settingsDir;
    QTranslator m_english;
    MainWindow *m_window = nullptr;
};

void TestUiTrend::initTestCase()
{
    TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_trend"));
    // English as the studio runs it: its file carries the plural forms ("5 items").
    QVERIFY(m_english.load(QStringLiteral(":/i18n/fatekstudio_en.qm")));
    QCoreApplication::installTranslator(&m_english);
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
    // The demo puts its sine and its ramp into the trend by itself.
    QCOMPARE(trend->itemCount(), 2);
    QCOMPARE(trend->itemName(0), QStringLiteral("Sine (R1)"));
    QCOMPARE(trend->itemName(1), QStringLiteral("Ramp (DR10)"));
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
    QCOMPARE(trend->itemCount(), 3);
    QCOMPARE(trend->itemName(2), QStringLiteral("Blink (Y0)"));
    // Twice is refused, not duplicated.
    add->trigger();
    QCOMPARE(trend->itemCount(), 3);
    QTRY_VERIFY_WITH_TIMEOUT(trend->buffer(2).countIn(0, std::numeric_limits<qint64>::max()) >= 5,
                             longWait);
    trend->refresh();
    for (const QPointF &p : allPoints(trend, 2))
        QVERIFY(p.y() == 0 || p.y() == 1);
    trend->removeItem(0);
    QCOMPARE(trend->itemCount(), 2);
    QCOMPARE(trend->itemName(1), QStringLiteral("Blink (Y0)"));
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
    // No drawn point falls strictly inside the stale stretch, and no line crosses it. A point at
    // staleFrom itself is the last value read before the pause: the gap takes that value's time
    // when the stale mark is not later (both in whole ms), so they can be the same instant.
    const auto from = static_cast<double>(staleFrom);
    const auto to = static_cast<double>(staleTo);
    for (const QLineSeries *piece : trend->series(0)) {
        bool before = false;
        bool after = false;
        for (const QPointF &p : piece->points()) {
            QVERIFY2(p.x() <= from || p.x() >= to,
                     qPrintable(QStringLiteral("%1 in %2..%3")
                                    .arg(QString::number(p.x(), 'f', 0))
                                    .arg(staleFrom)
                                    .arg(staleTo)));
            before = before || p.x() <= from;
            after = after || p.x() >= to;
        }
        QVERIFY2(!(before && after), "a line is drawn across the stale stretch");
    }
}

void TestUiTrend::seriesWithDifferentRangesGetTheirOwnAxes()
{
    TrendView *trend = m_window->trendView();
    WatchTableWidget *table = m_window->currentWatchTable();
    const int blink = rowOf(table->model(), "Y0");
    QVERIFY(blink >= 0);
    // The demo trends the sine (+-1000) and the ramp (0..99999, about 1000 in 10 s, far from 0);
    // the technician adds a bit.
    QCOMPARE(trend->itemName(1), QStringLiteral("Ramp (DR10)"));
    selectRows(table, {blink});
    addToTrendAction(table)->trigger();
    QCOMPARE(trend->itemCount(), 3);
    QTRY_VERIFY_WITH_TIMEOUT(trend->spanMs() >= 3000
                                 && trend->buffer(2).countIn(0, std::numeric_limits<qint64>::max())
                                        >= 5,
                             longWait);
    trend->setPaused(true);
    trend->refresh();
    QVERIFY(trend->hasSeparateAxes());
    QValueAxis *sineAxis = trend->valueAxis(0);
    QValueAxis *rampAxis = trend->valueAxis(1);
    QValueAxis *bitAxis = trend->valueAxis(2);
    QVERIFY(sineAxis && rampAxis && bitAxis);
    QVERIFY(sineAxis != rampAxis && sineAxis != bitAxis && rampAxis != bitAxis);
    // Each analog axis spans its own line, and not much more: the sine is not squashed flat.
    for (int i : {0, 1}) {
        const auto [lo, hi] = rangeOf(trend, i);
        QValueAxis *axis = trend->valueAxis(i);
        const QString what = QStringLiteral("%1: data %2..%3, axis %4..%5")
                                 .arg(trend->itemName(i))
                                 .arg(lo)
                                 .arg(hi)
                                 .arg(axis->min())
                                 .arg(axis->max());
        QVERIFY2(axis->min() <= lo && axis->max() >= hi, qPrintable(what));
        QVERIFY2(axis->max() - axis->min() <= std::max(2.0, 1.2 * (hi - lo)), qPrintable(what));
        QString why;
        QVERIFY2(niceTicks(TrendView::tickValues(axis), &why), qPrintable(what + ": " + why));
    }
    const auto [sineLo, sineHi] = rangeOf(trend, 0);
    QVERIFY2(sineHi - sineLo > 100, qPrintable(QStringLiteral("%1..%2").arg(sineLo).arg(sineHi)));
    // The bit has its own 0/1 axis, ticks at 0 and 1.
    QCOMPARE(TrendView::tickValues(bitAxis), (QList<double>{0.0, 1.0}));
    for (const QPointF &p : allPoints(trend, 2))
        QVERIFY(p.y() >= bitAxis->min() && p.y() <= bitAxis->max());

    // Shared: the analog items on one axis spanning both, the bit still on its own.
    trend->setSeparateAxes(false);
    trend->refresh();
    QCOMPARE(trend->valueAxis(0), trend->valueAxis(1));
    QVERIFY(trend->valueAxis(2) != trend->valueAxis(0));
    QCOMPARE(trend->valueAxes().size(), 2);
    const auto [rampLo, rampHi] = rangeOf(trend, 1);
    QVERIFY(trend->valueAxis(0)->min() <= std::min(sineLo, rampLo));
    QVERIFY(trend->valueAxis(0)->max() >= std::max(sineHi, rampHi));
    QString why;
    QVERIFY2(niceTicks(TrendView::tickValues(trend->valueAxis(0)), &why), qPrintable(why));
    // Zooming (rubber band) keeps the ticks round in the new range.
    trend->setSeparateAxes(true);
    trend->refresh();
    QVERIFY(trend->chart()->series().size() >= 3);
    trend->chart()->zoomIn(trend->chart()->plotArea().adjusted(30, 17, -50, -23));
    for (QValueAxis *axis : trend->valueAxes()) {
        if (axis == trend->valueAxis(2))
            continue;
        QVERIFY2(niceTicks(TrendView::tickValues(axis), &why),
                 qPrintable(axis->titleText() + ": " + why));
    }
}

void TestUiTrend::cursorReadoutShowsValuesUnderTheMouse()
{
    TrendView *trend = m_window->trendView();
    QTRY_VERIFY_WITH_TIMEOUT(trend->spanMs() >= 3000, longWait);
    trend->setPaused(true); // the picture (and the time under the mouse) stays
    trend->refresh();
    auto *view = trend->findChild<QChartView *>(QStringLiteral("trendChart"));
    QVERIFY(view);
    QTRY_VERIFY(view->isVisible() && trend->chart()->plotArea().width() > 50);
    QCOMPARE(trend->readoutText(), QString());
    const QRectF area = trend->chart()->plotArea();
    // Near the right end, where the sine has been sampled.
    const QPointF inChart(area.left() + area.width() * 0.9, area.center().y());
    const QPoint at = view->mapFromScene(trend->chart()->mapToScene(inChart));
    QTest::mouseMove(view->viewport(), at);
    const QString text = trend->readoutText();
    QVERIFY2(!text.isEmpty(), "no read-out under the mouse");
    const QStringList lines = text.split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 3); // the time, Sine (R1), Ramp (DR10)
    // The time under the mouse ...
    const QTime shown = QTime::fromString(lines.at(0), QStringLiteral("HH:mm:ss.zzz"));
    QVERIFY2(shown.isValid(), qPrintable(lines.at(0)));
    const qint64 fromMs = trend->timeAxis()->min().toMSecsSinceEpoch();
    const qint64 toMs = trend->timeAxis()->max().toMSecsSinceEpoch();
    const qint64 expectedMs = fromMs + (toMs - fromMs) * 9 / 10;
    const QTime expected = QDateTime::fromMSecsSinceEpoch(expectedMs).time();
    QVERIFY2(std::abs(expected.msecsTo(shown)) <= (toMs - fromMs) / 100,
             qPrintable(lines.at(0) + QStringLiteral(" vs ") + expected.toString()));
    // ... and the sine's value there: the last sample at or before that time.
    static const QRegularExpression valueLine(QStringLiteral("^Sine \\(R1\\): (-?\\d+)$"));
    const QRegularExpressionMatch m = valueLine.match(lines.at(1));
    QVERIFY2(m.hasMatch(), qPrintable(lines.at(1)));
    const TrendBuffer &b = trend->buffer(0);
    const QDateTime shownAt(QDateTime::fromMSecsSinceEpoch(expectedMs).date(), shown);
    double before = std::numeric_limits<double>::quiet_NaN();
    for (qsizetype i = 0; i < b.size() && b.at(i).timeMs <= shownAt.toMSecsSinceEpoch(); ++i)
        before = b.at(i).value;
    QCOMPARE(m.captured(1).toDouble(), before);
    QVERIFY2(lines.at(2).startsWith(QLatin1String("Ramp (DR10): ")), qPrintable(lines.at(2)));
    // Off the plot, the read-out goes.
    QTest::mouseMove(view->viewport(), QPoint(1, 1));
    QCOMPARE(trend->readoutText(), QString());
}

void TestUiTrend::addingSeveralItemsNamesThemAll()
{
    TrendView *trend = m_window->trendView();
    WatchTableWidget *table = m_window->currentWatchTable();
    const int counter = rowOf(table->model(), "R0");
    const int blink = rowOf(table->model(), "Y0");
    const int sine = rowOf(table->model(), "R1");
    QSignalSpy status(trend, &TrendView::statusMessage);
    QCOMPARE(trend->itemCount(), 2); // the demo's sine and ramp
    selectRows(table, {counter, blink});
    addToTrendAction(table)->trigger();
    QCOMPARE(trend->itemCount(), 4);
    QCOMPARE(status.size(), 1);
    QCOMPARE(m_window->statusBar()->currentMessage(),
             QStringLiteral("Scan counter (R0), Blink (Y0) added to the trend."));
    // Five walking bits: counted; the sine already there is said so.
    QList<int> rows{sine};
    for (int i = 0; i < 5; ++i)
        rows << rowOf(table->model(), QStringLiteral("X%1").arg(i).toLatin1().constData());
    selectRows(table, rows);
    addToTrendAction(table)->trigger();
    QCOMPARE(trend->itemCount(), 9);
    QCOMPARE(status.size(), 2);
    QCOMPARE(m_window->statusBar()->currentMessage(),
             QStringLiteral("5 items added to the trend. Sine (R1) is already in the trend."));
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
    QByteArray data = f.readAll();
    QVERIFY(data.startsWith("\xEF\xBB\xBF")); // UTF-8 for Excel on Windows
    data.remove(0, 3);
    const QStringList lines = QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
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

void TestUiTrend::loggingTwoFormatsAndAnOutage()
{
    // A PLC of its own, so the test can pull its plug.
    SimulatedPlc plc;
    SimServer server(&plc);
    QString error;
    QVERIFY2(server.listenTcp(0, &error), qPrintable(error));
    plc.setValue(*Address::parse("R0"), 0xFFFE);
    plc.setValue(*Address::parse("R1"), 7);
    SavedConnection saved;
    saved.name = QStringLiteral("Test PLC");
    saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
    saved.settings.timeoutMs = 300;
    saved.settings.retries = 0;
    saved.station = 1;
    MainWindow window;
    window.show();
    Connection *c = window.openConnection(saved, false);
    QTRY_COMPARE_WITH_TIMEOUT(c->linkState(), LinkState::Connected, longWait);
    WatchTableWidget *table = window.currentWatchTable();
    QCOMPARE(table->connection(), c);
    WatchTableModel *model = table->model();
    auto spec = [](const char *address, DisplayFormat format) {
        WatchItemSpec s;
        s.address = *Address::parse(address);
        s.format = format;
        return s;
    };
    // R0 as a number and as hex, beside R1.
    model->addItems({spec("R0", DisplayFormat::Signed), spec("R0", DisplayFormat::Hex),
                     spec("R1", DisplayFormat::Unsigned)});
    QTRY_VERIFY_WITH_TIMEOUT(model->hasValue(0) && model->hasValue(1) && model->hasValue(2),
                             longWait);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("outage.csv"));
    QVERIFY(window.startLogging(path));
    TableLogger *logger = window.tableLogger();
    QTRY_VERIFY_WITH_TIMEOUT(logger->rowCount() >= 3, longWait);
    // The link goes down while logging.
    server.close();
    QTRY_COMPARE_WITH_TIMEOUT(model->quality(0) == ValueQuality::Good, false, longWait);
    const qint64 before = logger->rowCount();
    QTRY_VERIFY_WITH_TIMEOUT(logger->rowCount() > before, longWait);
    window.stopLogging();

    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QByteArray data = f.readAll();
    QVERIFY(data.startsWith("\xEF\xBB\xBF")); // UTF-8 for Excel on Windows
    data.remove(0, 3);
    const QStringList lines = QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.at(0), QStringLiteral("timestamp,R0 [signed],R0 [hex],R1,status"));
    QCOMPARE(lines.at(1).section(QLatin1Char(','), 1), QStringLiteral("-2,0xFFFE,7,ok"));
    int outageRows = 0;
    static const QRegularExpression oneReason(
        QStringLiteral("^,,,\"?(stale|error|missing) all items \\((.+)\\)\"?$"));
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QString afterTime = lines.at(i).section(QLatin1Char(','), 1);
        if (afterTime.endsWith(QLatin1String(",ok")))
            continue;
        ++outageRows;
        // Item cells empty, the reason once.
        const QRegularExpressionMatch m = oneReason.match(afterTime);
        QVERIFY2(m.hasMatch(), qPrintable(lines.at(i)));
        QCOMPARE(afterTime.count(m.captured(2)), 1);
    }
    QVERIFY2(outageRows >= 1, qPrintable(lines.join(QLatin1Char('\n'))));
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

void TestUiTrend::doubleWordsPlotAsTheTableShowsThem()
{
    // DR10 = 1220 (low word 1220, high word 0): the trend plots 1220, not the swapped 0x04C40000.
    WatchItemSpec ramp;
    ramp.address = *Address::parse("DR10");
    ramp.format = DisplayFormat::Unsigned;
    QCOMPARE(trendValue(ramp, 1220), std::optional<double>(1220.0));
    ramp.format = DisplayFormat::Signed;
    QCOMPARE(trendValue(ramp, 0xFFFFFFFE), std::optional<double>(-2.0));
    // Shown with swapped words in the table: swapped in the trend too.
    ramp.format = DisplayFormat::Unsigned;
    ramp.swapWords = true;
    QCOMPARE(trendValue(ramp, 0x00010002), std::optional<double>(double(0x00020001)));
}

// Issue 54: the time labels fall on round moments of local time, evenly spaced, at every span
// and label count (a zoom gave :38 :40 :43 :45 :47).
// CI found a laptop's trend with two labels on the sine's axis: the step was rounded up from the
// range alone, and where the ticks fell depended on the data. Every range, anywhere on the
// number line, gets at least three ticks and not many more than the plot has room for.
void TestUiTrend::valueStepsKeepThreeLabels()
{
    QValueAxis axis;
    for (int target = 1; target <= 5; ++target) {
        for (double span : {0.013, 0.9, 1.0, 7.3, 13.0, 21.7, 110.0, 1234.5, 2200.0, 99999.0}) {
            for (int shift = -40; shift <= 40; ++shift) {
                const double min = span * shift / 13.7;
                const double max = min + span;
                const double step = TrendView::niceStep(min, max, target);
                axis.setRange(min, max);
                axis.setTickType(QValueAxis::TicksDynamic);
                axis.setTickAnchor(0.0);
                axis.setTickInterval(step);
                const QList<double> ticks = TrendView::tickValues(&axis);
                const QString what = QStringLiteral("%1..%2 for %3 ticks: step %4, %5 ticks")
                                         .arg(min)
                                         .arg(max)
                                         .arg(target)
                                         .arg(step)
                                         .arg(ticks.size());
                QVERIFY2(ticks.size() >= std::min(target, 3), qPrintable(what));
                QVERIFY2(ticks.size() <= target + 2, qPrintable(what));
                QString why;
                QVERIFY2(ticks.size() < 2 || niceTicks(ticks, &why), qPrintable(what + ": " + why));
            }
        }
    }
}

void TestUiTrend::timeTicksAreRound()
{
    const QList<qint64> roundSteps
        = {1000,   2000,   5000,    10000,   15000,   30000,    60000,    120000,   300000,
           600000, 900000, 1800000, 3600000, 7200000, 10800000, 21600000, 43200000, 86400000};
    const qint64 start = QDateTime(QDate(2026, 12, 2), QTime(14, 37, 23, 417)).toMSecsSinceEpoch();
    const qint64 offset = qint64(QDateTime::fromMSecsSinceEpoch(start).offsetFromUtc()) * 1000;
    for (qint64 span : {3300LL, 10000LL, 10517LL, 47000LL, 60000LL, 137000LL, 600000LL, 2345678LL,
                        3600000LL, 8 * 3600000LL, 86400000LL}) {
        for (int maxTicks = 2; maxTicks <= 7; ++maxTicks) {
            const QList<qint64> ticks = TrendTimeTicks::ticks(start, start + span, maxTicks);
            const qint64 step = TrendTimeTicks::stepMs(start, start + span, maxTicks);
            const QString where = QStringLiteral("span %1 ms, %2 labels: step %3, ticks %4")
                                      .arg(span)
                                      .arg(maxTicks)
                                      .arg(step)
                                      .arg(ticks.size());
            QVERIFY2(roundSteps.contains(step), qPrintable(where));
            QVERIFY2(!ticks.isEmpty(), qPrintable(where));
            // No more labels than fit, unless the next round step would leave none.
            const qsizetype next = roundSteps.indexOf(step) + 1;
            if (ticks.size() > maxTicks)
                QVERIFY2(
                    next < roundSteps.size()
                        && TrendTimeTicks::ticksOfStep(start, start + span, roundSteps.at(next))
                               .isEmpty(),
                    qPrintable(where));
            // No smaller round step would have done.
            const qsizetype smaller = roundSteps.indexOf(step) - 1;
            if (smaller >= 0 && ticks.size() <= maxTicks)
                QVERIFY2(
                    TrendTimeTicks::ticksOfStep(start, start + span, roundSteps.at(smaller)).size()
                        > maxTicks,
                    qPrintable(where));
            for (qsizetype i = 0; i < ticks.size(); ++i) {
                QVERIFY2(ticks.at(i) >= start && ticks.at(i) <= start + span, qPrintable(where));
                QVERIFY2((ticks.at(i) + offset) % step == 0, qPrintable(where));
                if (i > 0)
                    QVERIFY2(ticks.at(i) - ticks.at(i - 1) == step, qPrintable(where));
            }
        }
    }
    // The zoom (:38 :40 :43 :45 :47): 14:37:37.4 .. 14:37:47.9 with five labels.
    const qint64 from = start + 14000; // 14:37:37.417
    const QList<qint64> zoomed = TrendTimeTicks::ticks(from, from + 10500, 5);
    QStringList labels;
    for (qint64 t : zoomed)
        labels << QDateTime::fromMSecsSinceEpoch(t).toString(QStringLiteral("HH:mm:ss"));
    QCOMPARE(labels, QStringList({QStringLiteral("14:37:38"), QStringLiteral("14:37:40"),
                                  QStringLiteral("14:37:42"), QStringLiteral("14:37:44"),
                                  QStringLiteral("14:37:46")}));
}

// In the chart: after a zoom the labels under the plot are round moments, evenly spaced.
void TestUiTrend::zoomedTimeLabelsAreRound()
{
    TrendView *trend = m_window->trendView();
    QTRY_VERIFY_WITH_TIMEOUT(trend->spanMs() >= 2000, longWait);
    trend->setWindowMs(60000);
    trend->zoomBy(1.7);
    trend->refresh();
    QCategoryAxis *labels = nullptr;
    for (QAbstractAxis *axis : trend->chart()->axes(Qt::Horizontal)) {
        if (axis->isVisible())
            labels = qobject_cast<QCategoryAxis *>(axis);
    }
    QVERIFY2(labels, "the time labels are no category axis on round moments");
    const qint64 from = trend->timeAxis()->min().toMSecsSinceEpoch();
    const qint64 to = trend->timeAxis()->max().toMSecsSinceEpoch();
    QCOMPARE(qint64(labels->min()), from);
    QCOMPARE(qint64(labels->max()), to);
    const QStringList names = labels->categoriesLabels();
    QVERIFY2(names.size() >= 2, qPrintable(names.join(QLatin1Char(' '))));
    QList<qint64> at;
    for (const QString &name : names)
        at << qint64(labels->endValue(name));
    const qint64 step = at.at(1) - at.at(0);
    for (qsizetype i = 0; i < at.size(); ++i) {
        QVERIFY2(at.at(i) % 1000 == 0 && (at.at(i) / 1000) % (step / 1000) == 0,
                 qPrintable(names.join(QLatin1Char(' '))));
        if (i > 0)
            QCOMPARE(at.at(i) - at.at(i - 1), step);
        QCOMPARE(names.at(i),
                 QDateTime::fromMSecsSinceEpoch(at.at(i)).toString(QStringLiteral("HH:mm:ss")));
    }
}

QTEST_MAIN(TestUiTrend)
#include "tst_ui_trend.moc"
