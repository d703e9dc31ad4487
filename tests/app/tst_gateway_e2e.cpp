// The whole plant path end to end (issue 20): the in-process simulator (the PLC, over loopback
// TCP) → the real fatek-gateway executable → a real mosquitto → GatewayWatch, the one that serves
// the GUI's tables. No protocol peer stands in for either side: what GatewayWatch shows was read
// from the simulator, and a write it sends is counted in the simulator's own log.
#include "core/link/gatewaywatch.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QFile>
#include <QHash>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cstring>

#ifdef Q_OS_LINUX
#include <sys/prctl.h>
#include <unistd.h>
#endif

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 15000; // QTRY timeouts: generous for a loaded 2-core machine under TSan

const char *const watchList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[{"address":"R100","format":"float","name":"Level"},
   {"address":"R200","name":"Setpoint"},{"address":"R300"}]}]})json";

} // namespace

class TestGatewayEndToEnd : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void plcToWatchAndBack_data();
    void plcToWatchAndBack();

private:
    bool writeFile(const QString &name, const QByteArray &bytes);
    int simWrites() const
    {
        return static_cast<int>(m_simLog.filter(QStringLiteral(" write ")).size());
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_sim;
    std::unique_ptr<QProcess> m_gateway;
    QStringList m_simLog;
};

bool TestGatewayEndToEnd::writeFile(const QString &name, const QByteArray &bytes)
{
    QFile file(m_dir->filePath(name));
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

void TestGatewayEndToEnd::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QString error;
    QVERIFY2(m_broker->start(&error), qPrintable(error));
    m_plc = std::make_unique<SimulatedPlc>();
    m_sim = std::make_unique<SimServer>(m_plc.get());
    m_sim->setVerbose(true);
    m_simLog.clear();
    connect(m_sim.get(), &SimServer::logLine, this,
            [this](const QString &line) { m_simLog.append(line); });
    QVERIFY2(m_sim->listenTcp(0, &error), qPrintable(error));
}

void TestGatewayEndToEnd::cleanup()
{
    if (m_gateway && m_gateway->state() != QProcess::NotRunning) {
        m_gateway->kill();
        m_gateway->waitForFinished(5000);
    }
    m_gateway.reset();
    m_sim.reset();
    m_plc.reset();
    m_broker.reset();
    m_dir.reset();
}

void TestGatewayEndToEnd::plcToWatchAndBack_data()
{
    QTest::addColumn<bool>("denyWriteExecute");
    QTest::newRow("plain") << false;
#ifdef Q_OS_LINUX
    // The service runs with MemoryDenyWriteExecute=yes (packaging/linux/fatek-gateway.service):
    // no memory may become executable after it was writable (a JIT, e.g. a regular expression's,
    // would fail). The kernel's own switch for the same rule (PR_SET_MDWE, Linux 6.3) shows the
    // gateway works under it without systemd.
    QTest::newRow("memory deny write execute") << true;
#endif
}

void TestGatewayEndToEnd::plcToWatchAndBack()
{
    QFETCH(bool, denyWriteExecute);
    float level = 12.5f;
    std::uint32_t bits = 0;
    std::memcpy(&bits, &level, sizeof bits);
    QVERIFY(m_plc->setValue(addr("R100"), bits & 0xFFFF));
    QVERIFY(m_plc->setValue(addr("R101"), bits >> 16));
    QVERIFY(m_plc->setValue(addr("R200"), 42));

    QVERIFY(writeFile(QStringLiteral("line1.json"), watchList));
    const QByteArray config
        = QStringLiteral(
              R"json({"format":"fatek-gateway","version":1,"broker":{"url":"%1","keepAliveSec":5},
  "prefix":"plant/fatek","connections":[{"name":"line1","link":{"kind":"tcp","host":"127.0.0.1",
  "port":%2,"protocol":"facon","timeoutMs":500,"retries":0},"watchLists":[{"file":"line1.json"}],
  "allow":["R200..R299"]}]})json")
              .arg(m_broker->url())
              .arg(m_sim->tcpPort())
              .toUtf8();
    QVERIFY(writeFile(QStringLiteral("gateway.json"), config));
    m_gateway = std::make_unique<QProcess>();
    m_gateway->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    constexpr int noDenyWriteExecute = 97;
#ifdef Q_OS_LINUX
    if (denyWriteExecute) {
        m_gateway->setChildProcessModifier([] {
            constexpr int setMdwe = 65; // PR_SET_MDWE, PR_MDWE_REFUSE_EXEC_GAIN
            if (::prctl(setMdwe, 1UL, 0UL, 0UL, 0UL) != 0)
                ::_exit(noDenyWriteExecute);
        });
    }
#endif
    m_gateway->start(QStringLiteral(FATEK_GATEWAY_PATH),
                     {m_dir->filePath(QStringLiteral("gateway.json"))});
    QVERIFY(m_gateway->waitForStarted(5000));
    if (denyWriteExecute && m_gateway->waitForFinished(500)
        && m_gateway->exitCode() == noDenyWriteExecute)
        QSKIP("this kernel has no PR_SET_MDWE (Linux 6.3 or later)");

    GatewayWatchSettings settings;
    settings.broker = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.broker.reconnectMinMs = 50;
    settings.broker.reconnectMaxMs = 500;
    settings.prefix = QStringLiteral("plant/fatek");
    settings.connection = QStringLiteral("line1");
    GatewayWatch watch(settings);
    QHash<quint64, WatchItemValue> latest;
    connect(&watch, &PlcLink::itemValues, this, [&latest](const QList<WatchItemValue> &values) {
        for (const WatchItemValue &value : values)
            latest.insert(value.key, value);
    });
    // The table's items: the float, the setpoint, and one the gateway does not publish.
    const auto spec = [](const char *address, DisplayFormat format) {
        WatchItemSpec item;
        item.address = addr(address);
        item.format = format;
        return item;
    };
    watch.setItems({{1, spec("R100", DisplayFormat::Float32), 500},
                    {3, spec("R200", DisplayFormat::Signed), 500},
                    {4, spec("R500", DisplayFormat::Signed), 500}});
    watch.open();

    auto good = [&latest](quint64 key, std::uint64_t value) {
        const WatchItemValue v = latest.value(key);
        return v.quality == ValueQuality::Good && v.hasValue && v.raw == value;
    };
    QTRY_VERIFY_WITH_TIMEOUT(good(1, bits) && good(3, 42), Wait);
    QCOMPARE(watch.linkState(), LinkState::Connected);
    // Stale while the gateway connected, then (after its items had time to come) an error that
    // says the gateway does not publish it.
    QTRY_VERIFY_WITH_TIMEOUT(latest.contains(4) && latest.value(4).quality == ValueQuality::Error,
                             Wait);
    QVERIFY(english(latest.value(4).error).find("not published") != std::string::npos);

    // The PLC changes: the watch follows, through the gateway.
    QVERIFY(m_plc->setValue(addr("R200"), 43));
    QTRY_VERIFY_WITH_TIMEOUT(good(3, 43), Wait);

    // An allowlisted write reaches the PLC (its own log and memory) and is answered ok.
    const int writesBefore = simWrites();
    std::optional<LinkWriteResult> reply;
    watch.write(spec("R200", DisplayFormat::Signed), 77, this,
                [&reply](const LinkWriteResult &r) { reply = r; });
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), Wait);
    QVERIFY2(reply->ok, qPrintable(QString::fromStdString(english(reply->error))));
    QCOMPARE(simWrites(), writesBefore + 1);
    QCOMPARE(m_plc->value(addr("R200")), std::optional<std::uint32_t>(77));
    QTRY_VERIFY_WITH_TIMEOUT(good(3, 77), Wait);

    // The PLC stops answering and still acts on what it gets (an answer lost on the line): the
    // write is unknown, not failed; the gateway reads it back once the PLC answers again, and its
    // final reply (same id) says done. One write reached the PLC.
    FaultConfig mute;
    mute.dropRate = 1.0;
    m_sim->setFaults(mute);
    QList<LinkWriteResult> reports;
    watch.write(spec("R200", DisplayFormat::Signed), 88, this,
                [&reports](const LinkWriteResult &r) { reports.append(r); });
    QTRY_VERIFY_WITH_TIMEOUT(!reports.isEmpty(), Wait);
    QCOMPARE(reports.first().outcome, ChangeOutcome::Unknown);
    QVERIFY(!reports.first().final);
    QVERIFY(!reports.first().ok);
    QCOMPARE(m_plc->value(addr("R200")), std::optional<std::uint32_t>(88));
    m_sim->setFaults({});
    QTRY_VERIFY_WITH_TIMEOUT(reports.last().final, Wait);
    QCOMPARE(reports.size(), 2);
    QCOMPARE(reports.last().outcome, ChangeOutcome::Done);
    QVERIFY(reports.last().ok);
    QCOMPARE(simWrites(), writesBefore + 2);
    QTRY_VERIFY_WITH_TIMEOUT(good(3, 88), Wait);

    // Outside the allowlist: refused with the reason, nothing reaches the PLC.
    reply.reset();
    watch.write(spec("R100", DisplayFormat::Float32), 0x3FC00000, this,
                [&reply](const LinkWriteResult &r) { reply = r; });
    QTRY_VERIFY_WITH_TIMEOUT(reply.has_value(), Wait);
    QVERIFY(!reply->ok);
    QVERIFY(!english(reply->error).empty());
    QCOMPARE(reply->outcome, ChangeOutcome::Refused);
    QCOMPARE(simWrites(), writesBefore + 2);

    // The gateway dies without a word: the broker publishes its will, and the watch shows every
    // value stale (the last one, never as fresh) and the link lost.
    m_gateway->kill();
    m_gateway->waitForFinished(5000);
    QTRY_VERIFY_WITH_TIMEOUT(watch.linkState() == LinkState::Lost, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(latest.value(3).quality, ValueQuality::Stale, Wait);
    QCOMPARE(latest.value(3).raw, 88u);
    QCOMPARE(latest.value(1).quality, ValueQuality::Stale);
}

QTEST_GUILESS_MAIN(TestGatewayEndToEnd)
#include "tst_gateway_e2e.moc"
