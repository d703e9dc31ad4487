// Writes through the gateway under the one rule for changes (issue 48, case 4): a PLC that stops
// answering (fatek-sim frozen with SIGSTOP, as a hung PLC or a cable pulled mid-frame) gets the
// write once; the reply says the outcome is unknown, never "failed"; a second reply with the same
// id and "final": true says what the read-back found once the PLC answers again; a command that
// waited past its age limit is not sent at all. Counted on the simulator: its own log of the
// requests it carried out, and its memory read after it resumed.
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaylink.h"
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/session/session.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#ifdef Q_OS_UNIX
#include <csignal>
#endif

#include <memory>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 15000; // QTRY timeouts: generous for a loaded 2-core machine under TSan

const char *const watchList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":200,"items":[{"address":"R50"},{"address":"R51"}]}]})json";

struct Replies
{
    QList<GatewayPayload::Reply> all;
    QList<GatewayPayload::Reply> of(const QString &id) const
    {
        QList<GatewayPayload::Reply> list;
        for (const auto &r : all)
            if (r.id == id)
                list.append(r);
        return list;
    }
};

} // namespace

class TestGatewayWrites : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void frozenPlcWriteIsUnknownThenFinal();

private:
    bool startSim();
    bool startGateway(int commandMaxAgeSec, int timeoutMs);
    int simWrites(const QString &address) const;
    std::optional<std::uint32_t> readFromSim(const char *address);

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<QProcess> m_sim;
    quint16 m_simPort = 0;
    QString m_simOutput;
    std::unique_ptr<GatewayLink> m_link;
};

void TestGatewayWrites::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly));
    list.write(watchList);
    list.close();
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QString error;
    QVERIFY2(m_broker->start(&error), qPrintable(error));
    QVERIFY(startSim());
}

void TestGatewayWrites::cleanup()
{
    m_link.reset();
    if (m_sim) {
#ifdef Q_OS_UNIX
        ::kill(static_cast<pid_t>(m_sim->processId()), SIGCONT);
#endif
        TestUtil::stopConsoleProgram(m_sim.get());
        m_sim->waitForFinished(Wait);
        m_sim.reset();
    }
    m_broker.reset();
    m_dir.reset();
}

bool TestGatewayWrites::startSim()
{
    m_sim = std::make_unique<QProcess>();
    m_simOutput.clear();
    connect(m_sim.get(), &QProcess::readyReadStandardOutput, this,
            [this] { m_simOutput += QString::fromUtf8(m_sim->readAllStandardOutput()); });
    TestUtil::startConsoleProgram(m_sim.get(), QStringLiteral(FATEK_SIM_PATH),
                                  {QStringLiteral("--tcp"), QStringLiteral("0"),
                                   QStringLiteral("--bind"), QStringLiteral("127.0.0.1"),
                                   QStringLiteral("--verbose")});
    const QRegularExpression listening(QStringLiteral("listening on tcp [^:]+:(\\d+)"));
    QDeadlineTimer deadline(Wait);
    while (!listening.match(m_simOutput).hasMatch() && !deadline.hasExpired())
        QTest::qWait(10);
    const auto match = listening.match(m_simOutput);
    if (!match.hasMatch()) {
        qWarning() << "fatek-sim did not listen:" << m_simOutput;
        return false;
    }
    m_simPort = static_cast<quint16>(match.captured(1).toUInt());
    return true;
}

bool TestGatewayWrites::startGateway(int commandMaxAgeSec, int timeoutMs)
{
    const QJsonObject json{
        {QStringLiteral("format"), QStringLiteral("fatek-gateway")},
        {QStringLiteral("version"), 1},
        {QStringLiteral("prefix"), QStringLiteral("fatek")},
        {QStringLiteral("broker"), QJsonObject{{QStringLiteral("url"), m_broker->url()}}},
        {QStringLiteral("connections"),
         QJsonArray{QJsonObject{
             {QStringLiteral("name"), QStringLiteral("line2")},
             {QStringLiteral("link"),
              QJsonObject{{QStringLiteral("kind"), QStringLiteral("tcp")},
                          {QStringLiteral("host"), QStringLiteral("127.0.0.1")},
                          {QStringLiteral("port"), m_simPort},
                          {QStringLiteral("protocol"), QStringLiteral("facon")},
                          {QStringLiteral("timeoutMs"), timeoutMs},
                          {QStringLiteral("retries"), 2}}},
             {QStringLiteral("watchLists"),
              QJsonArray{QJsonObject{{QStringLiteral("file"), QStringLiteral("line1.json")}}}},
             {QStringLiteral("allow"), QJsonArray{QStringLiteral("R50..R59")}},
             {QStringLiteral("commandMaxAgeSec"), commandMaxAgeSec}}}}};
    Result<GatewayConfig> config = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir->path());
    if (!config) {
        qWarning() << QString::fromStdString(config.error().text());
        return false;
    }
    m_link = std::make_unique<GatewayLink>(config->connections.at(0), config->prefix,
                                           config->broker, config->readOnly);
    Message error;
    if (!m_link->start(&error)) {
        qWarning() << QString::fromStdString(english(error));
        return false;
    }
    return true;
}

// Writes of `address` the simulator carried out ("... FACON write R50 = 3333 ...").
int TestGatewayWrites::simWrites(const QString &address) const
{
    const QRegularExpression write(QStringLiteral("write %1 ").arg(address));
    return static_cast<int>(m_simOutput.count(write));
}

std::optional<std::uint32_t> TestGatewayWrites::readFromSim(const char *address)
{
    LinkSettings settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_simPort,
                                              LinkSettings::ProtocolChoice::Facon);
    Session session(settings);
    session.open();
    QObject context;
    std::optional<std::uint32_t> value;
    bool done = false;
    session.submit(Request::readRegisters(1, addr(address), 1), &context,
                   [&](const SessionResult &r) {
                       done = true;
                       if (r.ok() && !r.response().values.empty())
                           value = r.response().values.front();
                   });
    QDeadlineTimer deadline(Wait);
    while (!done && !deadline.hasExpired())
        QTest::qWait(5);
    return value;
}

void TestGatewayWrites::frozenPlcWriteIsUnknownThenFinal()
{
#ifndef Q_OS_UNIX
    QSKIP("freezing the simulator (SIGSTOP) has no Windows counterpart");
#else
    // 8 s of age allowed: "a" may wait behind a poll that times out (2 s) and still goes.
    QVERIFY(startGateway(8, 2000));
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    MqttClient client(settings);
    Replies replies;
    connect(&client, &MqttClient::messageReceived, this,
            [&replies](const QString &topic, const QByteArray &payload, bool) {
                if (!topic.endsWith(QStringLiteral("/reply")))
                    return;
                if (auto r = GatewayPayload::decodeReply(payload))
                    replies.all.append(*r);
            });
    client.subscribe(QStringLiteral("fatek/line2/+/+/reply"), 1);
    QVERIFY(client.open());
    const QString status = GatewayTopics::status(QStringLiteral("fatek"), QStringLiteral("line2"));
    QTRY_VERIFY_WITH_TIMEOUT(m_simOutput.contains(QStringLiteral("read R50")), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(client.isConnected(), Wait);

    const auto pid = static_cast<pid_t>(m_sim->processId());
    QCOMPARE(::kill(pid, SIGSTOP), 0);
    const QString now = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    QVERIFY(client.publish(
        QStringLiteral("fatek/line2/1/R50/set"),
        QStringLiteral(R"({"value":3333,"time":"%1","id":"a"})").arg(now).toUtf8(), 1, false));
    // Sent 7.7 s ago by its own clock: 0.3 s left of the 8 s limit, and the line is busy with
    // "a" (2 s timeout) until long after that.
    const QString old = QDateTime::currentDateTimeUtc().addMSecs(-7700).toString(Qt::ISODateWithMs);
    QTest::qWait(100);
    QVERIFY(client.publish(
        QStringLiteral("fatek/line2/1/R51/set"),
        QStringLiteral(R"({"value":4444,"time":"%1","id":"b"})").arg(old).toUtf8(), 1, false));

    QTRY_VERIFY_WITH_TIMEOUT(!replies.of(QStringLiteral("a")).isEmpty(), Wait);
    const GatewayPayload::Reply first = replies.of(QStringLiteral("a")).first();
    QVERIFY2(first.outcome == ChangeOutcome::Unknown, english(first.error).c_str());
    QVERIFY(!first.final);
    QVERIFY(!first.ok);
    QVERIFY2(english(first.error).find("may have been carried out") != std::string::npos,
             english(first.error).c_str());
    QTRY_VERIFY_WITH_TIMEOUT(!replies.of(QStringLiteral("b")).isEmpty(), Wait);
    const GatewayPayload::Reply expired = replies.of(QStringLiteral("b")).first();
    QVERIFY2(expired.outcome == ChangeOutcome::Refused, english(expired.error).c_str());
    QVERIFY(expired.final);
    // Not sent: past its deadline in the queue (or, on a slow machine, already too old when it
    // arrived). Either way nothing reaches the PLC.
    QVERIFY2(expired.error.id == MsgId::SessionExpired
                 || expired.error.id == MsgId::GatewayWriteExpired,
             english(expired.error).c_str());

    QTest::qWait(500);
    QCOMPARE(::kill(pid, SIGCONT), 0);
    QTRY_COMPARE_WITH_TIMEOUT(replies.of(QStringLiteral("a")).size(), 2, Wait);
    const GatewayPayload::Reply final = replies.of(QStringLiteral("a")).last();
    QVERIFY(final.final);
    QCOMPARE(final.outcome, ChangeOutcome::Done);
    QVERIFY(final.ok);
    QCOMPARE(readFromSim("R50"), std::optional<std::uint32_t>(3333));
    QCOMPARE(readFromSim("R51"), std::optional<std::uint32_t>(0));
    // One frame, not one per retry; and "b" never reached the PLC.
    QTest::qWait(300);
    QCOMPARE(simWrites(QStringLiteral("R50")), 1);
    QCOMPARE(simWrites(QStringLiteral("R51")), 0);
    QCOMPARE(replies.of(QStringLiteral("a")).size(), 2);
    QCOMPARE(replies.of(QStringLiteral("b")).size(), 1);
    Q_UNUSED(status);
#endif
}

QTEST_GUILESS_MAIN(TestGatewayWrites)
#include "tst_gatewaywrites.moc"
