// Figure 3: TCP loopback throughput and round trip. The full Session (submit() in this thread,
// the I/O on its worker thread, finished() back through a queued signal) against a bare
// QTcpSocket ping-pong (blocking, in this thread, no session) on the same simulator, with the
// same request, one transaction at a time. Also what a transaction costs the process (CPU time,
// context switches): on a busy machine the rates swing, these hardly do.
#include "bench.h"
#include "simthread.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "core/session/sessionresult.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTcpSocket>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <memory>

namespace Fatek::Bench {

namespace {

// What a run cost the whole process (this thread, the session's worker, the simulator) per
// transaction: CPU time, voluntary context switches (a thread went to sleep waiting) and read or
// write system calls (eventfd wake-ups included). Counts, unlike rates and latencies, hardly move
// with other load on the machine.
struct Cost
{
    double cpuUs = 0;
    double sleeps = 0;
    double syscalls = 0;
};

class CostMeter
{
public:
    void start() { m_start = sample(); }
    Cost per(qint64 transactions) const
    {
        if (transactions <= 0)
            return {};
        const Sample end = sample();
        const auto n = static_cast<double>(transactions);
        return {static_cast<double>(end.cpuNs - m_start.cpuNs) / 1000.0 / n,
                static_cast<double>(end.sleeps - m_start.sleeps) / n,
                static_cast<double>(end.syscalls - m_start.syscalls) / n};
    }

private:
    struct Sample
    {
        qint64 cpuNs = 0;
        qint64 sleeps = 0;
        qint64 syscalls = 0;
    };
    static Sample sample()
    {
        Sample s;
        timespec t{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
        s.cpuNs = qint64(t.tv_sec) * 1000000000 + t.tv_nsec;
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage); // all threads of the process
        s.sleeps = qint64(usage.ru_nvcsw);
        // syscr/syscw: read and write calls of all threads (Linux).
        QFile io(QStringLiteral("/proc/self/io"));
        if (io.open(QIODevice::ReadOnly)) {
            for (const QByteArray &line : io.readAll().split('\n')) {
                if (line.startsWith("syscr:") || line.startsWith("syscw:"))
                    s.syscalls += line.mid(6).trimmed().toLongLong();
            }
        }
        return s;
    }
    Sample m_start;
};

struct Latency
{
    bool ok = false;
    double perSecond = 0;
    double p50Us = 0;
    double p99Us = 0;
    Cost oneAtATime; // the round-trip run
    Cost queued;     // the throughput run (session only)
};

Latency summarize(std::vector<double> samplesUs, double seconds)
{
    Latency l;
    if (samplesUs.empty() || seconds <= 0)
        return l;
    std::sort(samplesUs.begin(), samplesUs.end());
    auto pct = [&samplesUs](double p) {
        const auto i = static_cast<std::size_t>(p * static_cast<double>(samplesUs.size() - 1));
        return samplesUs[i];
    };
    l.ok = true;
    l.perSecond = static_cast<double>(samplesUs.size()) / seconds;
    l.p50Us = pct(0.50);
    l.p99Us = pct(0.99);
    return l;
}

Request benchRequest()
{
    return Request::readRegisters(1, {ElementType::R, 0}, 10);
}

// Round trips one at a time (submit() to finished(), in this thread), then throughput with
// `depth` requests kept queued in the session, as a poll cycle queues its steps.
Latency viaSession(quint16 port, Protocol protocol, int warmup, double seconds, int depth,
                   double *closedLoopPerSecond)
{
    LinkSettings settings
        = LinkSettings::tcp(QStringLiteral("127.0.0.1"), port, choiceOf(protocol));
    Session session(settings);
    if (!openAndWait(session))
        return {};
    const Request request = benchRequest();
    std::vector<double> samples;
    samples.reserve(200000);
    QElapsedTimer clock;
    QElapsedTimer run;
    CostMeter meter;
    Cost cost;
    int done = 0;
    bool failed = false;
    bool pipelined = false;
    qint64 runNs = 0;
    QEventLoop loop;
    QObject::connect(
        &session, &Session::finished, &loop, [&](quint64, const SessionResult &result) {
            const qint64 ns = clock.nsecsElapsed();
            if (!result.ok()) {
                failed = true;
                loop.quit();
                return;
            }
            if (++done == warmup) {
                run.start();
                meter.start();
            } else if (done > warmup && !pipelined) {
                samples.push_back(static_cast<double>(ns) / 1000.0);
            }
            if (done > warmup && static_cast<double>(run.nsecsElapsed()) >= seconds * 1e9) {
                runNs = run.nsecsElapsed();
                cost = meter.per(done - warmup);
                loop.quit();
                return;
            }
            clock.start();
            session.submit(request);
        });
    clock.start();
    session.submit(request);
    loop.exec();
    if (failed)
        return {};
    Latency latency = summarize(std::move(samples), static_cast<double>(runNs) / 1e9);
    *closedLoopPerSecond = latency.perSecond;
    latency.oneAtATime = cost;

    // Throughput: `depth` in the queue at all times.
    pipelined = true;
    done = 0;
    clock.start();
    for (int i = 0; i < depth; ++i)
        session.submit(request);
    loop.exec();
    // The requests still queued finish (or are dropped) when the session goes.
    if (failed || runNs <= 0)
        return {};
    latency.perSecond = static_cast<double>(done - warmup) * 1e9 / static_cast<double>(runNs);
    latency.queued = cost;
    return latency;
}

Latency viaBareSocket(quint16 port, Protocol protocol, int warmup, double seconds)
{
    FaconCodec facon;
    BinaryCodec binary;
    const Codec &codec = protocol == Protocol::Facon ? static_cast<const Codec &>(facon)
                                                     : static_cast<const Codec &>(binary);
    std::unique_ptr<Deframer> deframer;
    if (protocol == Protocol::Facon)
        deframer = std::make_unique<FaconDeframer>();
    else
        deframer = std::make_unique<BinaryDeframer>();
    QTcpSocket socket;
    socket.connectToHost(QStringLiteral("127.0.0.1"), port);
    if (!socket.waitForConnected(5000))
        return {};
    socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    const Request request = benchRequest();
    const Bytes query = codec.encodeRequest(request).value();
    const QByteArray out(reinterpret_cast<const char *>(query.data()),
                         static_cast<qsizetype>(query.size()));
    std::vector<double> samples;
    samples.reserve(200000);
    std::vector<DeframedItem> frames;
    QElapsedTimer run;
    CostMeter meter;
    for (int i = 0;; ++i) {
        if (i == warmup) {
            run.start();
            meter.start();
        }
        QElapsedTimer clock;
        clock.start();
        socket.write(out);
        frames.clear();
        while (frames.empty()) {
            if (socket.bytesAvailable() == 0 && !socket.waitForReadyRead(5000))
                return {};
            const QByteArray in = socket.readAll();
            deframer->feed(std::span(reinterpret_cast<const std::uint8_t *>(in.constData()),
                                     static_cast<std::size_t>(in.size())),
                           frames);
        }
        // Decoded like the session does, so both sides do the protocol work.
        if (frames.front().error || !codec.decodeResponse(frames.front().frame, request))
            return {};
        if (i >= warmup)
            samples.push_back(static_cast<double>(clock.nsecsElapsed()) / 1000.0);
        if (i >= warmup && static_cast<double>(run.nsecsElapsed()) >= seconds * 1e9)
            break;
    }
    const Cost cost = meter.per(static_cast<qint64>(samples.size()));
    Latency latency = summarize(std::move(samples), static_cast<double>(run.nsecsElapsed()) / 1e9);
    latency.oneAtATime = cost;
    return latency;
}

} // namespace

void runTcp(const Options &options, Report &report)
{
    const double seconds = options.quick ? 0.3 : 2.0;
    const int warmup = options.quick ? 50 : 500;
    double worstRatio = 1e9;
    double worstOverhead = 0;
    bool ok = true;
    SimThread sim;
    for (Protocol protocol : {Protocol::Facon, Protocol::Binary}) {
        const QString proto = QString::fromUtf8(protocolName(protocol).data());
        const Latency bare = viaBareSocket(sim.port(), protocol, warmup, seconds);
        double closedLoop = 0;
        const Latency session = viaSession(sim.port(), protocol, warmup, seconds, 8, &closedLoop);
        if (!bare.ok || !session.ok) {
            ok = false;
            report.row(QStringLiteral("tcp %1: transactions").arg(proto),
                       QStringLiteral("failed (bare %1, session %2)")
                           .arg(bare.ok ? QStringLiteral("ok") : QStringLiteral("failed"),
                                session.ok ? QStringLiteral("ok") : QStringLiteral("failed")));
            continue;
        }
        const double ratio = session.perSecond / bare.perSecond;
        const double overhead = session.p99Us - bare.p99Us;
        worstRatio = std::min(worstRatio, ratio);
        worstOverhead = std::max(worstOverhead, overhead);
        report.row(
            QStringLiteral("tcp %1: session transactions/s, 8 queued (46 x 10 R)").arg(proto),
            fmt(session.perSecond, 0), QStringLiteral("bare %1").arg(fmt(bare.perSecond, 0)),
            fmt(ratio, 3), QStringLiteral(">= 0.8 x bare"));
        report.row(QStringLiteral("tcp %1: session transactions/s, one at a time").arg(proto),
                   fmt(closedLoop, 0), QStringLiteral("bare %1").arg(fmt(bare.perSecond, 0)),
                   fmt(closedLoop / bare.perSecond, 3));
        report.row(QStringLiteral("tcp %1: session RTT p50 (us)").arg(proto), fmt(session.p50Us, 1),
                   QStringLiteral("bare %1").arg(fmt(bare.p50Us, 1)),
                   QStringLiteral("+%1 us").arg(fmt(session.p50Us - bare.p50Us, 1)));
        report.row(QStringLiteral("tcp %1: session RTT p99 (us)").arg(proto), fmt(session.p99Us, 1),
                   QStringLiteral("bare %1").arg(fmt(bare.p99Us, 1)),
                   QStringLiteral("+%1 us").arg(fmt(overhead, 1)),
                   QStringLiteral("overhead < 50 us"));
        report.row(QStringLiteral("tcp %1: CPU per transaction, 8 queued (us)").arg(proto),
                   fmt(session.queued.cpuUs, 1),
                   QStringLiteral("bare %1").arg(fmt(bare.oneAtATime.cpuUs, 1)),
                   fmt(session.queued.cpuUs / bare.oneAtATime.cpuUs, 3));
        report.row(QStringLiteral("tcp %1: CPU per transaction, one at a time (us)").arg(proto),
                   fmt(session.oneAtATime.cpuUs, 1),
                   QStringLiteral("bare %1").arg(fmt(bare.oneAtATime.cpuUs, 1)),
                   fmt(session.oneAtATime.cpuUs / bare.oneAtATime.cpuUs, 3));
        report.row(QStringLiteral("tcp %1: sleeps per transaction, 8 queued / one").arg(proto),
                   QStringLiteral("%1 / %2").arg(fmt(session.queued.sleeps, 2),
                                                 fmt(session.oneAtATime.sleeps, 2)),
                   QStringLiteral("bare %1").arg(fmt(bare.oneAtATime.sleeps, 2)));
        report.row(
            QStringLiteral("tcp %1: read+write calls per transaction, 8 queued / one").arg(proto),
            QStringLiteral("%1 / %2").arg(fmt(session.queued.syscalls, 1),
                                          fmt(session.oneAtATime.syscalls, 1)),
            QStringLiteral("bare %1").arg(fmt(bare.oneAtATime.syscalls, 1)));
    }
    // Targets of issue 35.
    report.result(QStringLiteral("tcp_session_vs_bare_throughput"), ok ? worstRatio : 0,
                  QStringLiteral(">=0.8"), ok && worstRatio >= 0.8);
    report.result(QStringLiteral("tcp_p99_overhead_us"), worstOverhead, QStringLiteral("<50"),
                  ok && worstOverhead < 50);
}

} // namespace Fatek::Bench
