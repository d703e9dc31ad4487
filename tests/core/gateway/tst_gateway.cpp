// The MQTT gateway end to end (issue 20): a GatewayLink between the in-process simulator and a
// real mosquitto on a free port; the fatek-gateway executable for the last will and a clean stop.
// Writes are counted on the simulator's side (its request log and memory), never the client's.
#include "core/gateway/delayhistogram.h"
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaylink.h"
#include "core/gateway/gatewaypublisher.h"
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/protocol/logtext.h"
#include "core/session/session.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#ifdef Q_OS_UNIX
#include <csignal>
#endif
#ifdef Q_OS_LINUX
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#endif
#include <cstring>
#include <memory>

using namespace Fatek;
using GatewayPayload::LinkStatus;
using TestUtil::addr;
using TestUtil::floatBits;

namespace {

constexpr int Wait = 10000; // QTRY timeouts: generous for a loaded 2-core machine under TSan

const char *const watchList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[{"address":"R100","name":"Speed"},
   {"address":"R200","format":"float"},{"address":"Y0"},{"address":"R300"},{"address":"DR10"}]}]})json";
const char *const configTemplate = R"json({"format":"fatek-gateway","version":1,
  "prefix":"fatek","connections":[{"name":"line1","link":{"kind":"tcp","host":"127.0.0.1",
  "protocol":"facon","timeoutMs":500,"retries":0},"watchLists":[{"file":"line1.json"}],
  "allow":["R100..R199","Y0..Y7"],"statisticsIntervalMs":300}]})json";

// Every message a subscriber got, in order, and the last one per topic.
struct Inbox
{
    struct Entry
    {
        QString topic;
        QByteArray payload;
        bool retained = false;
    };
    QList<Entry> all;
    QHash<QString, Entry> last;

    void attach(MqttClient *client)
    {
        QObject::connect(client, &MqttClient::messageReceived,
                         [this](const QString &topic, const QByteArray &payload, bool retained) {
                             all.append({topic, payload, retained});
                             last.insert(topic, {topic, payload, retained});
                         });
    }
    std::optional<GatewayPayload::ItemValue> item(const QString &topic) const
    {
        return last.contains(topic) ? GatewayPayload::decodeItem(last.value(topic).payload)
                                    : std::nullopt;
    }
    std::optional<LinkStatus> status(const QString &topic) const
    {
        if (!last.contains(topic))
            return std::nullopt;
        const auto s = GatewayPayload::decodeStatus(last.value(topic).payload);
        return s ? std::optional<LinkStatus>(s->state) : std::nullopt;
    }
    std::optional<GatewayPayload::Reply> reply(const QString &topic) const
    {
        return last.contains(topic) ? GatewayPayload::decodeReply(last.value(topic).payload)
                                    : std::nullopt;
    }
};

// The fatek-gateway executable on a configuration file, stopped as a user would (SIGTERM) when
// it goes out of scope.
class GatewayProcess
{
public:
    explicit GatewayProcess(const QString &configPath, const QProcessEnvironment &environment
                                                       = QProcessEnvironment::systemEnvironment())
    {
        process.setProcessEnvironment(environment);
        TestUtil::startConsoleProgram(&process, QStringLiteral(FATEK_GATEWAY_PATH), {configPath});
    }
    ~GatewayProcess()
    {
        if (process.state() == QProcess::NotRunning)
            return;
        TestUtil::stopConsoleProgram(&process);
        process.waitForFinished(Wait);
    }
#ifdef Q_OS_UNIX
    // SIGHUP: read the configuration file again.
    bool reload() const
    {
        return ::kill(static_cast<pid_t>(process.processId()), SIGHUP) == 0;
    }
#endif

    QProcess process;
};

} // namespace

class TestGateway : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void valuesArriveRetained();
    void allowlistedWriteReachesPlc();
    void refusedWritesReachNothing();
    void readOnlyRefusesEverything();
    void brokerRestartRepublishes();
    void publisherBoundsWhileBrokerAway();
    void plcRestartGoesStaleThenGood();
    void neverReadItemsHaveNoValue();
    void silentStationIsDemoted();
    void commandsWhileAwayAreAnswered();
    void oldCommandIsRefused();
    void commandOnNoItemIsAnswered();
    void stalledBrokerKeepsNewestPerItem();
    void delayHistogramPercentiles();
    void logTextEscapesControls();
    void executableWillAndCleanStop();
    void sighupReloadsChangedLinksOnly();
    void systemdNotifyReadyAndWatchdog();
    void homeAssistantDiscovery();
    void statusOnceEachAtStart();

private:
    QByteArray configJson(bool readOnly, int keepAliveSec = 30) const;
    // configJson's connection line1 once per name, all to the same simulator.
    QByteArray configJsonOf(const QStringList &connections) const;
    void writeFile(const QString &path, const QByteArray &content);
    bool startGateway(bool readOnly);
    std::unique_ptr<MqttClient> subscriber(Inbox *inbox);
    QString topic(const char *address, int station = 1) const
    {
        return GatewayTopics::item(QStringLiteral("fatek"), QStringLiteral("line1"), station,
                                   addr(address));
    }
    QString statusTopic() const
    {
        return GatewayTopics::status(QStringLiteral("fatek"), QStringLiteral("line1"));
    }
    int simWrites() const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<GatewayLink> m_link;
    QStringList m_simLog;
    QStringList m_gatewayLog;
    quint16 m_plcPort = 0; // the PLC's port while the simulator is closed (else its own)
};

void TestGateway::init()
{
    m_plcPort = 0;
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly));
    list.write(watchList);
    list.close();
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setValue(addr("R100"), 1234);
    const std::uint32_t bits = floatBits(12.5F);
    m_plc->setValue(addr("R200"), bits & 0xFFFF); // low word first
    m_plc->setValue(addr("R201"), bits >> 16);
    m_plc->setValue(addr("Y0"), 1);
    m_plc->setValue(addr("DR10"), 50);
    m_server = std::make_unique<SimServer>(m_plc.get());
    m_server->setVerbose(true);
    m_simLog.clear();
    m_gatewayLog.clear();
    connect(m_server.get(), &SimServer::logLine, this,
            [this](const QString &line) { m_simLog.append(line); });
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QVERIFY2(m_broker->start(&error), qPrintable(error));
}

void TestGateway::cleanup()
{
    m_link.reset();
    m_broker.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

QByteArray TestGateway::configJson(bool readOnly, int keepAliveSec) const
{
    QJsonObject json = QJsonDocument::fromJson(configTemplate).object();
    json.insert(QStringLiteral("broker"),
                QJsonObject{{QStringLiteral("url"), m_broker->url()},
                            {QStringLiteral("keepAliveSec"), keepAliveSec}});
    json.insert(QStringLiteral("readOnly"), readOnly);
    QJsonObject connection = json.value(QStringLiteral("connections")).toArray().at(0).toObject();
    QJsonObject link = connection.value(QStringLiteral("link")).toObject();
    link.insert(QStringLiteral("port"), m_plcPort != 0 ? m_plcPort : m_server->tcpPort());
    connection.insert(QStringLiteral("link"), link);
    json.insert(QStringLiteral("connections"), QJsonArray{connection});
    return QJsonDocument(json).toJson();
}

QByteArray TestGateway::configJsonOf(const QStringList &connections) const
{
    QJsonObject json = QJsonDocument::fromJson(configJson(false)).object();
    const QJsonObject line1 = json.value(QStringLiteral("connections")).toArray().at(0).toObject();
    QJsonArray list;
    for (const QString &name : connections) {
        QJsonObject connection = line1;
        connection.insert(QStringLiteral("name"), name);
        list.append(connection);
    }
    json.insert(QStringLiteral("connections"), list);
    return QJsonDocument(json).toJson();
}

void TestGateway::writeFile(const QString &path, const QByteArray &content)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(file.write(content), content.size());
}

bool TestGateway::startGateway(bool readOnly)
{
    Result<GatewayConfig> config = GatewayConfig::load(configJson(readOnly), m_dir->path());
    if (!config) {
        qWarning() << QString::fromStdString(config.error().text());
        return false;
    }
    // Quick reconnects on both sides: the test waits for them.
    config.value().broker.reconnectMinMs = 50;
    config.value().broker.reconnectMaxMs = 500;
    GatewayConnectionConfig connection = config->connections.at(0);
    connection.link.reconnectMinMs = 50;
    connection.link.reconnectMaxMs = 500;
    m_link = std::make_unique<GatewayLink>(connection, config->prefix, config->broker,
                                           config->readOnly);
    connect(m_link.get(), &GatewayLink::logEvent, this, [this](const Message &event) {
        m_gatewayLog.append(QString::fromStdString(english(event)));
    });
    Message error;
    if (!m_link->start(&error)) {
        qWarning() << QString::fromStdString(english(error));
        return false;
    }
    return true;
}

std::unique_ptr<MqttClient> TestGateway::subscriber(Inbox *inbox)
{
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 500;
    auto client = std::make_unique<MqttClient>(settings);
    inbox->attach(client.get());
    client->subscribe(QStringLiteral("fatek/#"), 1);
    if (!client->open())
        return nullptr;
    return client;
}

// Write requests the simulator executed, from its own log ("[tcp ...] FACON write R100 = ...").
int TestGateway::simWrites() const
{
    return static_cast<int>(m_simLog.filter(QStringLiteral(" write ")).size());
}

void TestGateway::valuesArriveRetained()
{
    QVERIFY(startGateway(false));
    Inbox early;
    const std::unique_ptr<MqttClient> earlyClient = subscriber(&early);
    QVERIFY(earlyClient);
    QTRY_COMPARE_WITH_TIMEOUT(early.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    // Every item came through the broker, so the broker holds them all (it stores a retained
    // message before it forwards it).
    QTRY_VERIFY_WITH_TIMEOUT(early.item(topic("R100")) && early.item(topic("R200"))
                                 && early.item(topic("Y0")) && early.item(topic("R300"))
                                 && early.item(topic("DR10")),
                             Wait);
    // The link's frames were counted, none kept: nothing reads a gateway's traffic log.
    QVERIFY(m_link->session()->trafficLog()->lastSequence() > 0);
    QCOMPARE(m_link->session()->trafficLog()->size(), 0);
    QCOMPARE(m_link->session()->trafficLog()->bytesHeld(), 0);

    // A subscriber that comes later gets every item from the broker's retained store.
    Inbox late;
    const std::unique_ptr<MqttClient> second = subscriber(&late);
    QVERIFY(second);
    QTRY_VERIFY_WITH_TIMEOUT(late.item(topic("R100")) && late.item(topic("R200"))
                                 && late.item(topic("Y0")) && late.item(topic("R300")),
                             Wait);
    // From the broker's store: the first message of each topic is marked retained.
    for (const char *address : {"R100", "R200", "Y0", "R300"}) {
        const auto first
            = std::find_if(late.all.cbegin(), late.all.cend(),
                           [&](const Inbox::Entry &e) { return e.topic == topic(address); });
        QVERIFY2(first != late.all.cend() && first->retained, address);
    }
    const GatewayPayload::ItemValue r100 = *late.item(topic("R100"));
    QCOMPARE(r100.quality, ValueQuality::Good);
    QCOMPARE(r100.station, 1);
    QCOMPARE(r100.address, addr("R100"));
    QCOMPARE(r100.name, QStringLiteral("Speed"));
    QCOMPARE(r100.text, QStringLiteral("1234"));
    QCOMPARE(r100.words, std::vector<std::uint32_t>{1234});
    const QJsonObject r100Json
        = QJsonDocument::fromJson(late.last.value(topic("R100")).payload).object();
    QCOMPARE(r100Json.value(QStringLiteral("value")).toDouble(), 1234.0);
    QVERIFY(!r100Json.contains(QStringLiteral("error")));
    const GatewayPayload::ItemValue r200 = *late.item(topic("R200"));
    QCOMPARE(r200.format, DisplayFormat::Float32);
    QCOMPARE(r200.text, QStringLiteral("12.5"));
    const std::uint32_t bits = floatBits(12.5F);
    QCOMPARE(r200.words, (std::vector<std::uint32_t>{bits & 0xFFFF, bits >> 16}));
    QCOMPARE(late.item(topic("Y0"))->format, DisplayFormat::Bit);
    QCOMPARE(late.item(topic("Y0"))->words, std::vector<std::uint32_t>{1});
    QTRY_COMPARE_WITH_TIMEOUT(late.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    // A 32-bit register: value and text agree (no word swap the item did not ask for).
    QTRY_VERIFY_WITH_TIMEOUT(late.item(topic("DR10")).has_value(), Wait);
    QCOMPARE(late.item(topic("DR10"))->text, QStringLiteral("50"));
    QCOMPARE(QJsonDocument::fromJson(late.last.value(topic("DR10")).payload)
                 .object()
                 .value(QStringLiteral("value"))
                 .toDouble(),
             50.0);

    // A change is published; an unchanged value is not published again every cycle.
    m_plc->setValue(addr("R100"), 4321);
    QTRY_COMPARE_WITH_TIMEOUT(late.item(topic("R100"))->text, QStringLiteral("4321"), Wait);
    const QString statistics
        = GatewayTopics::statistics(QStringLiteral("fatek"), QStringLiteral("line1"));
    QTRY_VERIFY_WITH_TIMEOUT(late.last.contains(statistics), Wait);
    const QJsonObject stats = QJsonDocument::fromJson(late.last.value(statistics).payload).object();
    QVERIFY(stats.value(QStringLiteral("session"))
                .toObject()
                .value(QStringLiteral("pollCycles"))
                .toDouble()
            > 0);
    // The gateway's own delay (PLC answer -> hand-over) is there, ordered, and not absurd.
    const QJsonObject own = stats.value(QStringLiteral("gateway")).toObject();
    for (const char *key : {"delayP50Ms", "delayP99Ms", "delayMaxMs"})
        QVERIFY2(own.value(QLatin1String(key)).isDouble(), key);
    QVERIFY(own.value(QStringLiteral("delayP50Ms")).toDouble()
            <= own.value(QStringLiteral("delayP99Ms")).toDouble());
    QVERIFY(own.value(QStringLiteral("delayP99Ms")).toDouble()
            <= own.value(QStringLiteral("delayMaxMs")).toDouble());
    QVERIFY(own.value(QStringLiteral("delayMaxMs")).toDouble() < Wait);
    const qsizetype before = late.all.size();
    const int cycles = static_cast<int>(m_link->session()->statistics().pollCycles);
    QTRY_VERIFY_WITH_TIMEOUT(
        m_link->session()->statistics().pollCycles >= static_cast<quint64>(cycles + 5), Wait);
    QByteArrayList republished;
    for (qsizetype i = before; i < late.all.size(); ++i) {
        if (late.all.at(i).topic == topic("R300"))
            republished << late.all.at(i).payload;
    }
    QVERIFY2(republished.isEmpty(), republished.join('\n').constData());
}

void TestGateway::allowlistedWriteReachesPlc()
{
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    QVERIFY(client->isConnected());
    QCOMPARE(simWrites(), 0);

    QVERIFY(client->publish(topic("R100") + QStringLiteral("/set"), R"({"value":"77","id":"w1"})",
                            1, false));
    const QString reply = topic("R100") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(reply).has_value(), Wait);
    QVERIFY2(inbox.reply(reply)->ok, inbox.last.value(reply).payload.constData());
    QCOMPARE(inbox.reply(reply)->id, QStringLiteral("w1"));
    QCOMPARE(inbox.reply(reply)->value, QStringLiteral("77"));
    QVERIFY(!inbox.last.value(reply).retained);
    QCOMPARE(m_plc->value(addr("R100")), std::optional<std::uint32_t>(77));
    QCOMPARE(simWrites(), 1);
    // The new value comes back through the poll.
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->text, QStringLiteral("77"), Wait);

    // Plain text on a discrete.
    QVERIFY(client->publish(topic("Y3") + QStringLiteral("/set"), "ON", 1, false));
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(topic("Y3") + QStringLiteral("/reply")).has_value(), Wait);
    QVERIFY(inbox.reply(topic("Y3") + QStringLiteral("/reply"))->ok);
    QCOMPARE(m_plc->value(addr("Y3")), std::optional<std::uint32_t>(1));
    QCOMPARE(simWrites(), 2);
    QCOMPARE(m_link->statistics().writesAccepted, quint64(2));
    QCOMPARE(m_link->statistics().writesRefused, quint64(0));
    QVERIFY2(m_gatewayLog.contains(QStringLiteral("write station 1 R100 = \"77\" (id \"w1\"): "
                                                  "written")),
             qPrintable(m_gatewayLog.join(u'\n')));

    // The raw words and the format, as the studio sends a typed value: written as they are, and
    // the reply and the log say the value in the format's text.
    QVERIFY(client->publish(topic("R150") + QStringLiteral("/set"),
                            R"({"words":[0,16320],"format":"float","id":"w2"})", 1, false));
    const QString floatReply = topic("R150") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(floatReply).has_value(), Wait);
    QVERIFY2(inbox.reply(floatReply)->ok, inbox.last.value(floatReply).payload.constData());
    QCOMPARE(inbox.reply(floatReply)->value, QStringLiteral("1.5"));
    QCOMPARE(m_plc->value(addr("R150")), std::optional<std::uint32_t>(0));
    QCOMPARE(m_plc->value(addr("R151")), std::optional<std::uint32_t>(0x3FC0));
    QCOMPARE(simWrites(), 3);
    QVERIFY2(m_gatewayLog.contains(QStringLiteral("write station 1 R150 = \"1.5\" (id \"w2\"): "
                                                  "written")),
             qPrintable(m_gatewayLog.join(u'\n')));
}

void TestGateway::refusedWritesReachNothing()
{
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    // A retained command waits in the broker before the gateway starts (MQTT marks a message
    // retained only when it comes from the broker's store, on subscribing): it must not be carried
    // out now, nor at every later restart.
    QTRY_VERIFY_WITH_TIMEOUT(client->isConnected(), Wait);
    QVERIFY(client->publish(topic("R153") + QStringLiteral("/set"), "7", 1, true));
    QTRY_VERIFY_WITH_TIMEOUT(inbox.last.contains(topic("R153") + QStringLiteral("/set")), Wait);
    QVERIFY(startGateway(false));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    const QString retainedReply = topic("R153") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(retainedReply).has_value(), Wait);
    QVERIFY(!inbox.reply(retainedReply)->ok);
    QCOMPARE(inbox.reply(retainedReply)->error.id, MsgId::GatewayWriteRetained);

    struct Case
    {
        const char *address;
        QByteArray payload;
        bool retain;
        MessageId expected;
    };
    const QList<Case> cases{
        {"R300", R"({"value":"5","id":"outside"})", false, MsgId::GatewayWriteNotAllowed},
        // A float over R199 spans R199 and R200: the second element is outside.
        {"R199", R"({"value":"1.5","format":"float","id":"span"})", false,
         MsgId::GatewayWriteNotAllowed},
        {"R150", "{not json", false, MsgId::GatewaySetNotJson},
        {"R151", R"({"id":"novalue"})", false, MsgId::GatewaySetNoValue},
        {"R152", "twelve", false, MsgId::Text},
        {"R154", QByteArray(GatewayLink::MaxCommandBytes + 1, 'x'), false,
         MsgId::GatewayWriteTooLong},
        // The raw value (as the studio sends it): one word per element, whole numbers.
        {"R155", R"({"words":[1,2],"format":"signed","id":"count"})", false,
         MsgId::GatewaySetWordCount},
        {"R156", R"({"words":[-1],"id":"negative"})", false, MsgId::GatewaySetBadWords},
        {"R157", R"({"words":[1.5],"id":"fraction"})", false, MsgId::GatewaySetBadWords},
        {"R158", R"({"words":"7","id":"text"})", false, MsgId::GatewaySetBadWords},
    };
    for (const Case &c : cases) {
        QVERIFY(client->publish(topic(c.address) + QStringLiteral("/set"), c.payload, 1, c.retain));
        const QString reply = topic(c.address) + QStringLiteral("/reply");
        QTRY_VERIFY2_WITH_TIMEOUT(inbox.reply(reply).has_value(), c.address, Wait);
        QVERIFY2(!inbox.reply(reply)->ok, c.address);
        if (c.expected != MsgId::Text)
            QCOMPARE(inbox.reply(reply)->error.id, c.expected);
        else
            QVERIFY2(!inbox.reply(reply)->error.empty(), c.address);
    }
    QCOMPARE(inbox.reply(topic("R300") + QStringLiteral("/reply"))->id, QStringLiteral("outside"));
    QCOMPARE(english(inbox.reply(topic("R199") + QStringLiteral("/reply"))->error),
             std::string("Refused: R200 is not in this connection's write allowlist."));
    // A topic with no item: counted and logged, nowhere to answer.
    QVERIFY(client->publish(QStringLiteral("fatek/line1/1/NOPE/set"), "1", 1, false));
    QTRY_COMPARE_WITH_TIMEOUT(m_link->statistics().writesRefused, quint64(cases.size() + 2), Wait);
    QCOMPARE(m_link->statistics().writesAccepted, quint64(0));
    QCOMPARE(simWrites(), 0);
    QCOMPARE(m_plc->value(addr("R300")), std::optional<std::uint32_t>(0));
    QCOMPARE(m_plc->value(addr("R153")), std::optional<std::uint32_t>(0));
    // Still serving: an allowed write after the garbage works.
    QVERIFY(client->publish(topic("R101") + QStringLiteral("/set"), "9", 1, false));
    QTRY_COMPARE_WITH_TIMEOUT(m_plc->value(addr("R101")), std::optional<std::uint32_t>(9), Wait);
    QCOMPARE(simWrites(), 1);
}

void TestGateway::readOnlyRefusesEverything()
{
    QVERIFY(startGateway(true));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    QVERIFY(m_link->session()->isReadOnly());
    QVERIFY(client->publish(topic("R100") + QStringLiteral("/set"), R"({"value":"1","id":"ro"})", 1,
                            false));
    const QString reply = topic("R100") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(reply).has_value(), Wait);
    QVERIFY(!inbox.reply(reply)->ok);
    QCOMPARE(inbox.reply(reply)->id, QStringLiteral("ro"));
    QCOMPARE(inbox.reply(reply)->error.id, MsgId::GatewayWriteReadOnly);
    QCOMPARE(simWrites(), 0);
    QCOMPARE(m_plc->value(addr("R100")), std::optional<std::uint32_t>(1234));
    QVERIFY2(m_gatewayLog.contains(QStringLiteral("write station 1 R100 = \"1\" (id \"ro\"): "
                                                  "Refused: the gateway is read-only.")),
             qPrintable(m_gatewayLog.join(u'\n')));
}

void TestGateway::brokerRestartRepublishes()
{
    QVERIFY(startGateway(false));
    {
        Inbox inbox;
        const std::unique_ptr<MqttClient> client = subscriber(&inbox);
        QVERIFY(client);
        QTRY_VERIFY_WITH_TIMEOUT(inbox.item(topic("R300")).has_value(), Wait);
    }
    m_broker->kill(); // no persistence: every retained message is gone
    // Changes while the broker is away wait; a value replaced before it could go is counted.
    m_plc->setValue(addr("R100"), 1);
    QTRY_VERIFY_WITH_TIMEOUT(m_link->statistics().waiting > 0, Wait);
    m_plc->setValue(addr("R100"), 2);
    QTRY_VERIFY_WITH_TIMEOUT(m_link->statistics().superseded > 0, Wait);
    QString error;
    QVERIFY2(m_broker->start(&error), qPrintable(error));

    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(topic("R100")) && inbox.item(topic("R200"))
                                 && inbox.item(topic("Y0")) && inbox.item(topic("R300"))
                                 && inbox.status(statusTopic()),
                             Wait);
    QCOMPARE(inbox.status(statusTopic()), std::optional(LinkStatus::Up));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->text, QStringLiteral("2"), Wait);
    QCOMPARE(inbox.item(topic("R200"))->text, QStringLiteral("12.5"));
    QTRY_COMPARE_WITH_TIMEOUT(m_link->statistics().waiting, quint64(0), Wait);
    QVERIFY2(m_gatewayLog.filter(QStringLiteral("broker down")).size() >= 1,
             qPrintable(m_gatewayLog.join(u'\n')));
}

void TestGateway::publisherBoundsWhileBrokerAway()
{
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 200;
    m_broker->stop();
    MqttClient client(settings);
    QVERIFY(client.open());
    GatewayPublisher publisher(&client);
    GatewayPublisher::Limits limits;
    limits.maxReplies = 10;
    publisher.setLimits(limits);
    const QString reply = QStringLiteral("fatek/t/1/R1/reply");
    const QString item = QStringLiteral("fatek/t/1/R2");
    for (int i = 0; i < 15; ++i)
        publisher.publishReply(reply, QByteArray::number(i));
    for (int i = 0; i < 5; ++i)
        publisher.publishRetained(item, QByteArray::number(i));
    // Bounded while the broker is away: the 5 oldest replies and 4 replaced values are gone,
    // and counted.
    QCOMPARE(publisher.counters().repliesDropped, quint64(5));
    QCOMPARE(publisher.counters().superseded, quint64(4));
    QCOMPARE(publisher.counters().published, quint64(0));
    QCOMPARE(publisher.waiting(), 11);

    QString error;
    QVERIFY2(m_broker->start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(publisher.waiting(), 0, Wait);
    QCOMPARE(publisher.counters().published, quint64(11));
    // Acknowledged (QoS 1): the broker holds it, so a reader that comes now gets it retained.
    QTRY_COMPARE_WITH_TIMEOUT(client.outstanding(), 0, Wait);
    Inbox inbox;
    const std::unique_ptr<MqttClient> reader = subscriber(&inbox);
    QVERIFY(reader);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.last.contains(item), Wait);
    QCOMPARE(inbox.last.value(item).payload, QByteArray("4")); // only the newest went out
    QVERIFY(inbox.last.value(item).retained);
    // A reconnect sends the retained topic again (a broker without persistence lost it).
    m_broker->kill();
    QVERIFY2(m_broker->start(&error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(publisher.counters().published, quint64(12), Wait);
}

void TestGateway::neverReadItemsHaveNoValue()
{
    // The PLC is not there when the gateway starts: its items go out stale without a value, so
    // that a consumer's retained last value is not replaced by an invented 0.
    const quint16 port = m_server->tcpPort();
    m_server->close();
    m_plcPort = port;
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Down), Wait);
    for (const char *address : {"R100", "R200", "Y0"}) {
        QTRY_VERIFY2_WITH_TIMEOUT(inbox.item(topic(address)).has_value(), address, Wait);
        const GatewayPayload::ItemValue item = *inbox.item(topic(address));
        QCOMPARE(item.quality, ValueQuality::Stale);
        QVERIFY2(item.words.empty(), address);
        QVERIFY2(!item.error.empty(), address);
        const QJsonObject json
            = QJsonDocument::fromJson(inbox.last.value(topic(address)).payload).object();
        QVERIFY2(json.value(QStringLiteral("value")).isNull(), address);
        QVERIFY2(json.value(QStringLiteral("text")).isNull(), address);
        QCOMPARE(json.value(QStringLiteral("words")).toArray().size(), 0);
    }

    // The PLC comes: its real values, good.
    QString error;
    QVERIFY2(m_server->listenTcp(port, &error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->quality, ValueQuality::Good, Wait);
    QCOMPARE(inbox.item(topic("R100"))->text, QStringLiteral("1234"));
    QCOMPARE(inbox.item(topic("R100"))->words, std::vector<std::uint32_t>{1234});
}

void TestGateway::silentStationIsDemoted()
{
    // Station 7 on the line does not answer: it is demoted, the statistics say until when, its
    // item is stale with that reason, and station 1 goes on being published.
    QFile list(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(list.open(QIODevice::WriteOnly | QIODevice::Truncate));
    list.write(R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":100,"items":[{"address":"R100"},{"address":"R0","station":7}]}]})json");
    list.close();
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    const QString statistics
        = GatewayTopics::statistics(QStringLiteral("fatek"), QStringLiteral("line1"));
    const auto station7 = [&inbox, &statistics] {
        const QJsonArray stations = QJsonDocument::fromJson(inbox.last.value(statistics).payload)
                                        .object()
                                        .value(QStringLiteral("stations"))
                                        .toArray();
        for (const QJsonValue &station : stations) {
            if (station.toObject().value(QStringLiteral("station")).toInt() == 7)
                return station.toObject();
        }
        return QJsonObject();
    };
    QTRY_VERIFY_WITH_TIMEOUT(station7().value(QStringLiteral("demoted")).toBool(), Wait);
    QVERIFY(QDateTime::fromString(station7().value(QStringLiteral("nextTry")).toString(),
                                  Qt::ISODateWithMs)
                .isValid());
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R0", 7))->error.id, MsgId::SessionStationDemoted,
                              Wait);
    QCOMPARE(inbox.item(topic("R0", 7))->quality, ValueQuality::Stale);
    m_plc->setValue(addr("R100"), 4321);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->text, QStringLiteral("4321"), Wait);
    QCOMPARE(inbox.item(topic("R100"))->quality, ValueQuality::Good);
}

void TestGateway::commandsWhileAwayAreAnswered()
{
    // Issue 33 (major 5): the gateway keeps a persistent session, so commands published while it
    // is away wait at the broker and are all answered when it comes back: carried out when their
    // "time" says they are fresh, refused when their age cannot be known. Nothing vanishes.
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    m_link.reset(); // the gateway stops (a restart, an update)
    QTest::qWait(200);
    QCOMPARE(simWrites(), 0);

    const QString now = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    for (int i = 0; i < 10; ++i) {
        const QByteArray address = QByteArray("R") + QByteArray::number(101 + i);
        const QByteArray payload = R"({"value":")" + QByteArray::number(500 + i) + R"(","id":"c)"
                                   + QByteArray::number(i) + R"(","time":")" + now.toUtf8()
                                   + R"("})";
        QVERIFY(client->publish(topic(address.constData()) + QStringLiteral("/set"), payload, 1,
                                false));
    }
    // Without a time: how long it waited while the gateway was away is not known.
    QVERIFY(client->publish(topic("R150") + QStringLiteral("/set"), R"({"value":"9","id":"u"})", 1,
                            false));
    QTest::qWait(300); // at the broker, not at the gateway

    QVERIFY(startGateway(false));
    for (int i = 0; i < 10; ++i) {
        const QByteArray address = QByteArray("R") + QByteArray::number(101 + i);
        const QString reply = topic(address.constData()) + QStringLiteral("/reply");
        QTRY_VERIFY2_WITH_TIMEOUT(inbox.reply(reply).has_value(), address.constData(), Wait);
        QVERIFY2(inbox.reply(reply)->ok, inbox.last.value(reply).payload.constData());
        QCOMPARE(inbox.reply(reply)->id, QStringLiteral("c%1").arg(i));
        QCOMPARE(m_plc->value(addr(address.constData())), std::optional<std::uint32_t>(500 + i));
    }
    const QString unknown = topic("R150") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(unknown).has_value(), Wait);
    QVERIFY(!inbox.reply(unknown)->ok);
    QCOMPARE(inbox.reply(unknown)->error.id, MsgId::GatewayWriteAgeUnknown);
    QCOMPARE(m_plc->value(addr("R150")), std::optional<std::uint32_t>(0));
    QCOMPARE(simWrites(), 10); // counted on the wire: the ten, nothing else
}

void TestGateway::commandOnNoItemIsAnswered()
{
    // Issue 33 (minor): a command whose topic names no item is answered on its reply topic.
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    for (const char *level : {"1/R99999", "1/r100", "1/R0100", "01/R100"}) {
        const QString base = QStringLiteral("fatek/line1/") + QLatin1String(level);
        QVERIFY(
            client->publish(base + QStringLiteral("/set"), R"({"value":"1","id":"n"})", 1, false));
        const QString reply = base + QStringLiteral("/reply");
        QTRY_VERIFY2_WITH_TIMEOUT(inbox.last.contains(reply), level, Wait);
        const QJsonObject json = QJsonDocument::fromJson(inbox.last.value(reply).payload).object();
        QCOMPARE(json.value(QStringLiteral("ok")).toBool(true), false);
        QCOMPARE(json.value(QStringLiteral("error")).toObject().value(QStringLiteral("id")),
                 QJsonValue(QStringLiteral("GatewayNoSuchItem")));
        QCOMPARE(json.value(QStringLiteral("address")).toString(),
                 QString::fromLatin1(level).section(u'/', 1));
    }
    QCOMPARE(simWrites(), 0);
}

void TestGateway::oldCommandIsRefused()
{
    // A command whose time is older than commandMaxAgeSec (10 s) is refused, not carried out late.
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    const QByteArray old
        = QDateTime::currentDateTimeUtc().addSecs(-12).toString(Qt::ISODateWithMs).toUtf8();
    QVERIFY(client->publish(topic("R100") + QStringLiteral("/set"),
                            R"({"value":"5","id":"old","time":")" + old + R"("})", 1, false));
    const QString reply = topic("R100") + QStringLiteral("/reply");
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(reply).has_value(), Wait);
    QVERIFY(!inbox.reply(reply)->ok);
    QCOMPARE(inbox.reply(reply)->error.id, MsgId::GatewayWriteExpired);
    QVERIFY2(QString::fromStdString(english(inbox.reply(reply)->error))
                 .startsWith(QStringLiteral("Expired: the command is 12.")),
             qPrintable(QString::fromStdString(english(inbox.reply(reply)->error))));
    // A time without its offset is refused as such (the sender's zone would be a guess).
    QVERIFY(client->publish(topic("R100") + QStringLiteral("/set"),
                            R"({"value":"5","id":"local","time":"2026-11-27T10:00:00"})", 1,
                            false));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.reply(reply)->error.id, MsgId::GatewaySetBadTime, Wait);
    QCOMPARE(simWrites(), 0);
    QCOMPARE(m_plc->value(addr("R100")), std::optional<std::uint32_t>(1234));
}

void TestGateway::plcRestartGoesStaleThenGood()
{
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->quality, ValueQuality::Good, Wait);
    const quint16 port = m_server->tcpPort();

    m_server->close(); // the PLC goes away
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Down), Wait);
    const qsizetype downAt = inbox.all.size();
    QVERIFY(!GatewayPayload::decodeStatus(inbox.last.value(statusTopic()).payload)->reason.empty());
    for (const char *address : {"R100", "R200", "Y0", "R300"}) {
        QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic(address))->quality, ValueQuality::Stale, Wait);
        QVERIFY2(!inbox.item(topic(address))->error.empty(), address);
    }
    QCOMPARE(inbox.item(topic("R100"))->text, QStringLiteral("1234")); // the last value, stale
    // Changed while nobody can read it: only a read may show it as good.
    m_plc->setValue(addr("R100"), 555);

    QString error;
    QVERIFY2(m_server->listenTcp(port, &error), qPrintable(error));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R100"))->quality, ValueQuality::Good, Wait);
    QCOMPARE(inbox.item(topic("R100"))->text, QStringLiteral("555"));
    for (qsizetype i = downAt; i < inbox.all.size(); ++i) {
        const Inbox::Entry &e = inbox.all.at(i);
        if (e.topic != topic("R100"))
            continue;
        const auto value = GatewayPayload::decodeItem(e.payload);
        QVERIFY(value);
        if (value->quality == ValueQuality::Good)
            QCOMPARE(value->text, QStringLiteral("555")); // never the old value as good
    }
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(topic("R300"))->quality, ValueQuality::Good, Wait);
}

// A broker that stops reading (SIGSTOP) while every poll changes every item: once the socket and
// the client's bound are full, the link keeps one state per item, the newest, and counts what it
// replaced instead of queueing every poll; when the broker reads again the newest values arrive.
void TestGateway::stalledBrokerKeepsNewestPerItem()
{
#ifndef Q_OS_UNIX
    QSKIP("stopping the broker (SIGSTOP) has no Windows counterpart");
#else
    constexpr int Items = 300;
    QJsonArray items;
    for (int i = 0; i < Items; ++i)
        items.append(QJsonObject{{QStringLiteral("address"), QStringLiteral("R%1").arg(1000 + i)}});
    const QJsonObject list{{QStringLiteral("format"), QStringLiteral("fatek-studio-watchlist")},
                           {QStringLiteral("version"), 1},
                           {QStringLiteral("tables"),
                            QJsonArray{QJsonObject{{QStringLiteral("name"), QStringLiteral("Fast")},
                                                   {QStringLiteral("intervalMs"), 50},
                                                   {QStringLiteral("items"), items}}}}};
    QFile file(m_dir->filePath(QStringLiteral("line1.json")));
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(QJsonDocument(list).toJson());
    file.close();
    const auto address = [](int i) {
        return Address{ElementType::R, static_cast<std::uint32_t>(1000 + i)};
    };
    std::uint32_t tick = 0;
    const auto change = [&] {
        ++tick;
        for (int i = 0; i < Items; ++i)
            m_plc->setValue(address(i), (tick * 7 + static_cast<std::uint32_t>(i)) & 0x7FFF);
    };
    change();
    QVERIFY(startGateway(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    const auto topicOf = [&](int i) {
        return GatewayTopics::item(QStringLiteral("fatek"), QStringLiteral("line1"), 1, address(i));
    };
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(topicOf(Items - 1)), Wait);

    QTimer mutator;
    connect(&mutator, &QTimer::timeout, this, change);
    mutator.start(20);
    const auto pid = static_cast<pid_t>(m_broker->processId());
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid, SIGSTOP), 0);
    auto resume = qScopeGuard([pid] { ::kill(pid, SIGCONT); });
    const quint64 before = m_link->statistics().superseded;
    QTRY_VERIFY_WITH_TIMEOUT(m_link->statistics().superseded > before + 3 * Items, 4 * Wait);
    mutator.stop();
    QTest::qWait(200); // a last poll reads the final values
    std::vector<QString> finalText;
    for (int i = 0; i < Items; ++i)
        finalText.push_back(QString::number(m_plc->value(address(i)).value_or(0)));
    resume.dismiss();
    QCOMPARE(::kill(pid, SIGCONT), 0);

    const auto allNewest = [&] {
        for (int i = 0; i < Items; ++i) {
            const auto value = inbox.item(topicOf(i));
            if (!value || value->quality != ValueQuality::Good
                || value->text != finalText[static_cast<std::size_t>(i)])
                return false;
        }
        return true;
    };
    QTRY_VERIFY_WITH_TIMEOUT(allNewest(), 3 * Wait);
#endif
}

void TestGateway::delayHistogramPercentiles()
{
    DelayHistogram delays;
    QCOMPARE(delays.percentile(0.5), 0);
    for (int ms = 1; ms <= 100; ++ms)
        delays.add(ms);
    delays.add(-5);     // a clock step back: no delay
    delays.add(123456); // beyond the buckets: its true value is the maximum
    QCOMPARE(delays.count(), std::uint64_t(102));
    QCOMPARE(delays.percentile(0.50), 50); // nearest rank 51 of 0,1..100,123456
    QCOMPARE(delays.percentile(0.99), 100);
    QCOMPARE(delays.percentile(1.0), 123456);
    QCOMPARE(delays.max(), 123456);
    delays.clear();
    QCOMPARE(delays.count(), std::uint64_t(0));
    QCOMPARE(delays.max(), 0);
}

void TestGateway::logTextEscapesControls()
{
    QCOMPARE(escapedForLog("5\n2026 line1: written"), std::string("5\\n2026 line1: written"));
    QCOMPARE(escapedForLog("a\r\tb\x1b[2Jc\x7f"), std::string("a\\r\\tb\\x1b[2Jc\\x7f"));
    QCOMPARE(escapedForLog(std::string_view("\0", 1)), std::string("\\x00"));
    // NEL and the Unicode line/paragraph separators end a line for some readers too.
    QCOMPARE(escapedForLog("x\xc2\x85y\xe2\x80\xa8z\xe2\x80\xa9"),
             std::string("x\\u0085y\\u2028z\\u2029"));
    // Everything else passes unchanged: text, other UTF-8, a Windows path.
    QCOMPARE(escapedForLog("R100 = \"12.5\" \xe6\xb8\xac C:\\plc"),
             std::string("R100 = \"12.5\" \xe6\xb8\xac C:\\plc"));
}

void TestGateway::executableWillAndCleanStop()
{
    const QString configPath = m_dir->filePath(QStringLiteral("gateway.json"));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    const auto run = [&](int keepAliveSec, QProcess *process) {
        QFile file(configPath);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(configJson(false, keepAliveSec));
        file.close();
        TestUtil::startConsoleProgram(process, QStringLiteral(FATEK_GATEWAY_PATH), {configPath});
        QVERIFY(process->waitForStarted(Wait));
        QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    };

    // SIGKILL: no chance to say goodbye; the broker publishes the will at 1.5 x keep-alive.
    QProcess killed;
    run(5, &killed);
    if (QTest::currentTestFailed())
        return;
    killed.kill();
    QVERIFY(killed.waitForFinished(Wait));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Offline),
                              Wait + 5000);
    {
        // The will is retained: a reader that comes later learns it too.
        Inbox later;
        const std::unique_ptr<MqttClient> reader = subscriber(&later);
        QVERIFY(reader);
        QTRY_COMPARE_WITH_TIMEOUT(later.status(statusTopic()), std::optional(LinkStatus::Offline),
                                  Wait);
        QVERIFY(later.last.value(statusTopic()).retained);
    }

    // Wine 8 delivers no console control event (GenerateConsoleCtrlEvent fails with error 12
    // without a console, 6 on a pty): the Windows stop path is tested on Windows only.
    if (TestUtil::underWine())
        QSKIP("Wine delivers no Ctrl-Break to a console program (GenerateConsoleCtrlEvent)");
    // SIGTERM (Ctrl-Break on Windows): the gateway publishes offline itself at once (the will
    // would take 90 s here).
    QProcess stopped;
    run(60, &stopped);
    if (QTest::currentTestFailed())
        return;
    // A refused command whose value carries a newline and a line of its own (issue 33): the log
    // shows it escaped on the refusal's line, never as a line that says "written".
    const QByteArray forged
        = "2026-11-26T00:00:00.000Z line1: write station 1 Y0 = \"ON\" (id \"x\"): written";
    QVERIFY(client->publish(topic("R100") + QStringLiteral("/set"), "5\n" + forged, 1, false));
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(topic("R100") + QStringLiteral("/reply")).has_value(),
                             Wait);
    QVERIFY(!inbox.reply(topic("R100") + QStringLiteral("/reply"))->ok);
    TestUtil::stopConsoleProgram(&stopped);
    QVERIFY(stopped.waitForFinished(Wait));
    const QString log = QString::fromUtf8(stopped.readAllStandardError());
    QCOMPARE(stopped.exitStatus(), QProcess::NormalExit);
    QVERIFY2(stopped.exitCode() == 0, qPrintable(log)); // 66: a ThreadSanitizer report
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Offline),
                              Wait);
    QVERIFY2(log.contains(QStringLiteral("line1: PLC link connected")), qPrintable(log));
    QVERIFY2(log.contains(QStringLiteral("line1: stopped (status offline)")), qPrintable(log));
    QVERIFY2(log.contains(QStringLiteral("\"5\\n") + QString::fromUtf8(forged)), qPrintable(log));
    for (const QString &line : log.split(u'\n'))
        QVERIFY2(!line.endsWith(QStringLiteral("(id \"x\"): written")), qPrintable(log));
}

// SIGHUP (issue 33): the configuration file again; a connection added starts, one removed stops
// (offline), one unchanged keeps running with its session untouched (nothing new on its status
// topic); a file that does not load leaves the running configuration.
void TestGateway::sighupReloadsChangedLinksOnly()
{
#ifndef Q_OS_UNIX
    QSKIP("SIGHUP is a Unix signal");
#else
    const QString configPath = m_dir->filePath(QStringLiteral("gateway.json"));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    const auto status = [](const char *connection) {
        return GatewayTopics::status(QStringLiteral("fatek"), QString::fromLatin1(connection));
    };
    const auto r100 = [](const char *connection) {
        return GatewayTopics::item(QStringLiteral("fatek"), QString::fromLatin1(connection), 1,
                                   addr("R100"));
    };
    writeFile(configPath, configJsonOf({QStringLiteral("line1"), QStringLiteral("line2")}));
    GatewayProcess gateway(configPath);
    QVERIFY(gateway.process.waitForStarted(Wait));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(status("line1")), std::optional(LinkStatus::Up), Wait);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(status("line2")), std::optional(LinkStatus::Up), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(r100("line1")).has_value(), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(r100("line2")).has_value(), Wait);

    // line2 goes, line3 comes, line1 stays as it was.
    writeFile(configPath, configJsonOf({QStringLiteral("line1"), QStringLiteral("line3")}));
    const auto line1Status = [&inbox, &status] {
        return std::count_if(inbox.all.cbegin(), inbox.all.cend(),
                             [&status](const auto &e) { return e.topic == status("line1"); });
    };
    const auto line1Before = line1Status();
    m_plc->setValue(addr("R100"), 4321);
    QVERIFY(gateway.reload());
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(status("line2")), std::optional(LinkStatus::Offline),
                              Wait);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(status("line3")), std::optional(LinkStatus::Up), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(r100("line3")).has_value()
                                 && inbox.item(r100("line3"))->words
                                        == std::vector<std::uint32_t>{4321},
                             Wait);
    // line1 read the new value through the session it had all along.
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(r100("line1"))->words, std::vector<std::uint32_t>{4321},
                              Wait);
    QCOMPARE(line1Status(), line1Before);
    QCOMPARE(gateway.process.state(), QProcess::Running);
    // line2 no longer polls: its value stays the one before the reload.
    m_plc->setValue(addr("R100"), 5555);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.item(r100("line1"))->words, std::vector<std::uint32_t>{5555},
                              Wait);
    QCOMPARE(inbox.item(r100("line2"))->words, std::vector<std::uint32_t>{1234});

    // A file that does not load: logged with its error, everything keeps running.
    writeFile(configPath, R"({"format":"fatek-gateway","version":1,"readonly":true})");
    QVERIFY(gateway.reload());
    QString log;
    QTRY_VERIFY_WITH_TIMEOUT(
        (log += QString::fromUtf8(gateway.process.readAllStandardError()))
            .contains(QStringLiteral("not reloaded, the running configuration stays")),
        Wait);
    QVERIFY2(log.contains(QStringLiteral("readOnly")), qPrintable(log));
    QCOMPARE(gateway.process.state(), QProcess::Running);
    QCOMPARE(line1Status(), line1Before);
    QCOMPARE(inbox.status(status("line3")), std::optional(LinkStatus::Up));
    QVERIFY2(!log.contains(QStringLiteral("line1: stopped")), qPrintable(log));
#endif
}

// systemd's notify protocol (issue 33): with $NOTIFY_SOCKET (a path, then an abstract name) the
// gateway sends READY=1 once its links run, WATCHDOG=1 at half of $WATCHDOG_USEC from its event
// loop, RELOADING=1 ... READY=1 around a reload and STOPPING=1 when told to stop.
void TestGateway::systemdNotifyReadyAndWatchdog()
{
#ifndef Q_OS_LINUX
    QSKIP("sd_notify is Linux only");
#else
    const QString configPath = m_dir->filePath(QStringLiteral("gateway.json"));
    writeFile(configPath, configJson(false));
    Inbox inbox;
    const std::unique_ptr<MqttClient> client = subscriber(&inbox);
    QVERIFY(client);
    for (const bool abstract : {false, true}) {
        const QByteArray name
            = abstract
                  ? "@fatek-gateway-test-" + QByteArray::number(QCoreApplication::applicationPid())
                  : QFile::encodeName(m_dir->filePath(QStringLiteral("notify")));
        const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
        QVERIFY(fd >= 0);
        const auto closeSocket = qScopeGuard([fd] { ::close(fd); });
        sockaddr_un address = {};
        address.sun_family = AF_UNIX;
        QVERIFY(std::size_t(name.size()) < sizeof address.sun_path);
        std::memcpy(address.sun_path, name.constData(), std::size_t(name.size()));
        if (abstract)
            address.sun_path[0] = '\0';
        const auto length
            = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + std::size_t(name.size()));
        QCOMPARE(::bind(fd, reinterpret_cast<const sockaddr *>(&address), length), 0);
        QStringList received;
        const auto receive = [fd, &received]() -> const QStringList & {
            char buffer[512];
            ssize_t n = 0;
            while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0)
                received.append(QString::fromUtf8(buffer, n));
            return received;
        };
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("NOTIFY_SOCKET"), QString::fromUtf8(name));
        environment.insert(QStringLiteral("WATCHDOG_USEC"), QStringLiteral("400000"));
        GatewayProcess gateway(configPath, environment);
        QVERIFY(gateway.process.waitForStarted(Wait));
        QTRY_VERIFY_WITH_TIMEOUT(receive().contains(QStringLiteral("READY=1")), Wait);
        // Ready means started: the link's first status went out before.
        QTRY_VERIFY_WITH_TIMEOUT(inbox.status(statusTopic()).has_value(), Wait);
        // Every 200 ms: five within 2 s even on a loaded machine, a hung loop sends none.
        QTRY_VERIFY_WITH_TIMEOUT(receive().count(QStringLiteral("WATCHDOG=1")) >= 5, Wait);
        QVERIFY(!receive().contains(QStringLiteral("STOPPING=1")));

        QVERIFY(gateway.reload());
        const auto reloading = [&receive] {
            const QStringList &all = receive();
            return std::find_if(all.cbegin(), all.cend(), [](const QString &m) {
                return m.startsWith(QStringLiteral("RELOADING=1\nMONOTONIC_USEC="));
            });
        };
        QTRY_VERIFY_WITH_TIMEOUT(reloading() != received.cend(), Wait);
        QTRY_VERIFY_WITH_TIMEOUT(std::find(reloading(), received.cend(), QStringLiteral("READY=1"))
                                     != received.cend(),
                                 Wait);

        TestUtil::stopConsoleProgram(&gateway.process);
        QVERIFY(gateway.process.waitForFinished(Wait));
        QVERIFY(receive().contains(QStringLiteral("STOPPING=1")));
        QCOMPARE(gateway.process.exitCode(), 0);
    }
#endif
}

// Home Assistant's MQTT discovery (issue 33), read as Home Assistant would: one retained config
// per item under homeassistant/, valid JSON with the keys it needs, availability on topics that
// really carry the gateway's status and the item's quality, a command topic the gateway answers;
// a reload that removes a connection clears its configs (empty retained payloads).
void TestGateway::homeAssistantDiscovery()
{
#ifndef Q_OS_UNIX
    QSKIP("the reload is SIGHUP, a Unix signal");
#else
    const QString configPath = m_dir->filePath(QStringLiteral("gateway.json"));
    const auto withDiscovery = [](const QByteArray &json) {
        QJsonObject root = QJsonDocument::fromJson(json).object();
        root.insert(QStringLiteral("homeAssistant"),
                    QJsonObject{{QStringLiteral("discovery"), true}});
        return QJsonDocument(root).toJson();
    };
    writeFile(configPath,
              withDiscovery(configJsonOf({QStringLiteral("line1"), QStringLiteral("line2")})));
    Inbox inbox;
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    MqttClient client(settings);
    inbox.attach(&client);
    client.subscribe(QStringLiteral("fatek/#"), 1);
    client.subscribe(QStringLiteral("homeassistant/#"), 1);
    QVERIFY(client.open());
    GatewayProcess gateway(configPath);
    QVERIFY(gateway.process.waitForStarted(Wait));
    const auto configs = [&inbox](const QString &connection) {
        QHash<QString, QJsonObject> found;
        for (const Inbox::Entry &e : std::as_const(inbox.last)) {
            if (e.topic.startsWith(QStringLiteral("homeassistant/"))
                && e.topic.contains(QStringLiteral("/fatek_") + connection + u'/'))
                found.insert(e.topic, QJsonDocument::fromJson(e.payload).object());
        }
        return found;
    };
    QTRY_COMPARE_WITH_TIMEOUT(configs(QStringLiteral("line1")).size(), 5, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(configs(QStringLiteral("line2")).size(), 5, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
    QTRY_VERIFY_WITH_TIMEOUT(inbox.item(topic("DR10")).has_value(), Wait);

    // Which entity each item is: R100 and Y0 are allowlisted (number, switch), the rest not.
    const QString node = QStringLiteral("homeassistant/%1/fatek_line1/s1_%2/config");
    const QHash<QString, QJsonObject> line1 = configs(QStringLiteral("line1"));
    for (const auto &[component, address] : {std::pair{"number", "R100"},
                                             {"sensor", "R200"},
                                             {"switch", "Y0"},
                                             {"sensor", "R300"},
                                             {"sensor", "DR10"}}) {
        const QString configTopic = node.arg(QLatin1String(component), QLatin1String(address));
        QVERIFY2(line1.contains(configTopic), qPrintable(configTopic));
        const QJsonObject config = line1.value(configTopic);
        for (const char *key :
             {"name", "unique_id", "state_topic", "value_template", "availability", "device"})
            QVERIFY2(config.contains(QLatin1String(key)), key);
        QCOMPARE(config.value(QStringLiteral("state_topic")).toString(), topic(address));
        QVERIFY(config.value(QStringLiteral("value_template"))
                    .toString()
                    .contains(QStringLiteral("value_json.value")));
        QCOMPARE(config.value(QStringLiteral("unique_id")).toString(),
                 QStringLiteral("fatek_line1_s1_") + QLatin1String(address));
        QCOMPARE(config.value(QStringLiteral("device"))
                     .toObject()
                     .value(QStringLiteral("identifiers"))
                     .toArray()
                     .at(0)
                     .toString(),
                 QStringLiteral("fatek-gateway_fatek_line1"));
        // Availability: the connection's status (also the will) and the item's own quality, on
        // topics the gateway really publishes, in the words the templates compare.
        const QJsonArray availability = config.value(QStringLiteral("availability")).toArray();
        QCOMPARE(availability.size(), 2);
        const QJsonObject status = availability.at(0).toObject();
        QCOMPARE(status.value(QStringLiteral("topic")).toString(), statusTopic());
        QCOMPARE(status.value(QStringLiteral("payload_available")).toString(),
                 QStringLiteral("up"));
        QVERIFY(status.value(QStringLiteral("value_template"))
                    .toString()
                    .contains(QStringLiteral("value_json.state == '")
                              + GatewayPayload::linkStatusName(LinkStatus::Up)));
        const QJsonObject quality = availability.at(1).toObject();
        QCOMPARE(quality.value(QStringLiteral("topic")).toString(), topic(address));
        QVERIFY(quality.value(QStringLiteral("value_template"))
                    .toString()
                    .contains(QStringLiteral("value_json.quality == '")
                              + GatewayPayload::qualityName(ValueQuality::Good)));
        QTRY_VERIFY_WITH_TIMEOUT(inbox.item(topic(address))
                                     && inbox.item(topic(address))->quality == ValueQuality::Good,
                                 Wait);
        QCOMPARE(config.value(QStringLiteral("availability_mode")).toString(),
                 QStringLiteral("all"));
    }
    QCOMPARE(line1.value(node.arg(QStringLiteral("number"), QStringLiteral("R100")))
                 .value(QStringLiteral("name"))
                 .toString(),
             QStringLiteral("Speed")); // the watch list's name
    QCOMPARE(line1.value(node.arg(QStringLiteral("sensor"), QStringLiteral("R300")))
                 .value(QStringLiteral("name"))
                 .toString(),
             QStringLiteral("R300")); // no name: the address

    // The number's command topic takes what Home Assistant sends: the plain value.
    const QJsonObject number
        = line1.value(node.arg(QStringLiteral("number"), QStringLiteral("R100")));
    QVERIFY(
        client.publish(number.value(QStringLiteral("command_topic")).toString(), "77", 1, false));
    QTRY_VERIFY_WITH_TIMEOUT(inbox.reply(topic("R100") + QStringLiteral("/reply")).has_value(),
                             Wait);
    QVERIFY(inbox.reply(topic("R100") + QStringLiteral("/reply"))->ok);
    QTRY_COMPARE_WITH_TIMEOUT(m_plc->value(addr("R100")), std::optional<std::uint32_t>(77), Wait);

    // line2 removed: its entities go (empty retained configs), line1's stay.
    writeFile(configPath, withDiscovery(configJsonOf({QStringLiteral("line1")})));
    QVERIFY(gateway.reload());
    QTRY_COMPARE_WITH_TIMEOUT(
        inbox.status(GatewayTopics::status(QStringLiteral("fatek"), QStringLiteral("line2"))),
        std::optional(LinkStatus::Offline), Wait);
    for (const QString &configTopic : configs(QStringLiteral("line2")).keys())
        QVERIFY2(inbox.last.value(configTopic).payload.isEmpty(), qPrintable(configTopic));
    for (const QString &configTopic : line1.keys())
        QVERIFY(!inbox.last.value(configTopic).payload.isEmpty());
    {
        // A Home Assistant that starts now finds line1's configs only.
        Inbox later;
        MqttClient reader(settings);
        later.attach(&reader);
        reader.subscribe(QStringLiteral("homeassistant/#"), 1);
        QVERIFY(reader.open());
        QTRY_COMPARE_WITH_TIMEOUT(later.last.size(), 5, Wait);
        QTest::qWait(300);
        QCOMPARE(later.last.size(), 5);
        for (const Inbox::Entry &e : std::as_const(later.last)) {
            QVERIFY(e.retained);
            QVERIFY2(e.topic.contains(QStringLiteral("/fatek_line1/")), qPrintable(e.topic));
        }
    }
#endif
}

// At start the status goes connecting, then up, each at most once (issue 33: a retained topic
// handed to the client in the moment between its connection and the connected signal went out
// twice).
void TestGateway::statusOnceEachAtStart()
{
    for (int run = 0; run < 5; ++run) {
        Inbox inbox;
        const std::unique_ptr<MqttClient> client = subscriber(&inbox);
        QVERIFY(client);
        QTRY_VERIFY_WITH_TIMEOUT(client->isConnected(), Wait);
        QTest::qWait(100); // the subscription is in place
        QVERIFY(startGateway(false));
        QTRY_COMPARE_WITH_TIMEOUT(inbox.status(statusTopic()), std::optional(LinkStatus::Up), Wait);
        QTest::qWait(500);
        QStringList states;
        for (const Inbox::Entry &e : std::as_const(inbox.all)) {
            if (e.topic == statusTopic())
                states << GatewayPayload::linkStatusName(
                    GatewayPayload::decodeStatus(e.payload)->state);
        }
        // "connecting" may be replaced before it went out (a retained topic keeps its newest
        // state while the broker is not there yet); nothing goes twice.
        const QString text = states.join(u',');
        QVERIFY2(text == QStringLiteral("connecting,up") || text == QStringLiteral("up"),
                 qPrintable(text));
        m_link->stop();
        QTRY_VERIFY_WITH_TIMEOUT(m_link->isStopped(), Wait);
        m_link.reset();
        // The next run's subscriber must not get this run's retained status.
        MqttClient cleaner(*MqttBrokerSettings::fromUrl(m_broker->url()));
        QVERIFY(cleaner.open());
        QTRY_VERIFY_WITH_TIMEOUT(cleaner.isConnected(), Wait);
        QVERIFY(cleaner.publish(statusTopic(), {}, 1, true));
        QTRY_COMPARE_WITH_TIMEOUT(cleaner.outstanding(), 0, Wait);
    }
}

QTEST_GUILESS_MAIN(TestGateway)
#include "tst_gateway.moc"
