// Figure 6: fatek-gateway at plant scale (issue 20). The real gateway process polls simulated
// PLCs (SimServer over loopback TCP, values changing faster than the poll rate, so every poll
// publishes every item) and publishes to a real mosquitto; a subscriber in this process measures
// the latency from the PLC's answer (the payload's "time", stamped when the gateway got the
// answer) to its arrival, the message rate, and the gateway's CPU share and resident memory
// (/proc).
#include "bench.h"
#include "simthread.h"

#include "core/mqtt/mqttclient.h"
#include "core/watch/watchlist.h"
#include "tests/mosquittobroker.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTimer>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

namespace Fatek::Bench {

namespace {

// utime + stime of a process, in seconds.
double cpuSeconds(qint64 pid)
{
    QFile file(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    const QByteArray text = file.readAll();
    // Fields after the command name (which may hold spaces) start after the last ')'.
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return 0;
    const double ticks = fields[11].toDouble() + fields[12].toDouble(); // utime, stime
    return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// A line of /proc/PID/status in MiB ("VmRSS", "VmHWM").
double statusMiB(qint64 pid, const char *key)
{
    QFile file(QStringLiteral("/proc/%1/status").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith(key))
            return line.mid(line.indexOf(':') + 1).trimmed().split(' ').first().toDouble() / 1024.0;
    }
    return 0;
}

// "2026-11-26T02:04:14.947Z" in ms since the epoch, without QDateTime (whose parser cost more
// per message than the gateway's encoder).
std::optional<qint64> isoMs(const QByteArray &text)
{
    if (text.size() != 24 || text[4] != '-' || text[10] != 'T' || text[19] != '.'
        || text[23] != 'Z')
        return std::nullopt;
    const auto number = [&](int at, int digits) {
        qint64 value = 0;
        for (int i = at; i < at + digits; ++i)
            value = value * 10 + (text[i] - '0');
        return value;
    };
    // Days from 1970-01-01 for a proleptic Gregorian date (H. Hinnant's days_from_civil).
    qint64 y = number(0, 4);
    const qint64 m = number(5, 2);
    const qint64 d = number(8, 2);
    y -= m <= 2 ? 1 : 0;
    const qint64 era = y / 400;
    const qint64 yoe = y - era * 400;
    const qint64 doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
    const qint64 doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    const qint64 days = era * 146097 + doe - 719468;
    return ((days * 24 + number(11, 2)) * 60 + number(14, 2)) * 60000 + number(17, 2) * 1000
           + number(20, 3);
}

double percentile(std::vector<double> sorted, double p)
{
    if (sorted.empty())
        return 0;
    std::sort(sorted.begin(), sorted.end());
    const auto index = static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1));
    return sorted[index];
}

struct CaseResult
{
    bool ok = false;
    QString error;
    double messagesPerSecond = 0;
    double expectedPerSecond = 0;
    double p50 = 0;
    double p99 = 0;
    double max = 0;
    double cpuPercent = 0;
    double brokerCpuPercent = 0;
    double rssMiB = 0;
    double peakRssMiB = 0;
    std::size_t samples = 0;
    // The gateway's own delay (PLC answer -> hand-over to its broker connection), from its
    // statistics topics: the median of the links' p50 and the largest of their p99.
    double gatewayP50 = 0;
    double gatewayP99 = 0;
};

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate)
           && file.write(bytes) == bytes.size();
}

CaseResult runCase(int plcCount, int itemCount, int intervalMs, int seconds)
{
    CaseResult result;
    TestUtil::MosquittoBroker broker;
    if (!broker.start(&result.error))
        return result;

    std::vector<std::unique_ptr<SimThread>> plcs;
    for (int i = 0; i < plcCount; ++i)
        plcs.push_back(std::make_unique<SimThread>());

    QTemporaryDir dir;
    WatchTableSpec table;
    table.name = QStringLiteral("bench");
    table.intervalMs = intervalMs;
    for (int i = 0; i < itemCount; ++i) {
        WatchItemSpec item;
        item.address = Address{ElementType::R, static_cast<std::uint32_t>(i)};
        table.items.append(item);
    }
    WatchListFile list;
    list.tables.append(table);
    if (!writeFile(dir.filePath(QStringLiteral("list.json")), WatchList::save(list))) {
        result.error = QStringLiteral("cannot write the watch list");
        return result;
    }
    QJsonArray connections;
    for (int i = 0; i < plcCount; ++i) {
        connections.append(QJsonObject{
            {QStringLiteral("name"), QStringLiteral("plc%1").arg(i + 1, 2, 10, QLatin1Char('0'))},
            {QStringLiteral("link"),
             QJsonObject{{QStringLiteral("kind"), QStringLiteral("tcp")},
                         {QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                         {QStringLiteral("port"), plcs[static_cast<std::size_t>(i)]->port()},
                         {QStringLiteral("protocol"), QStringLiteral("facon")}}},
            {QStringLiteral("statisticsIntervalMs"), 1000},
            {QStringLiteral("watchLists"),
             QJsonArray{QJsonObject{{QStringLiteral("file"), QStringLiteral("list.json")}}}},
        });
    }
    const QJsonObject config{
        {QStringLiteral("format"), QStringLiteral("fatek-gateway")},
        {QStringLiteral("version"), 1},
        {QStringLiteral("broker"), QJsonObject{{QStringLiteral("url"), broker.url()}}},
        {QStringLiteral("prefix"), QStringLiteral("bench")},
        {QStringLiteral("connections"), connections},
    };
    const QString configPath = dir.filePath(QStringLiteral("gateway.json"));
    if (!writeFile(configPath, QJsonDocument(config).toJson())) {
        result.error = QStringLiteral("cannot write the gateway config");
        return result;
    }

    // Values change twice per poll interval: every poll reads new values, every item publishes.
    // Each simulated PLC changes its own values on its own thread, as a PLC does: this process's
    // main thread only measures (at 100,000 values/s one thread doing both fell behind).
    std::vector<QTimer *> mutators;
    for (auto &plc : plcs) {
        SimThread *sim = plc.get();
        QTimer *timer = nullptr;
        QMetaObject::invokeMethod(
            sim->context(),
            [sim, itemCount, intervalMs, &timer] {
                timer = new QTimer(sim->context());
                auto tick = std::make_shared<std::uint32_t>(0);
                QObject::connect(timer, &QTimer::timeout, sim->context(), [sim, itemCount, tick] {
                    ++*tick;
                    for (int i = 0; i < itemCount; ++i)
                        sim->plc().setValue(Address{ElementType::R, static_cast<std::uint32_t>(i)},
                                            (*tick * 7 + static_cast<std::uint32_t>(i)) & 0xFFFF);
                });
                timer->start(std::max(1, intervalMs / 2));
            },
            Qt::BlockingQueuedConnection);
        mutators.push_back(timer);
    }
    const auto stopMutators = [&] {
        for (std::size_t i = 0; i < mutators.size(); ++i)
            QMetaObject::invokeMethod(
                plcs[i]->context(), [timer = mutators[i]] { delete timer; },
                Qt::BlockingQueuedConnection);
        mutators.clear();
    };
    const auto mutatorGuard = qScopeGuard(stopMutators);

    MqttBrokerSettings brokerSettings = *MqttBrokerSettings::fromUrl(broker.url());
    MqttClient subscriber(brokerSettings);
    subscriber.subscribe(QStringLiteral("bench/+/+/+"));
    subscriber.subscribe(QStringLiteral("bench/+/statistics"));
    std::vector<double> gatewayP50s;
    double gatewayP99 = 0;
    bool measuring = false;
    bool timeParseMismatch = false;
    std::size_t received = 0;
    std::vector<double> latencies;
    latencies.reserve(
        static_cast<std::size_t>(plcCount * itemCount * (1000 / intervalMs + 1) * (seconds + 1)));
    QObject::connect(
        &subscriber, &MqttClient::messageReceived,
        [&](const QString &topic, const QByteArray &payload, bool retained) {
            if (!measuring || retained)
                return;
            if (topic.endsWith(QLatin1String("/statistics"))) {
                const QJsonObject own = QJsonDocument::fromJson(payload)
                                            .object()
                                            .value(QStringLiteral("gateway"))
                                            .toObject();
                gatewayP50s.push_back(own.value(QStringLiteral("delayP50Ms")).toDouble());
                gatewayP99
                    = std::max(gatewayP99, own.value(QStringLiteral("delayP99Ms")).toDouble());
                return;
            }
            const qint64 now = QDateTime::currentMSecsSinceEpoch();
            ++received;
            const qsizetype at = payload.indexOf("\"time\":\"");
            if (at < 0)
                return;
            const QByteArray text = payload.mid(at + 8, 24);
            const std::optional<qint64> time = isoMs(text);
            if (!time)
                return;
            if (latencies.empty()
                && QDateTime::fromString(QString::fromLatin1(text), Qt::ISODateWithMs)
                           .toMSecsSinceEpoch()
                       != *time)
                timeParseMismatch = true; // checked once against Qt's parser
            latencies.push_back(static_cast<double>(now - *time));
        });
    subscriber.open();

    QProcess gateway;
    gateway.setStandardErrorFile(dir.filePath(QStringLiteral("gateway.log")));
    gateway.setStandardOutputFile(QProcess::nullDevice());
    gateway.start(QStringLiteral(FATEK_GATEWAY_PATH), {configPath});
    if (!gateway.waitForStarted(5000)) {
        result.error = QStringLiteral("fatek-gateway did not start: %1").arg(gateway.errorString());
        return result;
    }
    auto spin = [](int ms) {
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < ms)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    };
    spin(3000); // links up, first cycles, retained state published
    if (gateway.state() != QProcess::Running) {
        QFile log(dir.filePath(QStringLiteral("gateway.log")));
        log.open(QIODevice::ReadOnly);
        result.error
            = QStringLiteral("fatek-gateway exited: %1").arg(QString::fromUtf8(log.readAll()));
        return result;
    }
    const qint64 pid = gateway.processId();
    const qint64 brokerPid = broker.processId();
    const double cpu0 = cpuSeconds(pid);
    const double brokerCpu0 = cpuSeconds(brokerPid);
    QElapsedTimer window;
    window.start();
    measuring = true;
    spin(seconds * 1000);
    measuring = false;
    const double elapsed = static_cast<double>(window.elapsed()) / 1000.0;
    result.cpuPercent = 100.0 * (cpuSeconds(pid) - cpu0) / elapsed;
    result.brokerCpuPercent = 100.0 * (cpuSeconds(brokerPid) - brokerCpu0) / elapsed;
    result.rssMiB = statusMiB(pid, "VmRSS");
    result.peakRssMiB = statusMiB(pid, "VmHWM");
    stopMutators();
    gateway.terminate();
    gateway.waitForFinished(10000);

    result.messagesPerSecond = static_cast<double>(received) / elapsed;
    result.expectedPerSecond = plcCount * itemCount * 1000.0 / intervalMs;
    result.samples = latencies.size();
    result.p50 = percentile(latencies, 0.50);
    result.p99 = percentile(latencies, 0.99);
    result.gatewayP50 = percentile(gatewayP50s, 0.50);
    result.gatewayP99 = gatewayP99;
    result.max = latencies.empty() ? 0 : *std::max_element(latencies.begin(), latencies.end());
    result.ok = !latencies.empty() && !timeParseMismatch;
    if (latencies.empty())
        result.error = QStringLiteral("no value arrived");
    else if (timeParseMismatch)
        result.error = QStringLiteral("the bench's time parser disagrees with QDateTime");
    return result;
}

} // namespace

void runGateway(const Options &options, Report &report)
{
    struct Case
    {
        int plcs;
        int items;
        int intervalMs;
        bool targets;
    };
    const int seconds = options.quick ? 5 : 20;
    for (const Case &c : {Case{50, 200, 1000, true}, Case{10, 1000, 100, false}}) {
        const QString name = QStringLiteral("gateway %1 PLCs x %2 items @ %3 Hz")
                                 .arg(c.plcs)
                                 .arg(c.items)
                                 .arg(1000 / c.intervalMs);
        const CaseResult r = runCase(c.plcs, c.items, c.intervalMs, seconds);
        if (!r.ok) {
            report.row(name, QStringLiteral("failed: %1").arg(r.error));
            if (c.targets)
                report.result(QStringLiteral("gateway_50x200_p99_ms"), 0, QStringLiteral("<50"),
                              false);
            continue;
        }
        report.row(name + QStringLiteral(": messages/s"), fmt(r.messagesPerSecond, 0),
                   QStringLiteral("every item every poll %1").arg(fmt(r.expectedPerSecond, 0)),
                   ratioText(r.messagesPerSecond, r.expectedPerSecond));
        report.row(name + QStringLiteral(": latency p50 / p99 / max (ms)"),
                   QStringLiteral("%1 / %2 / %3").arg(fmt(r.p50, 0), fmt(r.p99, 0), fmt(r.max, 0)),
                   QStringLiteral("%1 samples").arg(r.samples), {},
                   c.targets ? QStringLiteral("p99 < 50") : QString());
        report.row(name + QStringLiteral(": gateway's own delay p50 / p99 (ms)"),
                   QStringLiteral("%1 / %2").arg(fmt(r.gatewayP50, 0), fmt(r.gatewayP99, 0)),
                   QStringLiteral("PLC answer -> hand-over"));
        report.row(name + QStringLiteral(": gateway CPU (% of one core)"), fmt(r.cpuPercent, 1),
                   QStringLiteral("broker %1").arg(fmt(r.brokerCpuPercent, 1)), {},
                   c.targets ? QStringLiteral("< 50") : QString());
        report.row(name + QStringLiteral(": gateway resident memory (MiB)"), fmt(r.rssMiB, 1),
                   QStringLiteral("peak %1").arg(fmt(r.peakRssMiB, 1)));
        const QString key = QStringLiteral("gateway_%1x%2").arg(c.plcs).arg(c.items);
        if (c.targets) {
            report.result(key + QStringLiteral("_p99_ms"), r.p99, QStringLiteral("<50"),
                          r.p99 < 50);
            report.result(key + QStringLiteral("_cpu_pct"), r.cpuPercent, QStringLiteral("<50"),
                          r.cpuPercent < 50);
        }
    }
}

} // namespace Fatek::Bench
