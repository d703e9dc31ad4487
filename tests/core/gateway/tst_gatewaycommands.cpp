// Issue 48: what a write command on the gateway must be before anything is sent to the PLC (its
// time, its value, its words, its keys) and that it is answered once. A GatewayLink between the
// in-process simulator and a real mosquitto, as tst_gateway; writes are counted on the
// simulator's side (its request log and memory), never the client's.
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaylink.h"
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "core/watch/watchmessages.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 10000; // QTRY timeouts: generous for a loaded 2-core machine

const char *const watchList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[{"address":"R100"},{"address":"R200","format":"float"},
   {"address":"R210","format":"float","allowNonFinite":true},{"address":"M10"}]}]})json";

} // namespace

class TestGatewayCommands : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void futureTimeIsRefused();
    void outageCountsWithTime();
    void nonFiniteFloatIsRefused();
    void valuesMustFitTheElement();
    void retainedCommandWhileAwayAnsweredOnce();

private:
    bool startLink(int maxAgeSec = 10, int brokerReconnectMs = 50);
    void publish(const char *address, const QByteArray &payload, bool retain = false);
    // The replies on <address>/reply, oldest first.
    QList<GatewayPayload::Reply> replies(const char *address) const;
    // The last reply on <address>/reply, once there are `count` (nullopt after Wait).
    std::optional<GatewayPayload::Reply> awaitReply(const char *address, int count = 1) const;
    // Publishes a command and waits for its reply (the next one on its reply topic).
    std::optional<GatewayPayload::Reply> send(const char *address, const QByteArray &payload);
    QString topic(const char *address) const
    {
        return GatewayTopics::item(QStringLiteral("fatek"), QStringLiteral("line1"), 1,
                                   addr(address));
    }
    // Write requests the simulator executed, from its own log.
    int simWrites() const
    {
        return static_cast<int>(m_simLog.filter(QStringLiteral(" write ")).size());
    }
    std::optional<std::uint32_t> plc(const char *address) const
    {
        return m_plc->value(addr(address));
    }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<MqttClient> m_client; // the command sender, subscribed to fatek/#
    std::unique_ptr<GatewayLink> m_link;
    QStringList m_simLog;
    QHash<QString, QList<QByteArray>> m_replies;
};

void TestGatewayCommands::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly));
    list.write(watchList);
    list.close();
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setValue(addr("R100"), 1234);
    m_server = std::make_unique<SimServer>(m_plc.get());
    m_server->setVerbose(true);
    m_simLog.clear();
    m_replies.clear();
    connect(m_server.get(), &SimServer::logLine, this,
            [this](const QString &line) { m_simLog.append(line); });
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QVERIFY2(m_broker->start(&error), qPrintable(error));

    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 500;
    m_client = std::make_unique<MqttClient>(settings);
    connect(m_client.get(), &MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) {
                if (topic.endsWith(QStringLiteral("/reply")))
                    m_replies[topic].append(payload);
            });
    m_client->subscribe(QStringLiteral("fatek/#"), 1);
    QVERIFY(m_client->open());
    QTRY_VERIFY_WITH_TIMEOUT(m_client->isConnected(), Wait);
}

void TestGatewayCommands::cleanup()
{
    m_link.reset();
    m_client.reset();
    m_broker.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

bool TestGatewayCommands::startLink(int maxAgeSec, int brokerReconnectMs)
{
    const QByteArray json
        = QStringLiteral(R"({"format":"fatek-gateway","version":1,"prefix":"fatek",
          "broker":{"url":"%1"},"connections":[{"name":"line1","commandMaxAgeSec":%2,
          "link":{"kind":"tcp","host":"127.0.0.1","port":%3,"timeoutMs":500,"retries":0},
          "watchLists":[{"file":"line1.json"}],"allow":["R100..R299","M0..M20","Y0..Y7"]}]})")
              .arg(m_broker->url())
              .arg(maxAgeSec)
              .arg(m_server->tcpPort())
              .toUtf8();
    Result<GatewayConfig> config = GatewayConfig::load(json, m_dir->path());
    if (!config) {
        qWarning() << QString::fromStdString(config.error().text());
        return false;
    }
    config.value().broker.reconnectMinMs = brokerReconnectMs;
    config.value().broker.reconnectMaxMs = brokerReconnectMs;
    m_link = std::make_unique<GatewayLink>(config->connections.at(0), config->prefix,
                                           config->broker, config->readOnly);
    Message error;
    if (!m_link->start(&error)) {
        qWarning() << QString::fromStdString(english(error));
        return false;
    }
    // Up on both sides: the PLC link polled once (R100 published) and the broker took it.
    const QString item = topic("R100");
    auto client = m_client.get();
    QObject guard;
    bool seen = false;
    connect(client, &MqttClient::messageReceived, &guard,
            [&seen, item](const QString &t) { seen = seen || t == item; });
    return QTest::qWaitFor([&] { return seen && m_link->statistics().published > 0; }, Wait);
}

void TestGatewayCommands::publish(const char *address, const QByteArray &payload, bool retain)
{
    QVERIFY(m_client->publish(topic(address) + QStringLiteral("/set"), payload, 1, retain));
}

QList<GatewayPayload::Reply> TestGatewayCommands::replies(const char *address) const
{
    QList<GatewayPayload::Reply> list;
    for (const QByteArray &payload : m_replies.value(topic(address) + QStringLiteral("/reply"))) {
        if (const auto reply = GatewayPayload::decodeReply(payload))
            list.append(*reply);
    }
    return list;
}

std::optional<GatewayPayload::Reply> TestGatewayCommands::awaitReply(const char *address,
                                                                     int count) const
{
    if (!QTest::qWaitFor([&] { return replies(address).size() >= count; }, Wait))
        return std::nullopt;
    return replies(address).last();
}

std::optional<GatewayPayload::Reply> TestGatewayCommands::send(const char *address,
                                                               const QByteArray &payload)
{
    const auto before = static_cast<int>(replies(address).size());
    if (!m_client->publish(topic(address) + QStringLiteral("/set"), payload, 1, false))
        return std::nullopt;
    return awaitReply(address, before + 1);
}

void TestGatewayCommands::futureTimeIsRefused()
{
    // Case 5: a time in 2099 was taken as "not old" and carried out, the gateway running or not.
    QVERIFY(startLink());
    auto reply = send("R100", R"({"value":14,"id":"f1","time":"2099-01-01T00:00:00.000Z"})");
    QVERIFY(reply);
    QVERIFY(!reply->ok);
    QCOMPARE(reply->id, QStringLiteral("f1"));
    QCOMPARE(reply->error.id, MsgId::GatewayWriteFuture);
    // A clock a little ahead (within GatewayLink::MaxAheadSec) is a clock, not a wrong time.
    const QByteArray ahead
        = QDateTime::currentDateTimeUtc().addSecs(3).toString(Qt::ISODateWithMs).toUtf8();
    reply = send("R101", R"({"value":15,"id":"f2","time":")" + ahead + R"("})");
    QVERIFY(reply);
    QVERIFY2(reply->ok, english(reply->error).c_str());
    QCOMPARE(plc("R101"), std::optional<std::uint32_t>(15));

    // Published while the gateway is stopped, answered when it is back: still refused.
    m_link.reset();
    publish("R100", R"({"value":16,"id":"f3","time":"2099-01-01T00:00:00.000Z"})");
    QTest::qWait(300); // at the broker, not at the gateway
    QVERIFY(startLink());
    reply = awaitReply("R100", 2);
    QVERIFY(reply);
    QCOMPARE(reply->id, QStringLiteral("f3"));
    QCOMPARE(reply->error.id, MsgId::GatewayWriteFuture);
    QCOMPARE(plc("R100"), std::optional<std::uint32_t>(1234));
    QCOMPARE(simWrites(), 1); // R101's only
}

void TestGatewayCommands::outageCountsWithTime()
{
    // Case 5: the gateway's own measure of how long a command may have waited at the broker (its
    // outage) counts whether or not the command has a time: a time is the sender's word. The
    // gateway loses the broker while the broker runs (another client takes its session over)
    // and comes back 3..5 s later (its backoff), past commandMaxAgeSec = 2; the command's time
    // says it is fresh when it arrives.
    QVERIFY(startLink(2, 4000));
    MqttBrokerSettings impostor = *MqttBrokerSettings::fromUrl(m_broker->url());
    impostor.clientId = QStringLiteral("fatek-gateway-fatek-line1");
    impostor.cleanSession = false;
    {
        MqttClient takeover(impostor);
        QVERIFY(takeover.open());
        QTRY_VERIFY_WITH_TIMEOUT(takeover.isConnected(), Wait);
        takeover.close();
    }
    const QByteArray time
        = QDateTime::currentDateTimeUtc().addSecs(4).toString(Qt::ISODateWithMs).toUtf8();
    const auto reply = send("R102", R"({"value":"7","id":"o1","time":")" + time + R"("})");
    QVERIFY(reply);
    QVERIFY(!reply->ok);
    QCOMPARE(reply->error.id, MsgId::GatewayWriteWaited);
    QCOMPARE(plc("R102"), std::optional<std::uint32_t>(0));
    QCOMPARE(simWrites(), 0);
}

void TestGatewayCommands::nonFiniteFloatIsRefused()
{
    // Case 6: NaN and infinities reached a float register (ok:true) while 1e39 was refused.
    QVERIFY(startLink());
    struct Case
    {
        const char *address;
        QByteArray payload;
    };
    const QList<Case> cases{
        {"R200", R"({"value":"inf","id":"a"})"},
        {"R202", R"({"value":"nan","format":"float","id":"b"})"},
        {"R204", R"({"value":"-inf","format":"float","id":"c"})"},
        {"R200", "-Infinity"},
        // +inf as the raw words the studio sends (R200 watched as float).
        {"R200", R"({"words":[0,32640],"id":"d"})"},
        {"R220", R"({"value":"nan","format":"double","id":"e"})"},
    };
    for (const Case &c : cases) {
        const auto reply = send(c.address, c.payload);
        QVERIFY2(reply && !reply->ok, c.payload.constData());
        QCOMPARE(reply->error.id, MsgId::ValueNotFinite);
    }
    // The item that allows it (watch list "allowNonFinite") takes NaN.
    const auto reply = send("R210", R"({"value":"nan","id":"n"})");
    QVERIFY(reply);
    QVERIFY2(reply->ok, english(reply->error).c_str());
    QCOMPARE(plc("R211"), std::optional<std::uint32_t>(0x7FC0));
    QCOMPARE(simWrites(), 1);
    for (const char *address : {"R200", "R201", "R202", "R203", "R204", "R205", "R220", "R223"})
        QCOMPARE(plc(address), std::optional<std::uint32_t>(0));
}

void TestGatewayCommands::valuesMustFitTheElement()
{
    // Case 7: words cut to the element's bits, signed ranges, duplicate keys, an object id.
    QVERIFY(startLink());
    struct Case
    {
        const char *address;
        QByteArray payload;
        const char *error; // the reply's error in English
    };
    const QList<Case> cases{
        {"R100", R"({"words":[70000],"id":"w"})",
         "R100: 70000 does not fit a 16-bit register (0..65535)"},
        {"M10", R"({"words":[2]})", "M10: 2 does not fit a bit (0..1)"},
        {"Y4", R"({"words":[1000]})", "Y4: 1000 does not fit a bit (0..1)"},
        {"R103", "32768", "32768 does not fit a 16-bit register (-32768..32767)"},
        {"R104", R"({"value":"-0x1","format":"unsigned"})",
         "-0x1 does not fit a 16-bit register (0..65535)"},
        {"R105", R"({"value":1,"value":100})", "line 1: duplicate key \"value\""},
        {"R106", R"({"value":1,"id":{"a":1}})", "\"id\" must be text or a number."},
    };
    for (const Case &c : cases) {
        const auto reply = send(c.address, c.payload);
        QVERIFY2(reply && !reply->ok, c.payload.constData());
        QCOMPARE(QString::fromStdString(english(reply->error)), QString::fromUtf8(c.error));
    }
    QCOMPARE(replies("R100").first().id, QStringLiteral("w"));
    // What fits goes through: the words as they are, a number id given back as text.
    const auto reply = send("R107", R"({"words":[65535],"id":7})");
    QVERIFY(reply);
    QVERIFY2(reply->ok, english(reply->error).c_str());
    QCOMPARE(reply->id, QStringLiteral("7"));
    QCOMPARE(reply->value, QStringLiteral("-1"));
    QCOMPARE(plc("R107"), std::optional<std::uint32_t>(0xFFFF));
    QCOMPARE(simWrites(), 1);
    QCOMPARE(plc("R100"), std::optional<std::uint32_t>(1234));
    QCOMPARE(plc("M10"), std::optional<std::uint32_t>(0));
    QCOMPARE(plc("Y4"), std::optional<std::uint32_t>(0));
}

void TestGatewayCommands::retainedCommandWhileAwayAnsweredOnce()
{
    // Case 8: a retained command sent while the gateway was away came twice (queued for its
    // session, then as the retained copy at its subscription) and got two replies.
    QVERIFY(startLink());
    m_link.reset();
    const QByteArray now = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toUtf8();
    publish("R108", R"({"value":"5","id":"r","time":")" + now + R"("})", true);
    QTest::qWait(300); // at the broker, not at the gateway
    QVERIFY(startLink());
    const auto reply = awaitReply("R108");
    QVERIFY(reply);
    QCOMPARE(reply->id, QStringLiteral("r"));
    QTest::qWait(1500); // a second reply would come meanwhile
    QCOMPARE(replies("R108").size(), 1);
    QCOMPARE(simWrites(), reply->ok ? 1 : 0);
}

QTEST_GUILESS_MAIN(TestGatewayCommands)
#include "tst_gatewaycommands.moc"
