// Issue 50: the gateway's alarms with a real mosquitto and the in-process simulator. A high alarm
// on R100 is raised by a value written into the simulator; its state (retained) and its event go
// out; an acknowledgement sent by a real mosquitto_pub process is answered once and journaled; a
// new Gateway on the same journal publishes the alarm still active and unacknowledged (the same
// raise, not a new one); Home Assistant gets a binary_sensor; a reload that removes the alarm
// clears its topics. The gateway runs read-only: acknowledging is not writing.
#include "core/alarm/alarmjournal.h"
#include "core/gateway/gateway.h"
#include "core/gateway/gatewayconfig.h"
#include "core/mqtt/mqttclient.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace Fatek;
using TestUtil::addr;

namespace {

constexpr int Wait = 10000; // QTRY timeouts: generous for a loaded 2-core machine

const QString AlarmTopic = QStringLiteral("fatek/line1/alarms/1-R100-high");
const QString EventsTopic = QStringLiteral("fatek/line1/alarms/events");
const QString ReplyTopic = AlarmTopic + QStringLiteral("/reply");
const QString DiscoveryTopic
    = QStringLiteral("homeassistant/binary_sensor/fatek_line1/alarm_1-R100-high/config");

const char *const alarmedList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[
   {"address":"R100","name":"Tank level","alarms":[{"type":"high","limit":1000,
     "priority":"high","message":"Tank level too high","group":"tanks"}]},
   {"address":"R101"}]}]})json";
const char *const plainList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[{"address":"R100"},{"address":"R101"}]}]})json";

QJsonObject objectOf(const QByteArray &payload)
{
    return QJsonDocument::fromJson(payload).object();
}

} // namespace

class TestGatewayAlarms : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void raiseAcknowledgeRestart();

private:
    void writeList(const char *json);
    std::optional<GatewayConfig> config() const;
    bool startGateway();
    bool stopGateway();
    // The payloads received on `topic`, oldest first.
    QList<QByteArray> received(const QString &topic) const { return m_messages.value(topic); }
    // The events of the alarm of `type` ("raised", "acknowledged") received so far.
    QList<QJsonObject> events(const QString &type) const;
    // Publishes with the real mosquitto_pub (QoS 1, not retained).
    bool mosquittoPub(const QString &topic, const QByteArray &payload);
    QString journalPath() const { return m_dir->filePath(QStringLiteral("journal.db")); }

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<MqttClient> m_client; // subscribed to everything
    std::unique_ptr<Gateway> m_gateway;
    QStringList m_log;
    QHash<QString, QList<QByteArray>> m_messages;
};

void TestGatewayAlarms::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    writeList(alarmedList);
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setValue(addr("R100"), 500);
    m_server = std::make_unique<SimServer>(m_plc.get());
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
                m_messages[topic].append(payload);
            });
    m_client->subscribe(QStringLiteral("#"), 1);
    QVERIFY(m_client->open());
    QTRY_VERIFY_WITH_TIMEOUT(m_client->isConnected(), Wait);
}

void TestGatewayAlarms::cleanup()
{
    if (m_gateway)
        stopGateway();
    m_gateway.reset();
    m_client.reset();
    m_broker.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

void TestGatewayAlarms::writeList(const char *json)
{
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly | QIODevice::Truncate));
    list.write(json);
}

std::optional<GatewayConfig> TestGatewayAlarms::config() const
{
    const QByteArray json
        = QStringLiteral(R"({"format":"fatek-gateway","version":1,"prefix":"fatek",
          "readOnly":true,"alarmJournal":"journal.db","broker":{"url":"%1"},
          "homeAssistant":{"discovery":true},
          "connections":[{"name":"line1",
          "link":{"kind":"tcp","host":"127.0.0.1","port":%2,"timeoutMs":500,"retries":0},
          "watchLists":[{"file":"line1.json"}]}]})")
              .arg(m_broker->url())
              .arg(m_server->tcpPort())
              .toUtf8();
    Result<GatewayConfig> loaded = GatewayConfig::load(json, m_dir->path());
    if (!loaded) {
        qWarning() << QString::fromStdString(loaded.error().text());
        return std::nullopt;
    }
    loaded.value().broker.reconnectMinMs = 50;
    loaded.value().broker.reconnectMaxMs = 500;
    return std::move(loaded).value();
}

bool TestGatewayAlarms::startGateway()
{
    const std::optional<GatewayConfig> c = config();
    if (!c)
        return false;
    m_gateway = std::make_unique<Gateway>();
    connect(m_gateway.get(), &Gateway::logEvent, this,
            [this](const QString &connection, const Message &event) {
                m_log.append(connection + QStringLiteral(": ")
                             + QString::fromStdString(english(event)));
            });
    QString failed;
    Message error;
    if (!m_gateway->start(*c, &failed, &error)) {
        qWarning() << failed << QString::fromStdString(english(error));
        return false;
    }
    return true;
}

bool TestGatewayAlarms::stopGateway()
{
    bool stopped = false;
    connect(m_gateway.get(), &Gateway::stopped, this, [&stopped] { stopped = true; });
    m_gateway->stop();
    const bool done = QTest::qWaitFor([&] { return stopped; }, Wait);
    m_gateway.reset();
    return done;
}

QList<QJsonObject> TestGatewayAlarms::events(const QString &type) const
{
    QList<QJsonObject> list;
    for (const QByteArray &payload : received(EventsTopic)) {
        const QJsonObject event = objectOf(payload);
        if (event.value(QStringLiteral("event")).toString() == type)
            list.append(event);
    }
    return list;
}

bool TestGatewayAlarms::mosquittoPub(const QString &topic, const QByteArray &payload)
{
    const QString program = QStandardPaths::findExecutable(QStringLiteral("mosquitto_pub"));
    if (program.isEmpty()) {
        qWarning() << "mosquitto_pub is not installed (Debian: mosquitto-clients)";
        return false;
    }
    QProcess pub;
    pub.start(program,
              {QStringLiteral("-h"), QStringLiteral("127.0.0.1"), QStringLiteral("-p"),
               QString::number(m_broker->port()), QStringLiteral("-q"), QStringLiteral("1"),
               QStringLiteral("-t"), topic, QStringLiteral("-m"), QString::fromUtf8(payload)});
    if (!pub.waitForFinished(Wait) || pub.exitCode() != 0) {
        qWarning() << "mosquitto_pub:" << pub.readAllStandardError();
        return false;
    }
    return true;
}

void TestGatewayAlarms::raiseAcknowledgeRestart()
{
    QVERIFY(startGateway());
    // Normal while R100 is 500, published retained at start.
    QTRY_VERIFY_WITH_TIMEOUT(!received(AlarmTopic).isEmpty(), Wait);
    QJsonObject state = objectOf(received(AlarmTopic).last());
    QCOMPARE(state.value(QStringLiteral("state")).toString(), QStringLiteral("normal"));
    QCOMPARE(state.value(QStringLiteral("priority")).toString(), QStringLiteral("high"));
    QCOMPARE(state.value(QStringLiteral("kind")).toString(), QStringLiteral("high"));
    QCOMPARE(state.value(QStringLiteral("address")).toString(), QStringLiteral("R100"));
    QCOMPARE(state.value(QStringLiteral("item")).toString(), QStringLiteral("Tank level"));
    QCOMPARE(state.value(QStringLiteral("group")).toString(), QStringLiteral("tanks"));

    // Home Assistant: a binary sensor on the alarm's state topic.
    QTRY_VERIFY_WITH_TIMEOUT(!received(DiscoveryTopic).isEmpty(), Wait);
    const QJsonObject discovery = objectOf(received(DiscoveryTopic).last());
    QCOMPARE(discovery.value(QStringLiteral("state_topic")).toString(), AlarmTopic);
    QCOMPARE(discovery.value(QStringLiteral("device_class")).toString(), QStringLiteral("problem"));
    QCOMPARE(discovery.value(QStringLiteral("name")).toString(),
             QStringLiteral("Tank level too high"));

    // Over the limit in the PLC: raised, the event and the state.
    m_plc->setValue(addr("R100"), 1500);
    QTRY_COMPARE_WITH_TIMEOUT(events(QStringLiteral("raised")).size(), 1, Wait);
    const QJsonObject raised = events(QStringLiteral("raised")).first();
    QCOMPARE(raised.value(QStringLiteral("id")).toString(), QStringLiteral("1-R100-high"));
    QCOMPARE(raised.value(QStringLiteral("state")).toString(), QStringLiteral("activeUnacked"));
    QCOMPARE(raised.value(QStringLiteral("value")).toString(), QStringLiteral("1500"));
    QTRY_COMPARE_WITH_TIMEOUT(
        objectOf(received(AlarmTopic).last()).value(QStringLiteral("state")).toString(),
        QStringLiteral("activeUnacked"), Wait);
    state = objectOf(received(AlarmTopic).last());
    QVERIFY(state.value(QStringLiteral("conditionActive")).toBool());
    const QString raisedAt = state.value(QStringLiteral("raised")).toString();
    QVERIFY(!raisedAt.isEmpty());
    QVERIFY2(m_log.join(u'\n').contains(QStringLiteral("alarm 1-R100-high raised")),
             qPrintable(m_log.join(u'\n')));

    // Restarted on the same journal: still active and unacknowledged, the same raise. The
    // broker's retained copy is cleared first, so that what comes is the new gateway's.
    QVERIFY(stopGateway());
    QVERIFY(m_client->publish(AlarmTopic, {}, 1, true));
    QTRY_VERIFY_WITH_TIMEOUT(received(AlarmTopic).last().isEmpty(), Wait);
    QVERIFY(startGateway());
    QTRY_VERIFY_WITH_TIMEOUT(!received(AlarmTopic).last().isEmpty(), Wait);
    state = objectOf(received(AlarmTopic).last());
    QCOMPARE(state.value(QStringLiteral("state")).toString(), QStringLiteral("activeUnacked"));
    QCOMPARE(state.value(QStringLiteral("raised")).toString(), raisedAt);
    QTest::qWait(500); // polls of the new run: no new raise
    QCOMPARE(events(QStringLiteral("raised")).size(), 1);

    // Acknowledged by a real mosquitto_pub in read-only mode: one reply, the event, the state.
    QVERIFY(mosquittoPub(AlarmTopic + QStringLiteral("/ack"),
                         R"({"id":"k1","user":"anna","comment":"valve closed"})"));
    QTRY_COMPARE_WITH_TIMEOUT(received(ReplyTopic).size(), 1, Wait);
    const QJsonObject reply = objectOf(received(ReplyTopic).first());
    QVERIFY2(reply.value(QStringLiteral("ok")).toBool(), received(ReplyTopic).first().constData());
    QCOMPARE(reply.value(QStringLiteral("id")).toString(), QStringLiteral("k1"));
    QCOMPARE(reply.value(QStringLiteral("state")).toString(), QStringLiteral("activeAcked"));
    QTRY_COMPARE_WITH_TIMEOUT(events(QStringLiteral("acknowledged")).size(), 1, Wait);
    QCOMPARE(
        events(QStringLiteral("acknowledged")).first().value(QStringLiteral("user")).toString(),
        QStringLiteral("anna"));
    QTRY_COMPARE_WITH_TIMEOUT(
        objectOf(received(AlarmTopic).last()).value(QStringLiteral("state")).toString(),
        QStringLiteral("activeAcked"), Wait);
    QTest::qWait(300);
    QCOMPARE(received(ReplyTopic).size(), 1); // answered once

    // Refused with the reason: an unknown key, an alarm this connection does not have.
    QVERIFY(mosquittoPub(AlarmTopic + QStringLiteral("/ack"), R"({"id":"k2","coment":"x"})"));
    QTRY_COMPARE_WITH_TIMEOUT(received(ReplyTopic).size(), 2, Wait);
    QJsonObject refused = objectOf(received(ReplyTopic).last());
    QVERIFY(!refused.value(QStringLiteral("ok")).toBool());
    QCOMPARE(
        refused.value(QStringLiteral("error")).toObject().value(QStringLiteral("id")).toString(),
        QStringLiteral("GatewayAlarmUnknownKey"));
    const QString otherReply = QStringLiteral("fatek/line1/alarms/1-R999-high/reply");
    QVERIFY(mosquittoPub(QStringLiteral("fatek/line1/alarms/1-R999-high/ack"), "PRESS"));
    QTRY_COMPARE_WITH_TIMEOUT(received(otherReply).size(), 1, Wait);
    refused = objectOf(received(otherReply).first());
    QCOMPARE(
        refused.value(QStringLiteral("error")).toObject().value(QStringLiteral("id")).toString(),
        QStringLiteral("GatewayAlarmUnknown"));

    // Journaled: the raise and the acknowledgement with who and why.
    const auto journaled = [this](AlarmEventType type) -> std::optional<AlarmEvent> {
        Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::openReadOnly(journalPath());
        if (!journal)
            return std::nullopt;
        const Result<QList<AlarmEvent>> all
            = journal.value()->events(0, std::numeric_limits<qint64>::max());
        if (!all)
            return std::nullopt;
        for (const AlarmEvent &event : *all) {
            if (event.type == type)
                return event;
        }
        return std::nullopt;
    };
    QTRY_VERIFY_WITH_TIMEOUT(journaled(AlarmEventType::Acknowledged).has_value(), Wait);
    const AlarmEvent ack = *journaled(AlarmEventType::Acknowledged);
    QCOMPARE(ack.connection, QStringLiteral("line1"));
    QCOMPARE(ack.alarmId, QStringLiteral("1-R100-high"));
    QCOMPARE(ack.user, QStringLiteral("anna"));
    QCOMPARE(ack.comment, QStringLiteral("valve closed"));
    QVERIFY(journaled(AlarmEventType::Raised).has_value());
    QVERIFY2(m_log.join(u'\n').contains(QStringLiteral("alarm 1-R100-high acknowledged by anna")),
             qPrintable(m_log.join(u'\n')));

    // A reload that removes the alarm clears its state and its Home Assistant entity.
    writeList(plainList);
    const std::optional<GatewayConfig> reloaded = config();
    QVERIFY(reloaded);
    bool done = false;
    connect(m_gateway.get(), &Gateway::reloaded, this, [&done] { done = true; });
    m_gateway->reload(*reloaded);
    QTRY_VERIFY_WITH_TIMEOUT(done, Wait);
    QTRY_VERIFY_WITH_TIMEOUT(received(AlarmTopic).last().isEmpty(), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(received(DiscoveryTopic).last().isEmpty(), Wait);
}

QTEST_GUILESS_MAIN(TestGatewayAlarms)
#include "tst_gatewayalarms.moc"
