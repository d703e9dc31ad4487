// History in the studio (issue 51), as a person meets it at a laptop's 1366x768: a store pre-filled
// with 26 hours of 1 s values of the demo's sine row (with 40 minutes of bad quality two hours
// ago) is looked back at in the trend, on the in-process demo simulator. The row is marked
// "Record in History" through its context menu and added to the trend; "8 h" shows the recorded
// values joined to the live line, one click on the scroll bar's arrow goes back an hour; the drawn
// points are the stored ones at their times, the bad stretch is a gap. What the studio records
// itself reaches the store (read through a second handle), a range is exported to CSV through the
// file dialog and read back, and "Custom…" shows a chosen range. FATEK_HISTORY_SCREENSHOT names a
// file for the screenshot of a day's trend (docs/images/history-trend.png).
#include "core/history/historystore.h"
#include "core/history/historywriter.h"
#include "testutil.h"
#include "ui/common/csvfilefilter.h"
#include "ui/history/historycenter.h"
#include "ui/history/historyui.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/trend/tablelogger.h"
#include "ui/trend/trendhistory.h"
#include "ui/trend/trendlogging.h"
#include "ui/trend/trendview.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDateTimeEdit>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QLineSeries>
#include <QMenu>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTranslator>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QDateTimeAxis>

#include <cmath>
#include <map>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
constexpr int keyDelayMs = 120;
constexpr int mouseDelayMs = 300;
const QSize laptop(1366, 768);
constexpr qint64 hourMs = 3600 * 1000;
const QString seriesKey = QStringLiteral("Demo PLC/1-R1");

// The pre-filled store: 1 s values from 26 h ago to a few seconds ago, a sine-like curve (a 4 h
// wave, a 23 min one and a fast ripple), bad quality from 120 to 80 minutes ago.
struct Prefill
{
    qint64 fromMs = 0;
    qint64 toMs = 0;
    qint64 gapFromMs = 0;
    qint64 gapToMs = 0;
    std::map<qint64, double> good; // time -> value
    std::vector<HistorySample> samples;
};

double curve(qint64 timeMs)
{
    const double t = double(timeMs) / 1000.0;
    return std::round(600 * std::sin(2 * M_PI * t / (4 * 3600))
                      + 250 * std::sin(2 * M_PI * t / 1380) + 60 * std::sin(2 * M_PI * t / 97));
}

QString prefill(const QString &location, Prefill *out)
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch() / 1000 * 1000;
    out->fromMs = now - 26 * hourMs;
    out->toMs = now - 5000;
    out->gapFromMs = now - 120 * 60 * 1000;
    out->gapToMs = now - 80 * 60 * 1000;
    auto store = HistoryStore::open(location, HistoryStore::Mode::ReadWrite);
    if (!store)
        return QString::fromStdString(store.error().message.args.empty()
                                          ? std::string("cannot open")
                                          : store.error().message.args.front().text);
    HistorySeries series;
    series.source = QStringLiteral("Demo PLC");
    series.item = QStringLiteral("1-R1");
    series.label = QStringLiteral("Sine");
    series.format = QStringLiteral("signed");
    const auto id = (*store)->seriesId(series);
    if (!id)
        return QStringLiteral("no series id");
    std::vector<HistoryRecord> records;
    for (qint64 t = out->fromMs; t <= out->toMs; t += 1000) {
        HistorySample s;
        s.timeMs = t;
        if (t >= out->gapFromMs && t < out->gapToMs) {
            if (t != out->gapFromMs)
                continue; // one stale sample starts the gap, nothing until it ends
            s.quality = HistoryQuality::Stale;
        } else {
            s.value = curve(t);
            s.raw = static_cast<std::uint16_t>(static_cast<qint16>(s.value));
            out->good[t] = s.value;
        }
        out->samples.push_back(s);
        records.push_back({*id, s});
    }
    if (const Status s = (*store)->append(records); !s)
        return QStringLiteral("append failed");
    return {};
}

QString location()
{
    return qEnvironmentVariable("FATEK_HISTORY");
}

// In the save dialog `modal` (a QFileDialog): chooses the file type "CSV, Windows line ends" and
// types `path`. Returns false for another modal, or when that type is not offered (the dialog is
// cancelled then).
bool saveAsWindowsCsv(QWidget *modal, const QString &path)
{
    auto *dialog = qobject_cast<QFileDialog *>(modal);
    auto *edit = dialog ? dialog->findChild<QLineEdit *>(QStringLiteral("fileNameEdit")) : nullptr;
    if (!edit)
        return false;
    if (!dialog->nameFilters().contains(CsvFileFilter::windows())) {
        dialog->reject();
        return false;
    }
    dialog->selectNameFilter(CsvFileFilter::windows());
    edit->setFocus();
    QTest::keyClicks(edit, path);
    QTest::keyClick(edit, Qt::Key_Return);
    return true;
}

void clickCell(QTableView *view, const QModelIndex &index)
{
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(index).center(),
                      mouseDelayMs);
}

// Right-clicks the cell and clicks the entry of its context menu whose object name or text is
// `entry`. Returns whether it was there and enabled; `checked` what its check mark showed.
bool chooseFromContextMenu(QTableView *view, const QModelIndex &index, const QString &entry,
                           bool *checked = nullptr)
{
    clickCell(view, index);
    bool chosen = false;
    // Gone with this function: a menu that never opened leaves no hand behind.
    QTimer hand;
    hand.setSingleShot(true);
    hand.setInterval(mouseDelayMs);
    QObject::connect(&hand, &QTimer::timeout, view, [&] {
        auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        if (!menu)
            return;
        for (QAction *a : menu->actions()) {
            if ((a->objectName() == entry || a->text() == entry) && a->isEnabled()) {
                if (checked)
                    *checked = a->isChecked();
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                chosen = true;
                return;
            }
        }
        menu->close();
    });
    hand.start();
    const QPoint pos = view->visualRect(index).center();
    QContextMenuEvent event(QContextMenuEvent::Mouse, pos, view->viewport()->mapToGlobal(pos));
    QApplication::sendEvent(view->viewport(), &event); // the menu's own loop until chosen
    return chosen;
}

int rowOf(const WatchTableModel *model, const char *address)
{
    for (int r = 0; r < model->rowCount(); ++r) {
        if (model->item(r).address.toString() == address)
            return r;
    }
    return -1;
}

} // namespace

class TestUiHistory : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;
    QTranslator m_english;
    Prefill m_prefill;
    MainWindow *m_window = nullptr;
    qint64 m_markedMs = 0; // when the row was marked: later values are the studio's own

    TrendView *trend() const { return m_window->trendView(); }

    // The history drawn and nothing more asked of the store.
    bool historySettled()
    {
        return QTest::qWaitFor(
            [this] { return trend()->history()->isIdle() && !trend()->historySeries(0).isEmpty(); },
            longWait);
    }

    // Every drawn point of the recorded part is a stored value at its time (but the value the
    // line enters the range with and its join to the live line); none lies in the bad stretch,
    // and no piece bridges it.
    void checkHistoryPoints(int *matched)
    {
        int misses = 0;
        *matched = 0;
        const QList<QLineSeries *> pieces = trend()->historySeries(0);
        for (const QLineSeries *piece : pieces) {
            const QList<QPointF> points = piece->points();
            for (qsizetype i = 0; i < points.size(); ++i) {
                const auto t = static_cast<qint64>(points.at(i).x());
                QVERIFY2(t <= m_prefill.gapFromMs || t >= m_prefill.gapToMs,
                         qPrintable(QDateTime::fromMSecsSinceEpoch(t).toString()));
                if (i > 0) {
                    const auto before = static_cast<qint64>(points.at(i - 1).x());
                    QVERIFY(!(before <= m_prefill.gapFromMs && t >= m_prefill.gapToMs));
                    QVERIFY(t >= before);
                }
                if (t >= m_markedMs)
                    continue; // recorded by the studio itself, checked below
                const auto stored = m_prefill.good.find(t);
                // The point the line enters the range with (the value held from before the
                // range's start) and its join to the live line are not stored samples, even when
                // the range starts on a whole second where one is stored (CI under ASan).
                const bool edge = i == 0 || i + 1 == points.size();
                if (stored == m_prefill.good.end()
                    || (edge && !qFuzzyCompare(points.at(i).y(), stored->second))) {
                    ++misses;
                    continue;
                }
                QCOMPARE(points.at(i).y(), stored->second);
                ++*matched;
            }
        }
        QVERIFY2(misses <= 2 * pieces.size(), qPrintable(QString::number(misses)));
    }

    // The mouse over the chart at a time: the read-out's line of the item there.
    QString readoutAt(qint64 timeMs)
    {
        auto *view = trend()->findChild<QChartView *>(QStringLiteral("trendChart"));
        const QRectF area = trend()->chart()->plotArea();
        const qint64 fromMs = trend()->timeAxis()->min().toMSecsSinceEpoch();
        const qint64 toMs = trend()->timeAxis()->max().toMSecsSinceEpoch();
        const double x
            = area.left() + area.width() * double(timeMs - fromMs) / double(toMs - fromMs);
        const QPoint at
            = view->mapFromScene(trend()->chart()->mapToScene(QPointF(x, area.center().y())));
        QTest::mouseMove(view->viewport(), at);
        const QStringList lines = trend()->readoutText().split(QLatin1Char('\n'));
        QTest::mouseMove(view->viewport(), QPoint(1, 1));
        return lines.size() == 2 ? lines.at(1) : lines.join(QLatin1Char('|'));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_history"));
        QCOMPARE(QGuiApplication::primaryScreen()->size(), laptop);
        QVERIFY(m_english.load(QStringLiteral(":/i18n/fatekstudio_en.qm")));
        QCoreApplication::installTranslator(&m_english);
        const QString error = prefill(location(), &m_prefill);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void cleanupTestCase()
    {
        delete m_window;
        m_window = nullptr;
    }

    void nothingRecordedMakesNoFile();
    void scrollBackIntoRecordedValues();
};

// A studio whose tables record nothing, with the demo's rows in the trend and the window going
// back 8 h, makes no store: the history is opened for the first recorded row, or read when one
// exists.
void TestUiHistory::nothingRecordedMakesNoFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString unused = dir.filePath(QStringLiteral("never.sqlite"));
    const QByteArray before = qgetenv("FATEK_HISTORY");
    qputenv("FATEK_HISTORY", unused.toUtf8());
    auto *window = new MainWindow;
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    QSignalSpy ready(window, &MainWindow::demoReady);
    window->startDemo();
    QVERIFY(ready.wait(longWait));
    QCOMPARE(window->history()->center()->location(), unused);
    auto *trendView = window->findChild<TrendView *>();
    QVERIFY(trendView);
    QVERIFY(trendView->itemCount() > 0);
    trendView->setWindowMs(8 * 3600 * 1000LL);
    QTest::qWait(1500); // polls, trend refreshes and the debounced history request
    QVERIFY(!window->history()->center()->isOpen());
    QVERIFY2(!QFileInfo::exists(unused), qPrintable(unused));
    delete window;
    QVERIFY(!QFileInfo::exists(unused));
    qputenv("FATEK_HISTORY", before);
}

void TestUiHistory::scrollBackIntoRecordedValues()
{
    m_window = new MainWindow;
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window));
    QSignalSpy ready(m_window, &MainWindow::demoReady);
    m_window->startDemo();
    QVERIFY(ready.wait(longWait));
    // The demo put its rows into the trend by itself: the person starts with an empty one.
    while (trend()->itemCount() > 0)
        trend()->removeItem(0);
    WatchTableWidget *table = m_window->currentWatchTable();
    WatchTableModel *model = table->model();
    const int sine = rowOf(model, "R1");
    QVERIFY(sine >= 0);
    HistoryCenter *center = m_window->history()->center();
    QCOMPARE(center->location(), location());

    // Record in History, through the row's context menu: checked afterwards, the name marked.
    const QModelIndex name = table->viewIndex(model->index(sine, WatchTableModel::NameColumn));
    m_markedMs = QDateTime::currentMSecsSinceEpoch();
    bool wasChecked = true;
    QVERIFY(chooseFromContextMenu(table->view(), name, QStringLiteral("recordHistoryAction"),
                                  &wasChecked));
    QVERIFY(!wasChecked);
    QVERIFY(model->item(sine).history.has_value());
    QCOMPARE(*model->item(sine).history, HistorySetting{});
    QVERIFY(!model->index(sine, WatchTableModel::NameColumn)
                 .data(Qt::DecorationRole)
                 .value<QIcon>()
                 .isNull());
    QTRY_VERIFY(center->recorder(QStringLiteral("Demo PLC")));
    QVERIFY(center->isOpen());
    // The menu shows it checked now.
    QVERIFY(
        chooseFromContextMenu(table->view(), name, QStringLiteral("Add to &Trend"), &wasChecked));
    QTRY_COMPARE(trend()->itemCount(), 1);
    QCOMPARE(trend()->itemName(0), QStringLiteral("Sine (R1)"));

    // "8 h": typed into the window box, as a person picks it by its first character.
    QComboBox *window = trend()->windowBox();
    QVERIFY(window->isVisible());
    window->setFocus(Qt::TabFocusReason);
    QTest::keyClicks(window, QStringLiteral("8"), {}, keyDelayMs);
    QCOMPARE(window->currentText(), QStringLiteral("8 h"));
    QCOMPARE(trend()->windowMs(), 8 * hourMs);
    QTRY_VERIFY_WITH_TIMEOUT(trend()->buffer(0).size() >= 3, longWait);
    QVERIFY(historySettled());
    trend()->refresh();
    int matched = 0;
    checkHistoryPoints(&matched);
    QVERIFY2(matched > 500, qPrintable(QString::number(matched)));
    // The recorded line runs into the live one: its last point is the live buffer's first.
    const QList<QLineSeries *> pieces = trend()->historySeries(0);
    const QPointF joint = pieces.constLast()->points().constLast();
    QCOMPARE(static_cast<qint64>(joint.x()), trend()->buffer(0).at(0).timeMs);
    QVERIFY(!trend()->series(0).isEmpty());
    QVERIFY(trend()->series(0).constLast()->points().constLast().x() >= joint.x());
    QVERIFY(!trend()->isZoomed());

    // Back an hour: one click on the scroll bar's left arrow (an eighth of the 8 h shown).
    QScrollBar *bar = trend()->scrollBar();
    QVERIFY(bar->isVisible());
    const qint64 followedTo = trend()->timeAxis()->max().toMSecsSinceEpoch();
    QTest::mouseClick(bar, Qt::LeftButton, {}, QPoint(bar->height() / 2, bar->height() / 2));
    QVERIFY(trend()->isZoomed()); // it no longer follows the present
    const qint64 fromMs = trend()->timeAxis()->min().toMSecsSinceEpoch();
    const qint64 toMs = trend()->timeAxis()->max().toMSecsSinceEpoch();
    QCOMPARE(toMs - fromMs, 8 * hourMs);
    QVERIFY2(std::abs(followedTo - hourMs - toMs) < 3000,
             qPrintable(QString::number(followedTo - hourMs - toMs)));
    QVERIFY(historySettled());
    trend()->refresh();
    checkHistoryPoints(&matched);
    QVERIFY2(matched > 500, qPrintable(QString::number(matched)));
    // The bad stretch, 120 to 80 minutes ago, is in view: a gap with lines on either side.
    bool before = false, after = false;
    for (const QLineSeries *piece : trend()->historySeries(0)) {
        for (const QPointF &p : piece->points()) {
            before = before
                     || (p.x() < double(m_prefill.gapFromMs)
                         && p.x() > double(m_prefill.gapFromMs - 5 * 60 * 1000));
            after = after
                    || (p.x() >= double(m_prefill.gapToMs)
                        && p.x() < double(m_prefill.gapToMs + 5 * 60 * 1000));
        }
    }
    QVERIFY(before && after);
    QVERIFY(trend()->historySeries(0).size() >= 2);
    // The cursor read-out there: "no value" in the gap, a recorded value beside it.
    QCOMPARE(readoutAt((m_prefill.gapFromMs + m_prefill.gapToMs) / 2),
             QStringLiteral("Sine (R1): no value"));
    const QString recorded = readoutAt(m_prefill.gapToMs + 10 * 60 * 1000);
    static const QRegularExpression valueLine(QStringLiteral("^Sine \\(R1\\): (-?\\d+)$"));
    const QRegularExpressionMatch value = valueLine.match(recorded);
    QVERIFY2(value.hasMatch(), qPrintable(recorded));
    QVERIFY(std::abs(value.captured(1).toDouble()) <= 1000);

    // What the studio recorded itself reaches the store: read through a second handle once the
    // writer wrote what was pending.
    bool flushed = false;
    center->writer()->flush([&flushed] { flushed = true; });
    QTRY_VERIFY(flushed);
    {
        auto reader = HistoryStore::open(location(), HistoryStore::Mode::ReadOnly);
        QVERIFY(reader);
        auto all = (*reader)->series();
        QVERIFY(all);
        qint64 id = 0;
        for (const HistorySeries &s : *all) {
            if (s.key() == seriesKey)
                id = s.id;
        }
        QVERIFY(id != 0);
        auto recent = (*reader)->samples(id, m_markedMs, QDateTime::currentMSecsSinceEpoch() + 1);
        QVERIFY(recent);
        int fresh = 0;
        for (const HistorySample &s : *recent) {
            if (s.timeMs >= m_markedMs && s.quality == HistoryQuality::Good) {
                QVERIFY(s.value >= -1000 && s.value <= 1000);
                ++fresh;
            }
        }
        QVERIFY2(fresh >= 1, qPrintable(QString::number(fresh)));
    }

    // Export Range…: the file dialog takes the name; the file holds the stored samples.
    const QString csv = QFileInfo(location()).absolutePath() + QStringLiteral("/range.csv");
    QSignalSpy exported(trend()->history(), &TrendHistory::exportFinished);
    auto *exportButton = trend()->findChild<QToolButton *>(QStringLiteral("trendExport"));
    QVERIFY(exportButton && exportButton->isVisible());
    bool typed = false;
    UiTestUtil::answerModal(
        [&] { QTest::mouseClick(exportButton, Qt::LeftButton, {}, QPoint(), mouseDelayMs); },
        // The second file type: the same CSV with Windows line ends.
        [&](QWidget *modal) { typed = typed || saveAsWindowsCsv(modal, csv); });
    QVERIFY(typed);
    QVERIFY(exported.wait(longWait) || !exported.isEmpty());
    QCOMPARE(exported.constFirst().at(2).toString(), QString());
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray data = file.readAll();
    // UTF-8 with the byte order mark and CRLF: as Excel on Windows opens it right.
    QVERIFY2(data.startsWith("\xEF\xBB\xBFtime,series,value,raw,quality\r\n"),
             data.left(60).constData());
    QCOMPARE(data.count("\r\n"), data.count('\n'));
    data.remove(0, 3);
    data.replace("\r\n", "\n");
    const QStringList lines = QString::fromUtf8(data).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.constFirst(), QStringLiteral("time,series,value,raw,quality"));
    std::vector<HistorySample> expected;
    for (const HistorySample &s : m_prefill.samples) {
        if (s.timeMs >= fromMs && s.timeMs < toMs)
            expected.push_back(s);
    }
    QCOMPARE(lines.size() - 1, qsizetype(expected.size()));
    QCOMPARE(exported.constFirst().at(1).toInt(), int(expected.size()));
    const QRegularExpression withOffset(QStringLiteral("(Z|[+-]\\d\\d:\\d\\d)$"));
    bool sawStale = false;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QStringList fields = lines.at(i).split(QLatin1Char(','));
        QCOMPARE(fields.size(), 5);
        const HistorySample &s = expected[static_cast<std::size_t>(i - 1)];
        QVERIFY2(withOffset.match(fields.at(0)).hasMatch(), qPrintable(fields.at(0)));
        QCOMPARE(QDateTime::fromString(fields.at(0), Qt::ISODateWithMs).toMSecsSinceEpoch(),
                 s.timeMs);
        QCOMPARE(fields.at(1), seriesKey);
        QCOMPARE(fields.at(4), History::qualityName(s.quality));
        if (s.quality == HistoryQuality::Good) {
            QCOMPARE(fields.at(2).toDouble(), s.value);
            QCOMPARE(fields.at(3), QStringLiteral("0x%1").arg(s.raw, 16, 16, QLatin1Char('0')));
        } else {
            QVERIFY(fields.at(2).isEmpty());
            sawStale = true;
        }
    }
    QVERIFY(sawStale);

    // Start Data Logging…: its file dialog offers the same second type; chosen, the new log has
    // the byte order mark and CRLF from its header on.
    QAction *startLogging = nullptr;
    for (QAction *action : m_window->findChildren<QAction *>()) {
        if (action->text() == TrendLogging::tr("Start &Data Logging…"))
            startLogging = action;
    }
    QVERIFY(startLogging);
    const QString log = QFileInfo(location()).absolutePath() + QStringLiteral("/log-crlf.csv");
    bool logTyped = false;
    UiTestUtil::answerModal(
        [&] { startLogging->trigger(); },
        [&](QWidget *modal) { logTyped = logTyped || saveAsWindowsCsv(modal, log); });
    QVERIFY(logTyped);
    QVERIFY(m_window->tableLogger()->isLogging());
    m_window->stopLogging();
    QFile logFile(log);
    QVERIFY(logFile.open(QIODevice::ReadOnly));
    const QByteArray logData = logFile.readAll();
    QVERIFY2(logData.startsWith("\xEF\xBB\xBFtimestamp,") && logData.contains(",status\r\n")
                 && logData.count('\n') == logData.count("\r\n"),
             logData.constData());

    // Custom…: the last choice of the box; the dialog's range is shown.
    window->setFocus(Qt::TabFocusReason);
    QTest::keyClick(window, Qt::Key_End, {}, keyDelayMs);
    QPointer<QDialog> custom;
    QTRY_VERIFY((custom = trend()->findChild<QDialog *>(QStringLiteral("trendCustomRange")))
                && custom->isVisible());
    const QDateTime customFrom = QDateTime::fromMSecsSinceEpoch(m_prefill.fromMs + hourMs);
    custom->findChild<QDateTimeEdit *>(QStringLiteral("customFrom"))->setDateTime(customFrom);
    custom->findChild<QDateTimeEdit *>(QStringLiteral("customTo"))
        ->setDateTime(customFrom.addSecs(2 * 3600));
    QTest::mouseClick(custom->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok),
                      Qt::LeftButton, {}, QPoint(), mouseDelayMs);
    QTRY_VERIFY(!custom || !custom->isVisible());
    QCOMPARE(trend()->timeAxis()->min().toMSecsSinceEpoch(), customFrom.toMSecsSinceEpoch());
    QCOMPARE(trend()->timeAxis()->max().toMSecsSinceEpoch(),
             customFrom.addSecs(2 * 3600).toMSecsSinceEpoch());
    QVERIFY(historySettled());
    trend()->refresh();
    checkHistoryPoints(&matched);
    QVERIFY2(matched > 500, qPrintable(QString::number(matched)));

    // Reset Zoom follows the present again, in the window chosen before.
    auto *reset = trend()->findChild<QToolButton *>(QStringLiteral("trendResetZoom"));
    QTest::mouseClick(reset, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
    QVERIFY(!trend()->isZoomed());
    QCOMPARE(window->currentText(), QStringLiteral("8 h"));

    // History Settings…: the heartbeat typed, OK; an edit of the table, undone and redone.
    QVERIFY(chooseFromContextMenu(table->view(), name, QStringLiteral("historySettingsAction")));
    QPointer<QDialog> settings;
    QTRY_VERIFY((settings = table->findChild<QDialog *>(QStringLiteral("historySettingsDialog")))
                && settings->isVisible());
    auto *heartbeat = settings->findChild<QSpinBox *>(QStringLiteral("historyHeartbeat"));
    QVERIFY(heartbeat);
    heartbeat->setFocus(Qt::TabFocusReason);
    heartbeat->selectAll();
    QTest::keyClicks(heartbeat, QStringLiteral("60"), {}, keyDelayMs);
    QTest::mouseClick(settings->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok),
                      Qt::LeftButton, {}, QPoint(), mouseDelayMs);
    QTRY_COMPARE(model->item(sine).history.value_or(HistorySetting{}).heartbeatS, 60);
    // The window active again, as a window manager makes it when a dialog closes.
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window));
    clickCell(table->view(), name);
    QTest::keyClick(table->view(), Qt::Key_Z, Qt::ControlModifier, keyDelayMs);
    QTRY_COMPARE(model->item(sine).history.value_or(HistorySetting{}).heartbeatS, 600);
    QTest::keyClick(table->view(), Qt::Key_Z, Qt::ControlModifier, keyDelayMs);
    QTRY_VERIFY(!model->item(sine).history);
    QTest::keyClick(table->view(), Qt::Key_Y, Qt::ControlModifier, keyDelayMs);
    QTRY_VERIFY(model->item(sine).history.has_value());

    // The screenshot for docs/history.md: a day's trend.
    const QString screenshot = qEnvironmentVariable("FATEK_HISTORY_SCREENSHOT");
    if (!screenshot.isEmpty()) {
        window->setFocus(Qt::TabFocusReason);
        QTest::keyClicks(window, QStringLiteral("2"), {}, keyDelayMs);
        QCOMPARE(window->currentText(), QStringLiteral("24 h"));
        // The trend gets most of the window's height, as one looking back at a day gives it.
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("trendDock"));
        QVERIFY(dock);
        m_window->resizeDocks({dock}, {m_window->height() * 3 / 5}, Qt::Vertical);
        QVERIFY(historySettled());
        QTest::qWait(500);
        QVERIFY(historySettled());
        trend()->refresh();
        QVERIFY(m_window->grab().save(screenshot));
    }
}

// A screen of a laptop's size, and the history in a temporary folder, before the application.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QTemporaryDir dir;
    if (!dir.isValid())
        return 1;
    qputenv("FATEK_HISTORY", dir.filePath(QStringLiteral("history.sqlite")).toUtf8());
    qputenv("FATEK_ALARM_JOURNAL", dir.filePath(QStringLiteral("alarms.sqlite")).toUtf8());
    QApplication app(argc, argv);
    TestUiHistory test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_history.moc"
