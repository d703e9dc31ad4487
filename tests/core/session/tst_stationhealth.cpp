// Field faults on a multi-drop link (issues 31, 54, 55): a station that never answers must not slow
// the stations that do, one-shot requests get the line whatever the poll list does, an element the
// PLC refuses is reported once and polled rarely, and a line slower than the interval is not
// "late" every cycle. A real simulator over loopback TCP (or a socat pty pair) answers as station
// 1; station 7 has nobody behind it.
#include "core/session/session.h"
#include "core/session/stationscanner.h"
#include "core/session/trafficlog.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "testutil.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <memory>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

// Every value batch of a session, with the time it arrived.
class ValueLog : public QObject
{
public:
    explicit ValueLog(Session *session)
    {
        m_clock.start();
        connect(session, &Session::values, this, [this](const QList<WatchValue> &values) {
            for (const WatchValue &value : values)
                entries.append({m_clock.elapsed(), QDateTime::currentDateTimeUtc(), value});
        });
    }
    struct Entry
    {
        qint64 atMs = 0;
        QDateTime at; // wall clock, comparable with value timestamps
        WatchValue value;
    };
    // Arrival times of good values of `item` within [fromMs, toMs).
    QList<qint64> goodTimes(std::uint64_t item, qint64 fromMs, qint64 toMs) const
    {
        QList<qint64> times;
        for (const Entry &entry : entries) {
            if (entry.value.itemId == item && entry.value.quality == ValueQuality::Good
                && entry.atMs >= fromMs && entry.atMs < toMs)
                times.append(entry.atMs);
        }
        return times;
    }
    std::optional<WatchValue> last(std::uint64_t item) const
    {
        for (auto it = entries.crbegin(); it != entries.crend(); ++it) {
            if (it->value.itemId == item)
                return it->value;
        }
        return std::nullopt;
    }
    qint64 now() const { return m_clock.elapsed(); }
    // Values of `item` of this quality, from the start.
    qsizetype count(std::uint64_t item, ValueQuality quality) const
    {
        return std::count_if(entries.cbegin(), entries.cend(), [&](const Entry &entry) {
            return entry.value.itemId == item && entry.value.quality == quality;
        });
    }
    QList<Entry> entries;

private:
    QElapsedTimer m_clock;
};

} // namespace

class TestStationHealth : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void deadStationDoesNotStarveOthers_data();
    void deadStationDoesNotStarveOthers();
    void lateValuesAreMarked();
    void deadStationSparesGoodRows_data();
    void deadStationSparesGoodRows();
    void slowLineIsNotLateEveryCycle();
    void everyBatchIsOneWholeCycle();
    void scanRunsBehindDeadStation();
    void refusedElementReportedOnce();
    void toolReadsSpareRestingStation();

private:
    std::unique_ptr<Session> openSession(LinkSettings::ProtocolChoice protocol);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::shared_ptr<QProcess> m_socat;
    std::unique_ptr<QTemporaryDir> m_dir;
};

namespace {

// Traffic log events with this message id.
qsizetype events(const Session &session, MessageId id, std::uint8_t station)
{
    const QList<TrafficEntry> entries = session.trafficLog()->entries();
    return std::count_if(entries.cbegin(), entries.cend(), [&](const TrafficEntry &entry) {
        return entry.direction == TrafficEntry::Direction::Event && entry.summary.id == id
               && !entry.summary.args.empty()
               && entry.summary.args.front() == MessageArg(static_cast<int>(station));
    });
}

} // namespace

void TestStationHealth::init()
{
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_server = std::make_unique<SimServer>(m_plc.get());
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
}

void TestStationHealth::cleanup()
{
    m_server.reset();
    m_plc.reset();
    m_socat.reset();
    m_dir.reset();
}

std::unique_ptr<Session> TestStationHealth::openSession(LinkSettings::ProtocolChoice protocol)
{
    // The link as a user gets it: default timeout (1000 ms) and retries (2).
    auto session = std::make_unique<Session>(
        LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(), protocol));
    session->open();
    QDeadlineTimer deadline(10000);
    while (session->linkState() != LinkState::Connected && !deadline.hasExpired())
        QTest::qWait(5);
    return session;
}

void TestStationHealth::deadStationDoesNotStarveOthers_data()
{
    QTest::addColumn<int>("protocol");
    QTest::newRow("facon") << int(LinkSettings::ProtocolChoice::Facon);
    QTest::newRow("auto") << int(LinkSettings::ProtocolChoice::Auto);
}

void TestStationHealth::deadStationDoesNotStarveOthers()
{
    QFETCH(int, protocol);
    auto session = openSession(static_cast<LinkSettings::ProtocolChoice>(protocol));
    QCOMPARE(session->linkState(), LinkState::Connected);
    ValueLog log(session.get());
    constexpr int interval = 500;
    // R0 on station 7 (nobody answers) first, as in the field report.
    session->setWatchList({{1, 7, addr("R0"), interval}, {2, 1, addr("R1"), interval}});

    // The silent station is demoted after its first unanswered requests (a few seconds at a
    // 1 s timeout); from then on station 1 is polled at its own interval.
    QTRY_VERIFY_WITH_TIMEOUT(session->statistics().stations.value(7).demoted, 15000);
    const qint64 from = log.now();
    QTest::qWait(6000);
    const QList<qint64> times = log.goodTimes(2, from, log.now());
    QVERIFY2(times.size() >= 2, "station 1 got no good values");
    const double period = double(times.back() - times.front()) / double(times.size() - 1);
    qInfo("station 1: %lld good values in 6 s, mean period %.0f ms (interval %d ms)",
          qint64(times.size()), period, interval);
    QVERIFY2(period <= 1.5 * interval, qPrintable(QStringLiteral("mean period %1 ms").arg(period)));

    // The dead station's item says why it has no value, and when it is tried again.
    const std::optional<WatchValue> dead = log.last(1);
    QVERIFY(dead);
    QCOMPARE(dead->quality, ValueQuality::Stale);
    QCOMPARE(dead->error.id, MsgId::SessionStationDemoted);
    const StationStatistics seven = session->statistics().stations.value(7);
    QVERIFY(seven.demotions >= 1);
    QVERIFY(seven.nextTry.isValid());
    QVERIFY(!session->statistics().stations.value(1).demoted);
}

void TestStationHealth::lateValuesAreMarked()
{
    // A person asks station 7 (nobody there) with a long timeout: the request holds the line,
    // and station 1's values, polled every 200 ms, arrive later than twice their period and must
    // say so. (Polling itself no longer holds the line for a silent station: see
    // deadStationSparesGoodRows.)
    auto session = openSession(LinkSettings::ProtocolChoice::Facon);
    ValueLog log(session.get());
    session->setWatchList({{2, 1, addr("R1"), 200}});
    QTRY_VERIFY_WITH_TIMEOUT(log.goodTimes(2, 0, log.now()).size() >= 5, 10000);
    RequestOptions options;
    options.timeoutMs = 3000;
    options.retries = 0;
    std::optional<SessionResult> asked;
    session->submit(
        Request::briefStatus(7), this, [&](const SessionResult &result) { asked = result; },
        Priority::User, options);
    QTRY_VERIFY_WITH_TIMEOUT(std::any_of(log.entries.cbegin(), log.entries.cend(),
                                         [](const ValueLog::Entry &entry) {
                                             return entry.value.itemId == 2
                                                    && entry.value.quality == ValueQuality::Late;
                                         }),
                             10000);
    const auto late
        = std::find_if(log.entries.cbegin(), log.entries.cend(), [](const ValueLog::Entry &entry) {
              return entry.value.itemId == 2 && entry.value.quality == ValueQuality::Late;
          });
    // A late value is the last good one, with the time it was read, reported no sooner than two
    // intervals after that read.
    QCOMPARE(late->value.error.id, MsgId::SessionValueLate);
    const auto lastGood = std::find_if(
        std::make_reverse_iterator(late), log.entries.crend(), [](const ValueLog::Entry &entry) {
            return entry.value.itemId == 2 && entry.value.quality == ValueQuality::Good;
        });
    QVERIFY(lastGood != log.entries.crend());
    QCOMPARE(late->value.timestamp, lastGood->value.timestamp);
    QCOMPARE(late->value.value, lastGood->value.value);
    QVERIFY2(lastGood->value.timestamp.msecsTo(late->at) >= 2 * 200,
             qPrintable(QString::number(lastGood->value.timestamp.msecsTo(late->at))));
    QTRY_VERIFY_WITH_TIMEOUT(asked.has_value(), 10000);
}

void TestStationHealth::deadStationSparesGoodRows_data()
{
    QTest::addColumn<QString>("line");
    QTest::newRow("tcp") << QStringLiteral("tcp");
    QTest::newRow("serial 19200") << QStringLiteral("serial");
}

void TestStationHealth::deadStationSparesGoodRows()
{
    // Issue 54: R0 and R1 in the trend at 500 ms, R30 moved to station 7 (nobody there). The
    // station costs the line at most one short timeout before it rests, and its probes go only
    // in the line's slack: R0 and R1 never turn late and keep (nearly) every update, also while
    // station 7 is probed again.
    QFETCH(QString, line);
    LinkSettings settings;
    if (line == QLatin1String("tcp")) {
        settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(),
                                     LinkSettings::ProtocolChoice::Facon);
    } else {
        // A 19,200 baud line: a pty pair, the simulator taking each frame's wire time.
        m_dir = std::make_unique<QTemporaryDir>();
        const QString plcSide = m_dir->filePath(QStringLiteral("plc"));
        const QString appSide = m_dir->filePath(QStringLiteral("app"));
        m_socat = TestUtil::startPtyPair(plcSide, appSide);
        if (!m_socat)
            QSKIP("socat is not available for a serial pty pair");
        SerialSettings serial;
        serial.portName = plcSide;
        serial.baudRate = 19200;
        QString error;
        QVERIFY2(m_server->openSerial(serial, &error), qPrintable(error));
        FaultConfig faults;
        faults.baud = 19200;
        m_server->setFaults(faults);
        settings = LinkSettings::serial(appSide, 19200, LinkSettings::ProtocolChoice::Facon);
    }
    auto session = std::make_unique<Session>(settings); // default timeout and retries
    session->open();
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Connected, 10000);
    ValueLog log(session.get());
    constexpr int interval = 500;
    session->setWatchList({{1, 1, addr("R0"), interval},
                           {2, 1, addr("R1"), interval},
                           {3, 7, addr("R30"), interval}});
    QTRY_VERIFY_WITH_TIMEOUT(session->statistics().stations.value(7).demoted, 10000);
    // A window with station 7 probed again (its rest is 10 s).
    const qint64 from = log.now();
    constexpr qint64 window = 20000;
    const quint64 timeouts = session->statistics().stations.value(7).timeouts;
    QTRY_VERIFY_WITH_TIMEOUT(session->statistics().stations.value(7).timeouts > timeouts, 20000);
    if (log.now() - from < window)
        QTest::qWait(static_cast<int>(window - (log.now() - from)));
    const qint64 to = log.now();
    const double expected = double(to - from) / interval;
    for (const std::uint64_t item : {std::uint64_t(1), std::uint64_t(2)}) {
        const auto good = double(log.goodTimes(item, from, to).size());
        qInfo("%s, R%d beside a dead station: %.0f of %.1f updates (%.1f %%)", qPrintable(line),
              int(item - 1), good, expected, 100.0 * good / expected);
        QCOMPARE(log.count(item, ValueQuality::Late), 0);
        QVERIFY2(good >= 0.95 * expected,
                 qPrintable(QStringLiteral("%1 of %2 updates").arg(good).arg(expected)));
    }
    // Never slowed down on station 1's account, and station 7 says why it has no value.
    QCOMPARE(events(*session, MsgId::LogPollSlower, 1), 0);
    QCOMPARE(log.last(3)->error.id, MsgId::SessionStationDemoted);
    QVERIFY(!session->statistics().stations.value(1).demoted);
}

void TestStationHealth::slowLineIsNotLateEveryCycle()
{
    // Issue 55: a line slower than twice the interval (every answer 2.5 s late, interval 1 s).
    // The values are not late every cycle (good -> late -> good flapping); the poller says once
    // that the line gives one value every 2.5 s, and "late" is counted from that.
    FaultConfig faults;
    faults.latencyMs = 2500;
    m_server->setFaults(faults);
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_server->tcpPort(),
                                              LinkSettings::ProtocolChoice::Facon);
    settings.timeoutMs = 5000;
    auto session = std::make_unique<Session>(settings);
    session->open();
    QTRY_COMPARE_WITH_TIMEOUT(session->linkState(), LinkState::Connected, 10000);
    ValueLog log(session.get());
    session->setWatchList({{1, 1, addr("R0"), 1000}});
    QTRY_VERIFY_WITH_TIMEOUT(log.count(1, ValueQuality::Good) >= 5, 30000);
    QCOMPARE(log.count(1, ValueQuality::Late), 0);
    QCOMPARE(log.count(1, ValueQuality::Stale), 0);
    QCOMPARE(events(*session, MsgId::LogPollSlower, 1), 1);
    const QList<TrafficEntry> entries = session->trafficLog()->entries();
    const auto slower
        = std::find_if(entries.cbegin(), entries.cend(), [](const TrafficEntry &entry) {
              return entry.summary.id == MsgId::LogPollSlower;
          });
    QCOMPARE(slower->summary.args.at(1), MessageArg(1000));
    QVERIFY2(std::stoi(slower->summary.args.at(2).text) >= 2500,
             slower->summary.args.at(2).text.c_str());

    // The line is fast again: said once, and late counts from the interval again.
    m_server->setFaults({});
    QTRY_COMPARE_WITH_TIMEOUT(events(*session, MsgId::LogPollOnTime, 1), 1, 20000);
}

void TestStationHealth::everyBatchIsOneWholeCycle()
{
    // Issue 54 item 10: a 40-item list asked every 10 ms on a 9600 baud line (the simulator
    // takes each frame's wire time): a cycle takes far longer than the interval. Each batch the
    // session sends is one whole cycle (every item once, none reported late in between), and the
    // poller's cycle count agrees, so that "cycles" measured from the batches are cycles.
    FaultConfig faults;
    faults.baud = 9600;
    faults.turnaroundMs = 3;
    m_server->setFaults(faults);
    auto session = openSession(LinkSettings::ProtocolChoice::Facon);
    QList<WatchEntry> entries;
    for (std::uint32_t n = 0; n < 40; ++n)
        entries.append({n + 1, 1, Address{ElementType::R, n}, 10});
    struct Batch
    {
        QList<WatchValue> values;
        quint64 pollCycles = 0;
    };
    QList<Batch> batches;
    connect(session.get(), &Session::values, this, [&](const QList<WatchValue> &values) {
        batches.append({values, session->statistics().pollCycles});
    });
    session->setWatchList(entries);
    QTRY_VERIFY_WITH_TIMEOUT(batches.size() >= 6, 30000);
    session->setWatchList({});
    for (qsizetype i = 0; i < batches.size(); ++i) {
        const Batch &batch = batches.at(i);
        QCOMPARE(batch.values.size(), entries.size());
        for (const WatchValue &value : batch.values)
            QCOMPARE(value.quality, ValueQuality::Good);
        QCOMPARE(batch.pollCycles, batches.front().pollCycles + quint64(i));
    }
}

void TestStationHealth::scanRunsBehindDeadStation()
{
    // The studio connected to station 7 (nobody answers) under auto-detect: its status reads and
    // the watch list all go to station 7. A scan must still finish.
    auto session = openSession(LinkSettings::ProtocolChoice::Auto);
    session->setWatchList(
        {{1, 7, addr("R0"), 500}, {2, 7, addr("M0"), 500}, {3, 7, addr("D0"), 1000}});
    // The connection's own status questions, as ui/connection asks them.
    for (int i = 0; i < 5; ++i)
        session->submit(Request::briefStatus(7), Priority::Poll);
    QTest::qWait(1500);

    StationScanner scanner(session.get());
    QSignalSpy finished(&scanner, &StationScanner::finished);
    QElapsedTimer took;
    took.start();
    scanner.start(1, 10, 100);
    QVERIFY2(finished.wait(30000), "the scan did not finish within 30 s");
    qInfo("scan of 1..10 behind a dead station: %lld ms", took.elapsed());
    const auto hits = finished.front().front().value<QList<StationScanner::Hit>>();
    QCOMPARE(hits.size(), 1);
    QCOMPARE(hits.front().station, quint8(1));
}

void TestStationHealth::refusedElementReportedOnce()
{
    // An FBs has no R5000: the PLC refuses it with error A. It is found, shown as an error, and
    // from then on asked rarely; the error counters are for faults, not for a known refusal.
    auto session = openSession(LinkSettings::ProtocolChoice::Facon);
    ValueLog log(session.get());
    session->setWatchList({{1, 1, addr("R5000"), 100}, {2, 1, addr("R0"), 100}});
    QTRY_VERIFY_WITH_TIMEOUT(log.last(1).has_value(), 5000);
    QTest::qWait(300);
    const quint64 errorsBefore = session->statistics().total.plcErrors;
    QTest::qWait(3000);
    const SessionStatistics after = session->statistics();
    qInfo("PLC errors counted in 3 s of polling a refused element at 100 ms: %llu",
          after.total.plcErrors - errorsBefore);
    QVERIFY2(after.total.plcErrors - errorsBefore <= 1,
             qPrintable(QStringLiteral("%1 PLC errors").arg(after.total.plcErrors - errorsBefore)));
    // Still shown as refused, and the good neighbour keeps its rate.
    QCOMPARE(log.last(1)->quality, ValueQuality::Error);
    QVERIFY(log.goodTimes(2, log.now() - 3000, log.now()).size() >= 15);
}

void TestStationHealth::toolReadsSpareRestingStation()
{
    // The studio's own routine reads (status, forced marks) of a station the poller demoted are
    // answered at once with the reason instead of holding up the line for a timeout and its
    // retries; a user's request still goes out, once; an answer to it ends the rest early.
    m_server->setVerbose(true);
    int silentFrames = 0; // frames for station 7 on the wire
    connect(m_server.get(), &SimServer::logLine, this, [&](const QString &line) {
        if (line.contains(QStringLiteral("for station 7 ignored")))
            ++silentFrames;
    });
    auto session = openSession(LinkSettings::ProtocolChoice::Facon);
    session->setWatchList({{1, 7, addr("R0"), 500}, {2, 1, addr("R1"), 500}});
    QTRY_VERIFY_WITH_TIMEOUT(session->statistics().stations.value(7).demoted, 15000);
    const int framesAtDemotion = silentFrames;

    QList<SessionResult> routine;
    QElapsedTimer took;
    took.start();
    for (int i = 0; i < 3; ++i)
        session->submit(
            Request::briefStatus(7), this,
            [&](const SessionResult &result) { routine.append(result); }, Priority::Poll);
    QTRY_COMPARE_WITH_TIMEOUT(routine.size(), 3, 2000);
    qInfo("3 status reads of a resting station answered in %lld ms", took.elapsed());
    for (const SessionResult &result : routine) {
        QCOMPARE(result.errorKind(), ErrorKind::Timeout);
        QCOMPARE(result.error().message.id, MsgId::SessionStationDemoted);
    }
    QCOMPARE(silentFrames, framesAtDemotion); // none of them went out

    // Someone asks on purpose: one attempt, no retries.
    std::optional<SessionResult> asked;
    session->submit(Request::briefStatus(7), this,
                    [&](const SessionResult &result) { asked = result; });
    QTRY_VERIFY_WITH_TIMEOUT(asked.has_value(), 5000);
    QCOMPARE(asked->errorKind(), ErrorKind::Timeout);
    QCOMPARE(asked->attempts(), 1);
    QCOMPARE(silentFrames, framesAtDemotion + 1);

    // The PLC is set to station 7 and answers the next question: the rest ends then, not at the
    // next poll trial (10 s after the demotion).
    m_server->setStation(7);
    asked.reset();
    session->submit(Request::briefStatus(7), this,
                    [&](const SessionResult &result) { asked = result; });
    QTRY_VERIFY_WITH_TIMEOUT(asked.has_value(), 5000);
    QVERIFY2(asked->ok(), qPrintable(asked->errorText()));
    QVERIFY(!session->statistics().stations.value(7).demoted);
    QVERIFY2(took.elapsed() < 8000, "the rest ended only at the poll trial");
}

QTEST_GUILESS_MAIN(TestStationHealth)
#include "tst_stationhealth.moc"
