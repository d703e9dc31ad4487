// Field faults on a multi-drop link (issue 31): a station that never answers must not slow the
// stations that do, one-shot requests get the line whatever the poll list does, and an element the
// PLC refuses is reported once and polled rarely. A real simulator over loopback TCP answers as
// station 1; station 7 has nobody behind it.
#include "core/session/session.h"
#include "core/session/stationscanner.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QElapsedTimer>
#include <QSignalSpy>
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
    void scanRunsBehindDeadStation();
    void refusedElementReportedOnce();
    void toolReadsSpareRestingStation();

private:
    std::unique_ptr<Session> openSession(LinkSettings::ProtocolChoice protocol);

    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
};

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
    // Station 7 is demoted only after 3 requests in a row without an answer; until then
    // station 1's values arrive later than twice their interval and must say so.
    auto session = openSession(LinkSettings::ProtocolChoice::Facon);
    ValueLog log(session.get());
    session->setWatchList({{1, 7, addr("R0"), 200}, {2, 1, addr("R1"), 200}});
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
