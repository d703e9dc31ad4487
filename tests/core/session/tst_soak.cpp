// Fault soak and bounds: a session polls the simulator with every fault knob on and must keep
// polling, count each fault, recover, and never report a value the PLC did not hold; peers that
// flood bytes or never answer must not grow memory.
//
// FATEK_SOAK_SECONDS=N runs the TCP soak for N seconds (default 20; UDP gets half of it). The
// figures are printed with qInfo ("soak figures: ..."). Any N runs: main() raises Qt Test's
// per-function watchdog to fit.
#include "core/session/session.h"
#include "core/session/sessionworker.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QElapsedTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>
#include <QTimer>

#include <deque>
#include <map>
#include <memory>

using namespace Fatek;

// GCC defines __SANITIZE_ADDRESS__; clang only answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define FATEK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FATEK_ASAN 1
#endif
#endif
#ifdef FATEK_ASAN
constexpr bool builtWithAddressSanitizer = true;
#else
constexpr bool builtWithAddressSanitizer = false;
#endif

namespace {

Address addr(const char *text)
{
    return Address::parse(text).value();
}

// Resident memory of this process in kB (Linux), 0 if unknown.
qint64 residentKb()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return 0;
}

int soakSeconds()
{
    const int s = qEnvironmentVariableIntValue("FATEK_SOAK_SECONDS");
    return s > 0 ? s : 20;
}

// What the simulator's memory held over time, per watched address: every write the test made,
// in order. A reported value must be one of them, at or after the one reported before.
class History
{
public:
    void record(std::uint64_t id, std::uint32_t value) { m_values[id].push_back(value); }

    // True if `value` is what the PLC held at some point since the last accepted value.
    bool accept(std::uint64_t id, std::uint32_t value)
    {
        std::deque<std::uint32_t> &values = m_values[id];
        for (std::size_t i = values.size(); i-- > 0;) {
            if (values[i] == value) {
                values.erase(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(i));
                return true;
            }
        }
        return false;
    }

private:
    std::map<std::uint64_t, std::deque<std::uint32_t>> m_values;
};

struct SoakFigures
{
    quint64 goodValues = 0;
    quint64 wrongValues = 0;
    quint64 staleValues = 0;
    quint64 lateValues = 0;
    qint64 maxGapMs = 0; // longest time without a good value
};

} // namespace

class TestSoak : public QObject
{
    Q_OBJECT

public:
    // Before QTest starts (QTEST_GUILESS_MAIN calls it). Qt Test ends a test function that runs
    // longer than QTEST_FUNCTION_TIMEOUT ms (5 min by default), read once when it starts: a long
    // soak (TCP, then half of it over UDP, each settling a few seconds) raises it to fit, unless
    // the caller gave more.
    static void initMain()
    {
        const qint64 soakMs = qint64(soakSeconds()) * 1000;
        const qint64 neededMs = soakMs + std::max<qint64>(5000, soakMs / 2) + 5 * 60 * 1000;
        bool given = false;
        const qint64 givenMs = qEnvironmentVariableIntValue("QTEST_FUNCTION_TIMEOUT", &given);
        if (!given || givenMs < neededMs)
            qputenv("QTEST_FUNCTION_TIMEOUT", QByteArray::number(neededMs));
    }

private Q_SLOTS:
    void initTestCase() { registerSessionMetaTypes(); }
    void soak_data();
    void soak();
    void floodingPeer();
    void silentPeer();
    void trafficLogBytes();
};

void TestSoak::soak_data()
{
    QTest::addColumn<bool>("udp");
    QTest::newRow("tcp") << false;
    QTest::newRow("udp") << true;
}

void TestSoak::soak()
{
    QFETCH(bool, udp);
    const int seconds = udp ? std::max(5, soakSeconds() / 2) : soakSeconds();

    // The ladder stays off (STOP): the test itself changes memory, so it knows every value the
    // PLC held.
    SimulatedPlc plc;
    SimServer server(&plc);
    FaultConfig faults;
    faults.dropRate = 0.03;
    faults.corruptRate = 0.004; // per byte: about one answer in ten
    faults.garbageBytes = 3;
    faults.jitterMs = 20;
    faults.spikeRate = 0.05;
    faults.spikeMs = 150; // below the timeout: a slow answer is no error
    faults.wrongStationRate = 0.03;
    faults.chunkSize = 9;
    faults.chunkDelayMs = 1;
    faults.closeEverySeconds = udp ? 0 : 3;
    faults.seed = 8;
    server.setFaults(faults);
    QVERIFY(udp ? server.listenUdp(0) : server.listenTcp(0));

    LinkSettings settings = udp ? LinkSettings::udp(QStringLiteral("127.0.0.1"), server.udpPort())
                                : LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.tcpPort());
    settings.protocol = LinkSettings::ProtocolChoice::Facon;
    settings.timeoutMs = 600;
    settings.retries = 1;
    settings.reconnectMinMs = 100;
    settings.reconnectMaxMs = 400;
    Session session(settings);

    struct Watched
    {
        const char *address;
        std::function<std::uint32_t(std::uint32_t)> valueAt; // the k-th write
    };
    const std::vector<Watched> watched = {
        {"R100",
         [](std::uint32_t k) {
             return (k * 4 + 1) & 0xFFFF;
         }},
        {"R101",
         [](std::uint32_t k) {
             return (k * 4 + 2) & 0xFFFF;
         }},
        {"R102",
         [](std::uint32_t k) {
             return (k * 4 + 3) & 0xFFFF;
         }},
        {"DR200",
         [](std::uint32_t k) {
             return k * 2654435761u;
         }},
        {"WM0",
         [](std::uint32_t k) {
             return (k * 40503u) & 0xFFFF;
         }},
    };
    History history;
    std::uint32_t k = 0;
    auto writeAll = [&] {
        ++k;
        for (std::size_t i = 0; i < watched.size(); ++i) {
            const std::uint32_t v = watched[i].valueAt(k);
            const Address a = addr(watched[i].address);
            if (a.type == ElementType::WM) {
                for (std::uint32_t bit = 0; bit < 16; ++bit)
                    QVERIFY(plc.setValue({ElementType::M, a.number + bit}, (v >> bit) & 1));
            } else {
                QVERIFY(plc.setValue(a, v));
            }
            history.record(i, v);
        }
    };
    writeAll();
    QTimer writer;
    QObject::connect(&writer, &QTimer::timeout, &writer, writeAll);
    writer.start(37);

    SoakFigures figures;
    QElapsedTimer clock;
    clock.start();
    qint64 lastGood = 0;
    QObject::connect(&session, &Session::values, &session, [&](const QList<WatchValue> &values) {
        for (const WatchValue &v : values) {
            if (v.quality == ValueQuality::Stale) {
                ++figures.staleValues;
                continue;
            }
            if (v.quality == ValueQuality::Late) {
                // The last good value, said to be old: checked like a good one, counted apart.
                ++figures.lateValues;
                if (!history.accept(v.itemId, v.value)) {
                    ++figures.wrongValues;
                    qWarning("item %d: late value %u never held by the PLC", int(v.itemId),
                             v.value);
                }
                continue;
            }
            if (v.quality != ValueQuality::Good) {
                ++figures.wrongValues; // the simulator accepts every address watched
                qWarning("item %d: %s", int(v.itemId), qPrintable(englishText(v.error)));
                continue;
            }
            if (history.accept(v.itemId, v.value)) {
                ++figures.goodValues;
                figures.maxGapMs = std::max(figures.maxGapMs, clock.elapsed() - lastGood);
                lastGood = clock.elapsed();
            } else {
                ++figures.wrongValues;
                qWarning("item %d: value %u never held by the PLC", int(v.itemId), v.value);
            }
        }
    });

    QList<WatchEntry> entries;
    for (std::size_t i = 0; i < watched.size(); ++i)
        entries.append({i, 1, addr(watched[i].address), 50});
    session.open();
    session.setWatchList(entries);

    qint64 rssWarm = 0;
    quint64 goodAtHalf = 0;
    // The soak's length, and on until every kind of fault has been injected at least once: the
    // faults are random per answer, and a slow build (TSan: 54 answers in 5 s) may see no spike
    // in that time. Bounded: a fault kind still missing after six times as long fails below.
    const auto everyFaultSeen = [&server] {
        const SimServer::Counters c = server.counters();
        return c.faultyAnswers > 0 && c.spikes > 0 && c.garbageBytes > 0;
    };
    while (clock.elapsed() < seconds * 1000
           || (!everyFaultSeen() && clock.elapsed() < seconds * 6000)) {
        QTest::qWait(100);
        if (rssWarm == 0 && clock.elapsed() > seconds * 250)
            rssWarm = residentKb();
        if (goodAtHalf == 0 && clock.elapsed() > seconds * 500)
            goodAtHalf = figures.goodValues;
    }
    // Stop polling and let the last answers (and any late close) arrive before counting.
    session.setWatchList({});
    writer.stop();
    QTest::qWait(settings.timeoutMs * (settings.retries + 1) + 500);
    const qint64 rssEnd = residentKb();
    const SessionStatistics st = session.statistics();
    const SimServer::Counters sim = server.counters();
    const quint64 counted = st.total.timeouts + st.total.checksumErrors + st.total.frameErrors;

    qInfo("soak figures (%s, %d s): answers %llu, faults injected %llu (dropped %llu, corrupted "
          "%llu, wrong station %llu) + spikes %llu + garbage bytes %llu + disconnects %llu; "
          "faults counted %llu (timeouts %llu, checksum %llu, framing %llu), link losses %llu, "
          "bytes discarded %llu; good values %llu, stale %llu, late %llu, wrong values %llu; "
          "longest gap "
          "without a good value %lld ms; poll cycles %llu; RSS %lld -> %lld kB; log %d entries, "
          "%lld bytes",
          udp ? "udp" : "tcp", seconds, sim.answers, sim.faultyAnswers, sim.dropped, sim.corrupted,
          sim.wrongStation, sim.spikes, sim.garbageBytes, sim.closed, counted, st.total.timeouts,
          st.total.checksumErrors, st.total.frameErrors, st.linkLosses, st.bytesDiscarded,
          figures.goodValues, figures.staleValues, figures.lateValues, figures.wrongValues,
          figures.maxGapMs, st.pollCycles, rssWarm, rssEnd, session.trafficLog()->size(),
          session.trafficLog()->bytesHeld());

    // Never a value the PLC did not hold.
    QCOMPARE(figures.wrongValues, quint64(0));
    // Polling went on through the faults, in the second half too.
    QVERIFY(goodAtHalf > 0);
    QVERIFY(figures.goodValues > goodAtHalf);
    QVERIFY(sim.faultyAnswers > 0 && sim.spikes > 0 && sim.garbageBytes > 0);
    // Each disconnect counted once.
    QCOMPARE(st.linkLosses, sim.closed);
    if (!udp)
        QVERIFY(sim.closed > 0);
    // Each faulty answer counted once: a drop or a wrong station as a timeout, a damaged answer
    // as a checksum or framing error (or a timeout when its frame start or end was hit). A
    // disconnect can swallow the one answer in flight before the session sees it.
    QVERIFY2(counted <= sim.faultyAnswers, "a fault was counted twice, or a good answer as bad");
    QVERIFY2(sim.faultyAnswers - counted <= sim.closed, "a fault went uncounted");
    // Noise is counted as discarded.
    QVERIFY(st.bytesDiscarded >= sim.garbageBytes / 2);
    // Recovery: after a fault (two failed attempts at worst, then a reconnect with backoff, up to
    // a quarter longer at random) the next cycle brings good values again. Generous: sanitizer
    // builds run slowly.
    const qint64 recoveryBound
        = settings.timeoutMs * (settings.retries + 1) * 2 + settings.reconnectMaxMs * 5 / 4 + 3000;
    QVERIFY2(figures.maxGapMs <= recoveryBound, qPrintable(QString::number(figures.maxGapMs)));
    // Memory: the traffic log stays within its bounds, the process does not keep growing.
    QVERIFY(session.trafficLog()->size() <= session.trafficLog()->capacity());
    QVERIFY(session.trafficLog()->bytesHeld() <= session.trafficLog()->byteBudget());
    if (rssWarm > 0 && !builtWithAddressSanitizer)
        QVERIFY2(rssEnd - rssWarm < 64 * 1024, "memory grew by more than 64 MB during the soak");
}

// A peer that sends bytes as fast as it can: the session's buffers and log stay bounded, the
// session stays responsive, and nothing is reported good.
void TestSoak::floodingPeer()
{
    QTcpServer peer;
    QVERIFY(peer.listen(QHostAddress::LocalHost));
    QList<QTcpSocket *> clients;
    QTimer flood;
    const QByteArray noise(64 * 1024, 'Z');
    QObject::connect(&peer, &QTcpServer::newConnection, &peer, [&] {
        while (QTcpSocket *s = peer.nextPendingConnection())
            clients.append(s);
    });
    QObject::connect(&flood, &QTimer::timeout, &flood, [&] {
        for (QTcpSocket *s : clients) {
            if (s->bytesToWrite() < 4 * noise.size())
                s->write(noise);
        }
    });
    flood.start(1);

    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), peer.serverPort());
    settings.protocol = LinkSettings::ProtocolChoice::Facon;
    settings.timeoutMs = 200;
    settings.retries = 0;
    Session session(settings);
    session.trafficLog()->setByteBudget(1024 * 1024);
    int good = 0;
    int stale = 0;
    QObject::connect(&session, &Session::values, &session, [&](const QList<WatchValue> &values) {
        for (const WatchValue &v : values)
            (v.quality == ValueQuality::Good ? good : stale) += 1;
    });
    session.open();
    session.setWatchList({{1, 1, addr("R0"), 20}});
    const qint64 rssStart = residentKb();
    QElapsedTimer clock;
    clock.start();
    // At least 4 s, and until 10 MiB of flood arrived: on a loaded machine (CI, sanitizers) the
    // peer floods slower, and a fixed window saw less than the bound checked below.
    constexpr quint64 FloodBytes = 10 * 1024 * 1024;
    while (clock.elapsed() < 4000
           || (session.statistics().bytesDiscarded <= FloodBytes && clock.elapsed() < 60000))
        QTest::qWait(50);
    const qint64 rssEnd = residentKb();
    session.setWatchList({});
    flood.stop();

    const SessionStatistics st = session.statistics();
    qInfo("flood: %llu bytes in, %llu discarded, log %d entries / %lld bytes, RSS %lld -> %lld kB",
          st.total.bytesIn, st.bytesDiscarded, session.trafficLog()->size(),
          session.trafficLog()->bytesHeld(), rssStart, rssEnd);
    QCOMPARE(good, 0);
    QVERIFY(stale > 0);                      // polling went on (and timed out)
    QVERIFY(st.bytesDiscarded > FloodBytes); // the flood really arrived
    QVERIFY(session.trafficLog()->bytesHeld() <= 1024 * 1024);
    // AddressSanitizer keeps freed blocks in a quarantine (256 MB by default), so resident memory
    // says nothing about our buffers there; the bounds above still hold in that build.
    if (rssStart > 0 && !builtWithAddressSanitizer)
        QVERIFY2(rssEnd - rssStart < 64 * 1024, "memory grew by more than 64 MB under a flood");
    qDeleteAll(clients);
}

// A peer that accepts and never answers: queued requests are capped with a clear error, raw
// answers cannot pile up, and the queue empties by timeouts.
void TestSoak::silentPeer()
{
    QTcpServer peer;
    QVERIFY(peer.listen(QHostAddress::LocalHost));
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), peer.serverPort());
    settings.protocol = LinkSettings::ProtocolChoice::Facon;
    settings.timeoutMs = 100;
    settings.retries = 0;
    Session session(settings);
    QSignalSpy state(&session, &Session::linkStateChanged);
    session.open();
    QTRY_COMPARE(session.linkState(), LinkState::Connected);

    int limited = 0;
    int timeouts = 0;
    QString limitText;
    QObject::connect(&session, &Session::finished, &session,
                     [&](quint64, const SessionResult &result) {
                         if (result.errorKind() == ErrorKind::LimitExceeded) {
                             ++limited;
                             limitText = result.errorText();
                         } else if (result.errorKind() == ErrorKind::Timeout) {
                             ++timeouts;
                         }
                     });
    const int submitted = int(SessionWorker::maxQueuedRequests) + 500;
    for (int i = 0; i < submitted; ++i)
        session.submit(Request::readRegisters(1, {ElementType::R, 0}, 1));
    // At least the 500 beyond the cap are refused at once (one may already be on the wire).
    QTRY_VERIFY_WITH_TIMEOUT(limited >= 499, 10000);
    QVERIFY2(limited <= 500, qPrintable(QString::number(limited)));
    QVERIFY2(limitText.contains(QStringLiteral("already waiting")), qPrintable(limitText));
    QTRY_VERIFY(timeouts > 0); // the queue drains by timeouts
    session.close();
}

void TestSoak::trafficLogBytes()
{
    TrafficLog log(1000);
    log.setByteBudget(64 * 1024);
    const QByteArray big(100 * 1024, 'x');
    for (int i = 0; i < 50; ++i)
        log.append(TrafficEntry::Direction::In, big, Message::text("noise"));
    QVERIFY(log.bytesHeld() <= 64 * 1024);
    const auto entries = log.entries();
    QVERIFY(!entries.isEmpty());
    QCOMPARE(entries.last().bytes.size(), TrafficLog::maxEntryBytes);
    QVERIFY(englishText(entries.last().error).contains(QStringLiteral("first 4096 kept")));
    log.clear();
    QCOMPARE(log.bytesHeld(), qint64(0));
}

QTEST_GUILESS_MAIN(TestSoak)
#include "tst_soak.moc"
