// What an operator of the gateway sees (issue 55): the log tells what the PLCs do (a station
// silent, demoted, back; a PLC error per item once), the status goes down while no station
// answers, log fields cannot be forged, a duplicate client id is named as such and backed off,
// the will says when, and items stale for a demotion take the link's reason when it drops.
// Against a real mosquitto and the in-process simulator, and the real fatek-gateway for the will.
#include "core/gateway/gatewayconfig.h"
#include "core/gateway/gatewaylink.h"
#include "core/gateway/gatewaymessages.h"
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/protocol/logtext.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <csignal>
#include <memory>

using namespace Fatek;
using GatewayPayload::LinkStatus;
using TestUtil::addr;

namespace {

constexpr int Wait = 15000; // QTRY timeouts: generous for a loaded 2-core machine under TSan

// The last payload per topic a subscriber got.
struct Retained
{
    QHash<QString, QByteArray> last;

    void attach(MqttClient *client)
    {
        QObject::connect(client, &MqttClient::messageReceived,
                         [this](const QString &topic, const QByteArray &payload) {
                             last.insert(topic, payload);
                         });
    }
    std::optional<GatewayPayload::Status> status() const
    {
        const QString topic = GatewayTopics::status(QStringLiteral("fatek"), QStringLiteral("op"));
        return last.contains(topic) ? GatewayPayload::decodeStatus(last.value(topic))
                                    : std::nullopt;
    }
    std::optional<GatewayPayload::ItemValue> item(const char *address, int station = 1) const
    {
        const QString topic = GatewayTopics::item(QStringLiteral("fatek"), QStringLiteral("op"),
                                                  station, addr(address));
        return last.contains(topic) ? GatewayPayload::decodeItem(last.value(topic)) : std::nullopt;
    }
};

} // namespace

class TestGatewayOperator : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();
    void stationsAndPlcErrorsAreLogged();
    void demotedItemsTakeTheLinksReason();
    void logFieldsCannotBeForged();
    void commandsAreLoggedAsAnswered();
    void duplicateClientIdIsNamedAndBackedOff();
    void willCarriesItsTime();
    void tlsFilesRefusedAlike();
    void setCommandKeyTypes();

private:
    // A configuration of one connection "op" on the simulator with `items` (watch list items).
    QByteArray config(const QJsonArray &items, int keepAliveSec = 30) const;
    bool startLink(const QJsonArray &items);
    std::unique_ptr<MqttClient> subscriber(Retained *retained, const QString &clientId = {});
    int logCount(const QString &text) const;

    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SimulatedPlc> m_plc;
    std::unique_ptr<SimServer> m_server;
    std::unique_ptr<TestUtil::MosquittoBroker> m_broker;
    std::unique_ptr<GatewayLink> m_link;
    QStringList m_log;
};

void TestGatewayOperator::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    m_plc = std::make_unique<SimulatedPlc>(ModelProfile::fbs());
    m_plc->setValue(addr("R100"), 1234);
    m_server = std::make_unique<SimServer>(m_plc.get());
    QString error;
    QVERIFY2(m_server->listenTcp(0, &error), qPrintable(error));
    m_broker = std::make_unique<TestUtil::MosquittoBroker>();
    QVERIFY2(m_broker->start(&error), qPrintable(error));
    m_log.clear();
}

void TestGatewayOperator::cleanup()
{
    m_link.reset();
    m_broker.reset();
    m_server.reset();
    m_plc.reset();
    m_dir.reset();
}

QByteArray TestGatewayOperator::config(const QJsonArray &items, int keepAliveSec) const
{
    QFile list(m_dir->filePath(QStringLiteral("op.json")));
    if (!list.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return {};
    list.write(
        QJsonDocument(QJsonObject{{QStringLiteral("format"), "fatek-studio-watchlist"},
                                  {QStringLiteral("version"), 1},
                                  {QStringLiteral("tables"),
                                   QJsonArray{QJsonObject{{QStringLiteral("intervalMs"), 100},
                                                          {QStringLiteral("items"), items}}}}})
            .toJson());
    list.close();
    const QJsonObject link{{QStringLiteral("host"), "127.0.0.1"},
                           {QStringLiteral("port"), m_server->tcpPort()},
                           {QStringLiteral("protocol"), "facon"},
                           {QStringLiteral("timeoutMs"), 200},
                           {QStringLiteral("retries"), 0}};
    const QJsonObject connection{{QStringLiteral("name"), "op"},
                                 {QStringLiteral("link"), link},
                                 {QStringLiteral("watchLists"),
                                  QJsonArray{QJsonObject{{QStringLiteral("file"), "op.json"}}}},
                                 {QStringLiteral("allow"), QJsonArray{"R100..R199"}}};
    return QJsonDocument(QJsonObject{{QStringLiteral("format"), "fatek-gateway"},
                                     {QStringLiteral("version"), 1},
                                     {QStringLiteral("broker"),
                                      QJsonObject{{QStringLiteral("url"), m_broker->url()},
                                                  {QStringLiteral("keepAliveSec"), keepAliveSec}}},
                                     {QStringLiteral("connections"), QJsonArray{connection}}})
        .toJson();
}

bool TestGatewayOperator::startLink(const QJsonArray &items)
{
    Result<GatewayConfig> loaded = GatewayConfig::load(config(items), m_dir->path());
    if (!loaded) {
        qWarning() << QString::fromStdString(loaded.error().text());
        return false;
    }
    GatewayConnectionConfig connection = loaded->connections.at(0);
    connection.link.reconnectMinMs = 50;
    connection.link.reconnectMaxMs = 500;
    // Demoted after 2 silent requests, tried again every second: the test waits for both.
    connection.link.demoteAfter = 2;
    connection.link.demotionMs = 1000;
    m_link = std::make_unique<GatewayLink>(connection, loaded->prefix, loaded->broker, false);
    connect(m_link.get(), &GatewayLink::logEvent, this, [this](const Message &event) {
        m_log.append(QString::fromStdString(escapedForLog(english(event))));
    });
    Message error;
    if (!m_link->start(&error)) {
        qWarning() << QString::fromStdString(english(error));
        return false;
    }
    return true;
}

std::unique_ptr<MqttClient> TestGatewayOperator::subscriber(Retained *retained,
                                                            const QString &clientId)
{
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.clientId = clientId;
    auto client = std::make_unique<MqttClient>(settings);
    if (retained) {
        retained->attach(client.get());
        client->subscribe(QStringLiteral("fatek/#"), 1);
    }
    if (!client->open())
        return nullptr;
    return client;
}

int TestGatewayOperator::logCount(const QString &text) const
{
    return static_cast<int>(
        std::count_if(m_log.cbegin(), m_log.cend(),
                      [&text](const QString &line) { return line.contains(text); }));
}

// Issue 55, item 4: a 13 s SIGSTOP of the PLC left the log silent and the status "up"; R9999's
// "illegal address" was not logged at all.
void TestGatewayOperator::stationsAndPlcErrorsAreLogged()
{
    QVERIFY(startLink(
        {QJsonObject{{QStringLiteral("address"), "R100"}},
         QJsonObject{{QStringLiteral("address"), "R9999"}, {QStringLiteral("name"), "bad"}}}));
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QTRY_COMPARE_WITH_TIMEOUT(retained.item("R100") ? retained.item("R100")->quality
                                                    : ValueQuality::Stale,
                              ValueQuality::Good, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(retained.item("R9999") ? retained.item("R9999")->quality
                                                     : ValueQuality::Good,
                              ValueQuality::Error, Wait);
    const QString itemError = QStringLiteral("station 1 R9999: ");
    QTRY_COMPARE_WITH_TIMEOUT(logCount(itemError), 1, Wait);
    QCOMPARE(retained.status()->state, LinkStatus::Up);

    // The PLC stops answering (another station number: the line is open, nothing answers).
    m_server->setStation(9);
    QTRY_COMPARE_WITH_TIMEOUT(logCount(QStringLiteral("station 1 does not answer: ")), 1, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(logCount(QStringLiteral("station 1 demoted: ")), 1, Wait);
    // No value of the connection is current: the status, the readers' gap marker, says so.
    QTRY_COMPARE_WITH_TIMEOUT(retained.status()->state, LinkStatus::Down, Wait);
    QVERIFY(!retained.status()->reason.empty());

    m_server->setStation(1);
    QTRY_COMPARE_WITH_TIMEOUT(logCount(QStringLiteral("station 1 answers again")), 1, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(retained.status()->state, LinkStatus::Up, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(retained.item("R100")->quality, ValueQuality::Good, Wait);
    QTRY_COMPARE_WITH_TIMEOUT(retained.item("R9999")->quality, ValueQuality::Error, Wait);
    // Once per change, not once per poll: the same refusal after the silence is no news.
    QTest::qWait(500);
    QCOMPARE(logCount(itemError), 1);
    QCOMPARE(logCount(QStringLiteral("station 1 does not answer: ")), 1);
    QCOMPARE(logCount(QStringLiteral("station 1 demoted: ")), 1);
}

// Issue 55, item 9: an item already stale because its station was demoted kept that reason when
// the link itself then dropped.
void TestGatewayOperator::demotedItemsTakeTheLinksReason()
{
    QVERIFY(startLink(
        {QJsonObject{{QStringLiteral("address"), "R100"}},
         QJsonObject{{QStringLiteral("address"), "R0"}, {QStringLiteral("station"), 7}}}));
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QTRY_VERIFY_WITH_TIMEOUT(
        retained.item("R0", 7) && retained.item("R0", 7)->error.id == MsgId::SessionStationDemoted,
        Wait);
    m_server->close(); // the PLC link goes down
    QTRY_COMPARE_WITH_TIMEOUT(retained.status()->state, LinkStatus::Down, Wait);
    // The demoted item now says the link's reason, as every other item.
    QTRY_VERIFY_WITH_TIMEOUT(retained.item("R0", 7)->error.id != MsgId::SessionStationDemoted,
                             Wait);
    QCOMPARE(retained.item("R0", 7)->quality, ValueQuality::Stale);
    QVERIFY(!retained.item("R0", 7)->error.empty());
}

// Issue 55, item 8: a quote in a value closed the log's quotes ("1" (id "admin"): written" read as
// two fields) and U+202E turned the rest of the line around.
void TestGatewayOperator::logFieldsCannotBeForged()
{
    QCOMPARE(quotedFieldForLog("1\" (id \"admin\"): written"),
             std::string("1\\\" (id \\\"admin\\\"): written"));
    QCOMPARE(quotedFieldForLog("C:\\plc"), std::string("C:\\\\plc"));
    QCOMPARE(escapedForLog("a\xe2\x80\xae"
                           "b\xe2\x81\xa6"
                           "c\xe2\x80\x8f"
                           "d\xd8\x9c"
                           "e"),
             std::string("a\\u202eb\\u2066c\\u200fd\\u061ce"));
    // Other text of the same blocks stays: an en dash, a bullet, Arabic letters.
    QCOMPARE(escapedForLog("\xe2\x80\x93\xe2\x80\xa2\xd8\xa8"),
             std::string("\xe2\x80\x93\xe2\x80\xa2\xd8\xa8"));

    QVERIFY(startLink({QJsonObject{{QStringLiteral("address"), "R100"}}}));
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QTRY_VERIFY_WITH_TIMEOUT(retained.status() && retained.status()->state == LinkStatus::Up, Wait);
    const QString set = QStringLiteral("fatek/op/1/R100/set");
    QVERIFY(client->publish(set, "1\" (id \"admin\"): written \xe2\x80\xae", 1, false));
    QTRY_COMPARE_WITH_TIMEOUT(logCount(QStringLiteral("write station 1 R100")), 1, Wait);
    const QString line = m_log.filter(QStringLiteral("write station 1 R100")).first();
    QVERIFY2(
        line.startsWith(QStringLiteral(
            "write station 1 R100 = \"1\\\" (id \\\"admin\\\"): written \\u202e\" (id \"\"): ")),
        qPrintable(line));
}

// Issue 55, item 8: a words command was logged as = "" and a command on a topic that names no
// item, answered as refused, was logged as "Ignored".
void TestGatewayOperator::commandsAreLoggedAsAnswered()
{
    QVERIFY(startLink({QJsonObject{{QStringLiteral("address"), "R100"}}}));
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QTRY_VERIFY_WITH_TIMEOUT(retained.status() && retained.status()->state == LinkStatus::Up, Wait);
    QVERIFY(client->publish(QStringLiteral("fatek/op/1/R100/set"),
                            "{\"words\":[70000],\"id\":\"w1\"}", 1, false));
    QVERIFY(client->publish(QStringLiteral("fatek/op/1/R99999/set"),
                            "{\"value\":\"1\",\"id\":\"n\"}", 1, false));
    QTRY_COMPARE_WITH_TIMEOUT(logCount(QStringLiteral("(id \"w1\")")), 1, Wait);
    QVERIFY2(logCount(QStringLiteral("write station 1 R100 = \"[70000]\" (id \"w1\"): ")) == 1,
             qPrintable(m_log.join(u'\n')));
    QTRY_COMPARE_WITH_TIMEOUT(
        logCount(QStringLiteral("refused a command on \"fatek/op/1/R99999/set\": ")), 1, Wait);
    QCOMPARE(logCount(QStringLiteral("Ignored")), 0);
}

// Issue 55, item 7: two gateways with one configuration threw each other off the broker 47 times
// in 12 s, logged only as "The connection was lost.".
void TestGatewayOperator::duplicateClientIdIsNamedAndBackedOff()
{
    const QString id = QStringLiteral("fatek-gateway-fatek-op");
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(m_broker->url());
    settings.clientId = id;
    settings.reconnectMinMs = 200;
    settings.reconnectMaxMs = 30000;
    MqttClient first(settings);
    MqttClient second(settings);
    QSignalSpy firstDown(&first, &MqttClient::disconnected);
    QSignalSpy secondDown(&second, &MqttClient::disconnected);
    QVERIFY(first.open());
    QTRY_VERIFY_WITH_TIMEOUT(first.isConnected(), Wait);
    QVERIFY(second.open());
    const auto takenOver = [](const QSignalSpy &spy) {
        for (const QList<QVariant> &down : spy) {
            if (down.front().value<Message>().id == MsgId::MqttTakenOver)
                return true;
        }
        return false;
    };
    QTRY_VERIFY_WITH_TIMEOUT(takenOver(firstDown) || takenOver(secondDown), Wait);
    const Message named = [&] {
        for (const QSignalSpy *spy : {&firstDown, &secondDown}) {
            for (const QList<QVariant> &down : *spy) {
                if (down.front().value<Message>().id == MsgId::MqttTakenOver)
                    return down.front().value<Message>();
            }
        }
        return Message();
    }();
    const QString text = QString::fromStdString(english(named));
    QVERIFY2(text.contains(QStringLiteral("another client with the same client id \"") + id
                           + QStringLiteral("\" took over")),
             qPrintable(text));
    // Backed off: from here each waits twice as long as before (0.2, 0.4, 0.8, 1.6, 3.2 s ... up to
    // 30 s, each 75..125 %), so in the next 6 s the two drop each other a handful of times, not
    // the 30 times a fixed 0.2 s would give.
    const qsizetype before = firstDown.size() + secondDown.size();
    QTest::qWait(6000);
    const qsizetype drops = firstDown.size() + secondDown.size() - before;
    QVERIFY2(drops <= 12, qPrintable(QString::number(drops)));
}

// Issue 55, item 9: the will "offline" had no time, although the docs tell historians to take the
// status's time as the start of a gap.
void TestGatewayOperator::willCarriesItsTime()
{
    const QString path = m_dir->filePath(QStringLiteral("gateway.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(config({QJsonObject{{QStringLiteral("address"), "R100"}}}, 5));
    file.close();
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QProcess gateway;
    TestUtil::startConsoleProgram(&gateway, QStringLiteral(FATEK_GATEWAY_PATH), {path});
    QVERIFY(gateway.waitForStarted(Wait));
    QTRY_VERIFY_WITH_TIMEOUT(retained.status() && retained.status()->state == LinkStatus::Up, Wait);
    const QDateTime beforeConnect = QDateTime::currentDateTimeUtc().addSecs(-60);
    gateway.kill(); // no goodbye: the broker publishes the will at 1.5 x keep-alive
    QVERIFY(gateway.waitForFinished(Wait));
    QTRY_COMPARE_WITH_TIMEOUT(retained.status()->state, LinkStatus::Offline, Wait + 5000);
    const QDateTime time = retained.status()->time;
    QVERIFY(time.isValid());
    // The time of the connect that left the will: before the kill, not in the future.
    QVERIFY(time > beforeConnect);
    QVERIFY(time <= QDateTime::currentDateTimeUtc());
}

// Issue 55, item 3: a CA file that is no certificate and a key that is not the certificate's
// passed --check, then the start retried for ever. The one check of the configuration refuses
// them, word for word the same in --check, a start and a SIGHUP reload.
void TestGatewayOperator::tlsFilesRefusedAlike()
{
    // The certificates: ca.crt signed server.crt/.key and client.crt/.key (openssl, as the TLS
    // broker of tst_mqtt has them).
    TestUtil::MosquittoBroker tlsBroker;
    QString error;
    if (!tlsBroker.startWithTls(&error) && error.contains(QStringLiteral("openssl is not")))
        QSKIP("openssl is not installed (tools/install-deps.sh installs it)");
    QVERIFY2(tlsBroker.isRunning(), qPrintable(error));
    const QDir certs(tlsBroker.directory());
    const QString notCa = m_dir->filePath(QStringLiteral("not-a-certificate.pem"));
    QFile junk(notCa);
    QVERIFY(junk.open(QIODevice::WriteOnly));
    junk.write("-----BEGIN CERTIFICATE-----\nnot base64 at all\n-----END CERTIFICATE-----\n");
    junk.close();
    const QJsonObject good
        = QJsonDocument::fromJson(config({QJsonObject{{QStringLiteral("address"), "R100"}}}))
              .object();
    const auto withBroker = [&good](const QJsonObject &broker) {
        QJsonObject json = good;
        json.insert(QStringLiteral("broker"), broker);
        return QJsonDocument(json).toJson();
    };
    const QString url = QStringLiteral("mqtts://127.0.0.1:%1").arg(tlsBroker.port());
    const struct
    {
        QJsonObject broker;
        QString expected;
    } cases[] = {
        {{{QStringLiteral("url"), url}, {QStringLiteral("caFile"), notCa}},
         QStringLiteral("broker: the CA file %1 holds no usable certificate: ").arg(notCa)},
        {{{QStringLiteral("url"), url},
          {QStringLiteral("caFile"), certs.filePath(QStringLiteral("ca.crt"))},
          {QStringLiteral("certFile"), certs.filePath(QStringLiteral("client.crt"))},
          {QStringLiteral("keyFile"), certs.filePath(QStringLiteral("server.key"))}},
         QStringLiteral("broker: the key file %1 is not the key of the certificate %2.")
             .arg(certs.filePath(QStringLiteral("server.key")),
                  certs.filePath(QStringLiteral("client.crt")))},
    };
    const QString path = m_dir->filePath(QStringLiteral("gateway.json"));
    const auto writeConfig = [&path](const QByteArray &json) {
        QFile file(path);
        return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(json) > 0;
    };
    // A gateway that runs, for the reloads.
    QVERIFY(writeConfig(QJsonDocument(good).toJson()));
    Retained retained;
    const std::unique_ptr<MqttClient> client = subscriber(&retained);
    QVERIFY(client);
    QProcess running;
    TestUtil::startConsoleProgram(&running, QStringLiteral(FATEK_GATEWAY_PATH), {path});
    QVERIFY(running.waitForStarted(Wait));
    QTRY_VERIFY_WITH_TIMEOUT(retained.status() && retained.status()->state == LinkStatus::Up, Wait);
    QString log;
    for (const auto &c : cases) {
        QVERIFY(writeConfig(withBroker(c.broker)));
        const QString expected = QStringLiteral("%1: %2").arg(path, c.expected);
        const TestUtil::ProgramRun check
            = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", path});
        QCOMPARE(check.code, 2);
        QVERIFY2(check.err.startsWith(QStringLiteral("fatek-gateway: ") + expected),
                 qPrintable(check.err));
        const TestUtil::ProgramRun start
            = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {path});
        QCOMPARE(start.code, 2);
        QCOMPARE(start.err, check.err);
#ifdef Q_OS_UNIX
        // (Reloading is SIGHUP's: Windows has no such signal, and the gateway no reload there.)
        QCOMPARE(::kill(static_cast<pid_t>(running.processId()), SIGHUP), 0);
        QTRY_VERIFY_WITH_TIMEOUT(
            (log += QString::fromUtf8(running.readAllStandardError()))
                .contains(QStringLiteral("not reloaded, the running configuration stays: ")
                          + expected),
            Wait);
#endif
    }
    QCOMPARE(retained.status()->state, LinkStatus::Up); // the running one kept running
    TestUtil::stopConsoleProgram(&running);
    QVERIFY(running.waitForFinished(Wait));
}

// Issue 55, item 9: {"value":"1","format":5} was refused as '"" is not a value format'.
void TestGatewayOperator::setCommandKeyTypes()
{
    Message error;
    QVERIFY(!GatewayPayload::decodeSet("{\"value\":\"1\",\"format\":5}", &error));
    QCOMPARE(QString::fromStdString(english(error)),
             QStringLiteral("\"format\" must be a string."));
    QVERIFY(!GatewayPayload::decodeSet("{\"value\":\"1\",\"time\":5}", &error));
    QCOMPARE(QString::fromStdString(english(error)), QStringLiteral("\"time\" must be a string."));
    QVERIFY(GatewayPayload::decodeSet("{\"value\":\"1\",\"format\":\"hex\"}", &error));
}

QTEST_GUILESS_MAIN(TestGatewayOperator)
#include "tst_gatewayoperator.moc"
