// Issue 51: the gateway's history. Its "history" configuration is read strictly (every key
// known, the place named; a password in a PostgreSQL URL refused); the in-process Gateway against
// a real mosquitto and the in-process simulator records what its items do into an SQLite store
// (every item with "recordAll", else only those with a "history" setting) and keeps an Off sample
// when it stops; the real fatek-gateway killed with SIGKILL while recording leaves a store that
// opens and holds every value older than the last second.
#include "core/gateway/gateway.h"
#include "core/gateway/gatewayconfig.h"
#include "core/history/historystore.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QDateTime>
#include <QFile>
#include <QProcess>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

#include <csignal>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 10000; // QTRY timeouts: generous for a loaded 2-core machine

const char *const plainList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[
   {"address":"R100","name":"Tank level"},{"address":"R101"}]}]})json";
const char *const recordedList = R"json({"format":"fatek-studio-watchlist","version":2,"tables":[
  {"name":"Main","intervalMs":100,"items":[
   {"address":"R100","name":"Tank level","history":{"heartbeatS":5}},{"address":"R101"}]}]})json";

QString configJson(const QString &history,
                   const QString &broker = QStringLiteral("mqtt://127.0.0.1:1"), int port = 1)
{
    return QStringLiteral(R"({"format":"fatek-gateway","version":1,"prefix":"fatek","readOnly":true,
      "broker":{"url":"%1"},%2"connections":[{"name":"line1",
      "link":{"kind":"tcp","host":"127.0.0.1","port":%3,"timeoutMs":500,"retries":0},
      "watchLists":[{"file":"line1.json"}]}]})")
        .arg(broker, history.isEmpty() ? QString() : QStringLiteral("\"history\":%1,").arg(history))
        .arg(port);
}

} // namespace

class TestGatewayHistory : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void configRefusals_data();
    void configRefusals();
    void configDefaults();
    void recordsEveryItemAndStops();
    void recordsOnlyItemsWithASetting();
    void killedGatewayLosesAtMostTheLastSecond();

private:
    void writeList(const char *json);
    Result<GatewayConfig> load(const QString &history) const;
    bool runGateway(const GatewayConfig &config, int ms);
    std::vector<HistorySample> samplesOf(const QString &key) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
};

void TestGatewayHistory::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    writeList(plainList);
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setValue(addr("R100"), 500);
    m_plc->setValue(addr("R101"), 7);
    m_server = std::make_unique<SimServer>(m_plc.get());
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QVERIFY2(m_broker->start(&error), qPrintable(error));
}

void TestGatewayHistory::cleanup()
{
    m_broker.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

void TestGatewayHistory::writeList(const char *json)
{
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly | QIODevice::Truncate));
    list.write(json);
}

Result<GatewayConfig> TestGatewayHistory::load(const QString &history) const
{
    Result<GatewayConfig> loaded = GatewayConfig::load(
        configJson(history, m_broker->url(), m_server->tcpPort()).toUtf8(), m_dir->path());
    if (loaded) {
        loaded.value().broker.reconnectMinMs = 50;
        loaded.value().broker.reconnectMaxMs = 500;
    }
    return loaded;
}

void TestGatewayHistory::configRefusals_data()
{
    QTest::addColumn<QString>("history");
    QTest::addColumn<QString>("error");
    QTest::newRow("misspelt key")
        << R"({"recordAll":true,"heartbeat":60})"
        << R"(history: "heartbeat" is not a known setting; did you mean "heartbeatS"?)";
    QTest::newRow("defaults without recordAll")
        << R"({"deadband":2})"
        << R"(history: "deadband" is the setting of every item recorded with "recordAll")";
    QTest::newRow("heartbeat out of range") << R"({"recordAll":true,"heartbeatS":0})"
                                            << "history: heartbeatS";
    QTest::newRow("negative deadband") << R"({"recordAll":true,"deadband":-1})"
                                       << "history: deadband";
    QTest::newRow("retention key")
        << R"({"retention":{"day":3}})"
        << R"(history: retention: "day" is not a known setting; did you mean "days"?)";
    QTest::newRow("negative days") << R"({"retention":{"days":-1}})"
                                   << "history: retention: days";
    QTest::newRow("empty store") << R"({"store":" "})"
                                 << R"("store" must name a file.)";
    QTest::newRow("password in the URL")
        << R"({"store":"postgresql://fatek:secret@127.0.0.1/plant"})"
        << "holds a password"; // refused before a build without libpq says so (issue 55)
    QTest::newRow("not an object") << R"(true)"
                                   << "history";
}

void TestGatewayHistory::configRefusals()
{
    QFETCH(QString, history);
    QFETCH(QString, error);
    const Result<GatewayConfig> loaded = load(history);
    QVERIFY2(!loaded, "loaded");
    const QString text = QString::fromStdString(loaded.error().text());
    QVERIFY2(text.contains(error), qPrintable(text));
}

void TestGatewayHistory::configDefaults()
{
    qunsetenv("STATE_DIRECTORY");
    const Result<GatewayConfig> none = load({});
    QVERIFY2(none, none ? "" : none.error().text().c_str());
    QCOMPARE(none->historyCount(), 0); // no item has a setting, nothing recorded
    QCOMPARE(none->history.store, m_dir->filePath(QStringLiteral("history.db")));
    QCOMPARE(none->history.retention.maxAgeS, 30LL * 24 * 3600);
    QVERIFY(!none->history.recordAll);

    const Result<GatewayConfig> all = load(QStringLiteral(
        R"({"store":"data/h.sqlite","recordAll":true,"deadband":0.5,"heartbeatS":60,
            "retention":{"days":0,"maxMB":100}})"));
    QVERIFY2(all, all ? "" : all.error().text().c_str());
    QCOMPARE(all->historyCount(), 2);
    QCOMPARE(all->history.store, m_dir->filePath(QStringLiteral("data/h.sqlite")));
    QVERIFY(all->history.recordAll);
    QCOMPARE(all->history.recordAll->deadband, 0.5);
    QCOMPARE(all->history.recordAll->heartbeatS, 60);
    QCOMPARE(all->history.retention.maxAgeS, 0);
    QCOMPARE(all->history.retention.maxBytes, 100LL * 1024 * 1024);
}

bool TestGatewayHistory::runGateway(const GatewayConfig &config, int ms)
{
    Gateway gateway;
    QStringList log;
    connect(&gateway, &Gateway::logEvent, this, [&log](const QString &c, const Message &event) {
        log.append(c + QStringLiteral(": ") + QString::fromStdString(english(event)));
    });
    QString failed;
    Message error;
    if (!gateway.start(config, &failed, &error)) {
        qWarning() << failed << QString::fromStdString(english(error));
        return false;
    }
    // The value changes twice while the gateway polls it.
    QTest::qWait(ms / 3);
    m_plc->setValue(addr("R100"), 501);
    QTest::qWait(ms / 3);
    m_plc->setValue(addr("R100"), 502);
    QTest::qWait(ms / 3);
    bool stopped = false;
    connect(&gateway, &Gateway::stopped, this, [&stopped] { stopped = true; });
    gateway.stop();
    const bool done = QTest::qWaitFor([&] { return stopped; }, Wait);
    for (const QString &line : std::as_const(log)) {
        if (line.contains(QLatin1String("history")))
            qWarning() << line;
    }
    return done;
}

std::vector<HistorySample> TestGatewayHistory::samplesOf(const QString &key) const
{
    Result<std::unique_ptr<HistoryStore>> store = HistoryStore::open(
        m_dir->filePath(QStringLiteral("history.db")), HistoryStore::Mode::ReadOnly);
    if (!store) {
        qWarning() << QString::fromStdString(store.error().text());
        return {};
    }
    const Result<QList<HistorySeries>> series = (*store)->series();
    if (!series)
        return {};
    for (const HistorySeries &s : *series) {
        if (s.key() == key) {
            const Result<std::vector<HistorySample>> samples
                = (*store)->samples(s.id, 0, std::numeric_limits<qint64>::max());
            return samples ? *samples : std::vector<HistorySample>{};
        }
    }
    return {};
}

void TestGatewayHistory::recordsEveryItemAndStops()
{
    const Result<GatewayConfig> config = load(QStringLiteral(R"({"recordAll":true})"));
    QVERIFY2(config, config ? "" : config.error().text().c_str());
    const qint64 started = QDateTime::currentMSecsSinceEpoch();
    QVERIFY(runGateway(*config, 1500));
    const qint64 ended = QDateTime::currentMSecsSinceEpoch();

    const std::vector<HistorySample> r100 = samplesOf(QStringLiteral("line1/1-R100"));
    QList<double> values;
    for (const HistorySample &s : r100) {
        QVERIFY(s.timeMs >= started && s.timeMs <= ended);
        if (History::hasValue(s.quality))
            values.append(s.value);
    }
    // Each value once (an unchanged value is not kept again), in the order they came.
    QCOMPARE(values, (QList<double>{500, 501, 502}));
    QVERIFY(!r100.empty());
    QCOMPARE(r100.back().quality, HistoryQuality::Off);
    const std::vector<HistorySample> r101 = samplesOf(QStringLiteral("line1/1-R101"));
    QVERIFY(r101.size() >= 2);
    QCOMPARE(r101.front().value, 7.0);
    QCOMPARE(r101.front().raw, quint64(7));
    QCOMPARE(r101.back().quality, HistoryQuality::Off);
}

void TestGatewayHistory::recordsOnlyItemsWithASetting()
{
    writeList(recordedList);
    const Result<GatewayConfig> config = load({});
    QVERIFY2(config, config ? "" : config.error().text().c_str());
    QCOMPARE(config->historyCount(), 1);
    QVERIFY(runGateway(*config, 900));
    QVERIFY(!samplesOf(QStringLiteral("line1/1-R100")).empty());
    QVERIFY(samplesOf(QStringLiteral("line1/1-R101")).empty());
}

void TestGatewayHistory::killedGatewayLosesAtMostTheLastSecond()
{
#ifndef Q_OS_LINUX
    QSKIP("SIGKILL of a child process: Linux only");
#else
    QFile config(m_dir->filePath(QStringLiteral("gateway.json")));
    QVERIFY(config.open(QIODevice::WriteOnly));
    config.write(
        configJson(QStringLiteral(R"({"recordAll":true})"), m_broker->url(), m_server->tcpPort())
            .toUtf8());
    config.close();
    QProcess gateway;
    gateway.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    gateway.start(QStringLiteral(FATEK_GATEWAY_PATH), {config.fileName()});
    QVERIFY(gateway.waitForStarted(5000));
    // Polling and recording before the first value counts: a started process has not yet
    // connected to the PLC or opened its store (under ASan that took longer than a poll, and
    // the first value was never read, CI).
    m_plc->setValue(addr("R100"), 999);
    QTRY_VERIFY_WITH_TIMEOUT(!samplesOf(QStringLiteral("line1/1-R100")).empty(), 30000);
    // A new value every 300 ms for 3 s, each held for three polls (100 ms): a value held for one
    // poll interval is missed by any jitter of the poll, and the promise is about what was read.
    QList<std::pair<qint64, int>> set;
    for (int i = 0; i < 10; ++i) {
        m_plc->setValue(addr("R100"), static_cast<std::uint32_t>(1000 + i));
        set.append({QDateTime::currentMSecsSinceEpoch(), 1000 + i});
        QTest::qWait(300);
    }
    QVERIFY2(gateway.state() == QProcess::Running, "the gateway ended by itself");
    ::kill(static_cast<pid_t>(gateway.processId()), SIGKILL);
    const qint64 killed = QDateTime::currentMSecsSinceEpoch();
    QVERIFY(gateway.waitForFinished(5000));

    const std::vector<HistorySample> kept = samplesOf(QStringLiteral("line1/1-R100"));
    QVERIFY2(!kept.empty(), "the store does not open, or holds nothing");
    QSet<int> values;
    for (const HistorySample &s : kept)
        values.insert(static_cast<int>(s.value));
    // Set more than the flush (1 s) plus a poll and its answer (0.1 s + slack) before the kill:
    // committed for sure.
    for (const auto &[at, value] : std::as_const(set)) {
        if (at < killed - 1600)
            QVERIFY2(values.contains(value),
                     qPrintable(QStringLiteral("%1 set %2 ms before the kill is missing")
                                    .arg(value)
                                    .arg(killed - at)));
    }
#endif
}

QTEST_GUILESS_MAIN(TestGatewayHistory)
#include "tst_gatewayhistory.moc"
