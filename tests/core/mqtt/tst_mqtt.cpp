// The MQTT client (libmosquitto) against a real mosquitto on a free loopback port, and the
// gateway's topic scheme and payloads (issue 20).
#include "core/mqtt/gatewaypayload.h"
#include "core/mqtt/gatewaytopics.h"
#include "core/mqtt/messagejson.h"
#include "core/mqtt/mqttclient.h"
#include "core/mqtt/mqttmessages.h"
#include "core/mqtt/mqttpacket.h"
#include "core/watch/itemvalues.h"
#include "core/watch/watchmessages.h"
#include "mosquittobroker.h"
#include "testutil.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTimeZone>

#include <algorithm>
#ifdef Q_OS_UNIX
#include <csignal>
#endif
#include <cstring>
#include <span>

using namespace Fatek;
using TestUtil::addr;
using TestUtil::floatBits;

namespace {

// Messages received by a client, by topic (the last one wins, as a retained topic reads).
struct Inbox
{
    QHash<QString, QByteArray> last;
    QHash<QString, bool> retained;
    int count = 0;

    void connect(MqttClient *client)
    {
        QObject::connect(client, &MqttClient::messageReceived,
                         [this](const QString &topic, const QByteArray &payload, bool isRetained) {
                             last.insert(topic, payload);
                             retained.insert(topic, isRetained);
                             ++count;
                         });
    }
};

MqttBrokerSettings settingsFor(const TestUtil::MosquittoBroker &broker)
{
    MqttBrokerSettings settings = *MqttBrokerSettings::fromUrl(broker.url());
    settings.reconnectMinMs = 50;
    settings.reconnectMaxMs = 200;
    return settings;
}

// A subscriber of one topic that collects its numbered payloads, and a publisher. start() opens
// both and returns once a probe came through (the subscription is in place); the caller checks
// QTest::currentTestFailed() after it.
struct NumberedFeed
{
    explicit NumberedFeed(const TestUtil::MosquittoBroker &broker)
        : subscriber(settingsFor(broker))
        , publisher(settingsFor(broker))
    {}
    void start(const QString &topic)
    {
        QObject::connect(&subscriber, &MqttClient::messageReceived,
                         [this](const QString &, const QByteArray &payload, bool) {
                             if (payload == "probe")
                                 probed = true;
                             else
                                 received.append(payload.toInt());
                         });
        subscriber.subscribe(topic);
        QVERIFY(subscriber.open());
        QVERIFY(publisher.open());
        QTRY_VERIFY_WITH_TIMEOUT(publisher.isConnected(), 5000);
        QTRY_VERIFY_WITH_TIMEOUT((publisher.publish(topic, "probe"), probed), 5000);
    }
    MqttClient subscriber;
    MqttClient publisher;
    QList<int> received;
    bool probed = false;
};

} // namespace

class TestMqtt : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void brokerUrls_data();
    void brokerUrls();
    void brokerSettingsValidate();
    void brokerTlsWhereTheLibraryHasIt();
    void tlsFailuresSayWhich_data();
    void tlsFailuresSayWhich();
    void topicsRoundTrip();
    void topicsRejectOthers();
    void messageJsonKeepsIdsAndNesting();
    void messageJsonKnowsTheIdsAGatewaySends();
    void messageJsonFallsBackToEnglish();
    void itemPayloadFloat();
    void itemPayloadSignedBitAndNan();
    void itemPayloadRejectsGarbage();
    void itemPayloadIsQtsJson_data();
    void itemPayloadIsQtsJson();
    void setCommands();
    void replyAndStatusRoundTrip();

    void clientPublishesAndReceivesRetained();
    void clientRefusedConnectionSaysWhy();
    void clientWrongPasswordSaysWhy();
    void clientReconnectsAfterBrokerRestart();
    void clientStalledBrokerSaysKeepalive();
    void clientsDoNotReconnectInLockstep();
    void clientBurstArrivesWholeAndInOrder();
    void clientStalledBrokerKeepsNewestPerTopic();
    void publishPacketEncoding();
    void clientReceiveWindowReadsOn();
};

void TestMqtt::brokerUrls_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<bool>("ok");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<bool>("tls");
    QTest::addColumn<QString>("user");
    QTest::addColumn<QString>("password");
    QTest::newRow("plain") << "mqtt://broker" << true << "broker" << 1883 << false << ""
                           << "";
    QTest::newRow("bare host:port") << "10.0.0.5:1884" << true << "10.0.0.5" << 1884 << false << ""
                                    << "";
    QTest::newRow("tls default port")
        << "mqtts://op:s3cret@broker.plant" << true << "broker.plant" << 8883 << true << "op"
        << "s3cret";
    QTest::newRow("ipv6") << "mqtt://[::1]:1999" << true << "::1" << 1999 << false << ""
                          << "";
    QTest::newRow("http") << "http://broker" << false << "" << 0 << false << ""
                          << "";
    QTest::newRow("path") << "mqtt://broker/topic" << false << "" << 0 << false << ""
                          << "";
    QTest::newRow("empty") << "  " << false << "" << 0 << false << ""
                           << "";
    QTest::newRow("port too big") << "mqtt://broker:70000" << false << "" << 0 << false << ""
                                  << "";
}

void TestMqtt::brokerUrls()
{
    QFETCH(QString, url);
    QFETCH(bool, ok);
    const Result<MqttBrokerSettings> settings = MqttBrokerSettings::fromUrl(url);
    QCOMPARE(settings.ok(), ok);
    if (!ok) {
        QVERIFY(!settings.error().text().empty());
        return;
    }
    QTEST(settings->host, "host");
    QTEST(int(settings->port), "port");
    QTEST(settings->tls, "tls");
    QTEST(settings->username, "user");
    QTEST(settings->password, "password");
    // The URL shown back never carries the password.
    QVERIFY(!settings->toUrl().contains(QStringLiteral("s3cret")));
    QCOMPARE(MqttBrokerSettings::fromUrl(settings->toUrl())->host, settings->host);
}

void TestMqtt::brokerSettingsValidate()
{
    MqttBrokerSettings settings;
    QVERIFY(settings.validate().empty());
    settings.tls = true;
    settings.caFile = QStringLiteral("/nonexistent/ca.crt");
    QCOMPARE(englishText(settings.validate()),
             QStringLiteral("Cannot read the TLS file /nonexistent/ca.crt."));
    settings.caFile.clear();
    settings.password = QStringLiteral("x");
    QCOMPARE(englishText(settings.validate()),
             QStringLiteral("A broker password needs a user name."));
    // open() refuses the same and starts nothing.
    MqttClient client(settings);
    QVERIFY(!client.open());
    QCOMPARE(englishText(client.openError()),
             QStringLiteral("A broker password needs a user name."));
}

void TestMqtt::brokerTlsWhereTheLibraryHasIt()
{
    const auto settings = MqttBrokerSettings::fromUrl(QStringLiteral("mqtts://broker.example"));
    QVERIFY(settings.ok());
#ifdef Q_OS_WIN
    // The Windows build's libmosquitto has no TLS (tools/windows/build-qt.sh): said before any
    // connection is tried, by the settings and by open().
    QVERIFY(!MqttBrokerSettings::tlsAvailable());
    const QString expected = QStringLiteral(
        "mqtts://broker.example needs TLS, which this build's MQTT library does not have (the "
        "Windows build has none yet): use an mqtt:// broker.");
    QCOMPARE(englishText(settings->validate()), expected);
    MqttClient client(*settings);
    QVERIFY(!client.open());
    QCOMPARE(englishText(client.openError()), expected);
#else
    QVERIFY(MqttBrokerSettings::tlsAvailable());
    QVERIFY(settings->validate().empty());
#endif
}

void TestMqtt::tlsFailuresSayWhich_data()
{
    QTest::addColumn<bool>("rightCa");
    QTest::addColumn<QString>("host");
    QTest::addColumn<bool>("expired");
    QTest::addColumn<QString>("expected");
    const QString ip = QStringLiteral("127.0.0.1");
    // The broker wants a client certificate and the client has none: TLS 1.3 tells after the
    // handshake, so the connection opens and closes before any CONNACK.
    QTest::newRow("no client certificate")
        << true << ip << false
        << QStringLiteral("certificate required|may require a client certificate");
    // Issue 55: each failed check named, not "certificate verify failed" alone.
    QTest::newRow("wrong CA") << false << ip << false
                              << QStringLiteral("certificate verify failed: (self-signed "
                                                "certificate in certificate chain|unable to get "
                                                "local issuer certificate)");
    // (libmosquitto names this one itself.)
    QTest::newRow("host mismatch") << true << QStringLiteral("localhost") << false
                                   << QStringLiteral("host name verification failed");
    QTest::newRow("expired") << true << ip << true
                             << QStringLiteral(
                                    "certificate verify failed: certificate has expired");
}

// Issue 33 (major 3): a failed TLS connection is reported at once, every attempt, naming the check
// that failed (not "A TLS error occurred." alone, and not silence while the broker sees retries).
void TestMqtt::tlsFailuresSayWhich()
{
#ifdef Q_OS_WIN
    QSKIP("the Windows build's MQTT library has no TLS (brokerTlsWhereTheLibraryHasIt)");
#else
    QFETCH(bool, rightCa);
    QFETCH(QString, host);
    QFETCH(bool, expired);
    QFETCH(QString, expected);
    TestUtil::MosquittoBroker broker;
    const QDir dir(broker.directory());
    if (QStandardPaths::findExecutable(QStringLiteral("openssl")).isEmpty())
        QSKIP("openssl is not installed (tools/install-deps.sh installs it)");
    QString error;
    QVERIFY2(broker.startWithTls(&error), qPrintable(error + broker.log()));
    if (expired) {
        // The broker's certificate again, with its end a day ago, and the broker on it.
        QProcess sign;
        sign.setWorkingDirectory(dir.path());
        sign.setProcessChannelMode(QProcess::MergedChannels);
        sign.start(QStringLiteral("openssl"),
                   {"x509", "-req", "-in", "server.csr", "-CA", "ca.crt", "-CAkey", "ca.key",
                    "-CAcreateserial", "-out", "server.crt", "-days", "-1", "-extfile", "ext.cnf"});
        QVERIFY2(sign.waitForFinished(30000) && sign.exitCode() == 0, sign.readAll().constData());
        QVERIFY2(broker.start(&error, QStringLiteral("cafile %1\ncertfile %2\nkeyfile %3\n")
                                          .arg(dir.filePath(QStringLiteral("ca.crt")),
                                               dir.filePath(QStringLiteral("server.crt")),
                                               dir.filePath(QStringLiteral("server.key")))),
                 qPrintable(error + broker.log()));
    }

    MqttBrokerSettings settings = settingsFor(broker);
    settings.host = host;
    settings.tls = true;
    settings.caFile
        = dir.filePath(rightCa ? QStringLiteral("ca.crt") : QStringLiteral("other.crt"));
    MqttClient client(settings);
    QSignalSpy failures(&client, &MqttClient::disconnected);
    QElapsedTimer clock;
    clock.start();
    QVERIFY(client.open());
    QTRY_VERIFY_WITH_TIMEOUT(failures.size() >= 4, 5000); // each attempt, not only the first
    qInfo("%lld attempts reported in %lld ms", static_cast<long long>(failures.size()),
          static_cast<long long>(clock.elapsed()));
    for (const QList<QVariant> &failure : failures) {
        const QString reason = englishText(failure.front().value<Message>());
        qInfo("%s", qPrintable(reason));
        QVERIFY2(reason.startsWith(QStringLiteral("Cannot reach the broker ")), qPrintable(reason));
        QVERIFY2(reason.contains(QRegularExpression(expected)), qPrintable(reason));
    }
    QVERIFY(!client.isConnected());
#endif
}

void TestMqtt::topicsRoundTrip()
{
    const QString prefix = QStringLiteral("plant/fatek");
    QCOMPARE(GatewayTopics::item(prefix, QStringLiteral("line1"), 3, addr("R100")),
             QStringLiteral("plant/fatek/line1/3/R100"));
    QCOMPARE(GatewayTopics::itemSet(prefix, QStringLiteral("line1"), 3, addr("DR10")),
             QStringLiteral("plant/fatek/line1/3/DR10/set"));
    QCOMPARE(GatewayTopics::status(prefix, QStringLiteral("line1")),
             QStringLiteral("plant/fatek/line1/status"));

    auto parsed = GatewayTopics::parse(prefix, QStringLiteral("plant/fatek/line1/3/WY16/reply"));
    QVERIFY(parsed);
    QCOMPARE(parsed->kind, GatewayTopics::Kind::Reply);
    QCOMPARE(parsed->connection, QStringLiteral("line1"));
    QCOMPARE(parsed->station, 3);
    QCOMPARE(parsed->address, addr("WY16"));
    parsed = GatewayTopics::parse(prefix, QStringLiteral("plant/fatek/line1/statistics"));
    QVERIFY(parsed);
    QCOMPARE(parsed->kind, GatewayTopics::Kind::Statistics);
    parsed = GatewayTopics::parse(prefix, QStringLiteral("plant/fatek/line1/1/Y0"));
    QVERIFY(parsed);
    QCOMPARE(parsed->kind, GatewayTopics::Kind::Item);
}

void TestMqtt::topicsRejectOthers()
{
    const QString prefix = QStringLiteral("fatek");
    for (const char *topic :
         {"other/line1/1/R100", "fatek/line1/1/R70000", "fatek/line1/x/R1", "fatek/line1/01/R1",
          "fatek/line1/1/r100", "fatek/line1/1/R100/get", "fatek/line1/1/R100/set/x",
          "fatek/12/1/R1", "fatek/line1/status/x", "fatek/line1", "fatek/line 1/1/R1"})
        QVERIFY2(!GatewayTopics::parse(prefix, QString::fromLatin1(topic)), topic);
    QVERIFY(GatewayTopics::isValidConnectionName(QStringLiteral("press-3.a_b")));
    QVERIFY(!GatewayTopics::isValidConnectionName(QStringLiteral("12")));
    QVERIFY(!GatewayTopics::isValidConnectionName(QStringLiteral("a/b")));
    QVERIFY(!GatewayTopics::isValidConnectionName(QStringLiteral("a+")));
    QVERIFY(GatewayTopics::isValidPrefix(QStringLiteral("plant/fatek")));
    QVERIFY(!GatewayTopics::isValidPrefix(QStringLiteral("plant//fatek")));
    QVERIFY(!GatewayTopics::isValidPrefix(QStringLiteral("fatek/#")));
    QVERIFY(!GatewayTopics::isValidPrefix(QStringLiteral("/fatek")));
}

void TestMqtt::messageJsonKeepsIdsAndNesting()
{
    const Message inner = msg<MsgId::MqttUrlInvalid>("http://x");
    const Message outer = msg<MsgId::Joined>("R100", inner);
    const QJsonObject json = MessageJson::toJson(outer);
    QCOMPARE(json.value(QStringLiteral("id")).toString(), QStringLiteral("Joined"));
    QCOMPARE(json.value(QStringLiteral("text")).toString(), englishText(outer));
    const std::optional<Message> back = MessageJson::fromJson(json);
    QVERIFY(back);
    QVERIFY(*back == outer);
}

void TestMqtt::messageJsonKnowsTheIdsAGatewaySends()
{
    // Every id of the lists up to core/mqtt (what a gateway publishes: replies, statuses, item
    // errors) comes back as itself, by name; the gateway's own list is not on the wire.
    for (const auto &list : {std::span<const MessageDef *const>(protocolMessages),
                             std::span<const MessageDef *const>(watchMessages),
                             std::span<const MessageDef *const>(mqttMessages)}) {
        for (const MessageDef *def : list) {
            Message m{*def, {}};
            for (int i = 1; i <= def->argc; ++i)
                m.args.emplace_back(std::to_string(i));
            const std::optional<Message> back = MessageJson::fromJson(MessageJson::toJson(m));
            QVERIFY2(back && *back == m, def->name);
        }
    }
}

void TestMqtt::messageJsonFallsBackToEnglish()
{
    // A newer gateway's id this program does not know: its English text, verbatim.
    const QJsonObject unknown{{QStringLiteral("id"), QStringLiteral("SomethingNew")},
                              {QStringLiteral("args"), QJsonArray{}},
                              {QStringLiteral("text"), QStringLiteral("Something new happened")}};
    const std::optional<Message> message = MessageJson::fromJson(unknown);
    QVERIFY(message);
    QCOMPARE(englishText(*message), QStringLiteral("Something new happened"));
    // Wrong argument count for a known id: the same.
    const QJsonObject wrongArgs{{QStringLiteral("id"), QStringLiteral("MqttUrlInvalid")},
                                {QStringLiteral("args"), QJsonArray{}},
                                {QStringLiteral("text"), QStringLiteral("bad url")}};
    QCOMPARE(englishText(*MessageJson::fromJson(wrongArgs)), QStringLiteral("bad url"));
    QVERIFY(!MessageJson::fromJson(QJsonObject{}));
}

void TestMqtt::itemPayloadFloat()
{
    WatchItemSpec spec;
    spec.address = addr("R100");
    spec.station = 2;
    spec.format = DisplayFormat::Float32;
    spec.name = QStringLiteral("Tank level");
    const ItemValues item(spec);
    const std::uint32_t bits = floatBits(12.5f);
    const std::vector<std::uint32_t> words{bits & 0xFFFF, bits >> 16};
    const QDateTime time = QDateTime::fromMSecsSinceEpoch(1764111600123, Qt::UTC);
    const QByteArray payload
        = GatewayPayload::encodeItem(item, words, ValueQuality::Good, time, {});

    const QJsonObject json = QJsonDocument::fromJson(payload).object();
    QCOMPARE(json.value(QStringLiteral("value")).toDouble(), 12.5);
    QCOMPARE(json.value(QStringLiteral("text")).toString(), QStringLiteral("12.5"));
    QCOMPARE(json.value(QStringLiteral("time")).toString(),
             QStringLiteral("2025-11-25T23:00:00.123Z"));
    QVERIFY(!json.contains(QStringLiteral("error")));

    const auto decoded = GatewayPayload::decodeItem(payload);
    QVERIFY(decoded);
    QCOMPARE(decoded->station, 2);
    QCOMPARE(decoded->address, addr("R100"));
    QCOMPARE(decoded->format, DisplayFormat::Float32);
    QCOMPARE(decoded->name, QStringLiteral("Tank level"));
    QCOMPARE(decoded->words, words);
    QCOMPARE(decoded->quality, ValueQuality::Good);
    QCOMPARE(decoded->time, time);
}

void TestMqtt::itemPayloadSignedBitAndNan()
{
    WatchItemSpec spec;
    spec.address = addr("R5");
    spec.format = DisplayFormat::Signed;
    const QDateTime now = QDateTime::currentDateTimeUtc();
    QJsonObject json
        = QJsonDocument::fromJson(
              GatewayPayload::encodeItem(ItemValues(spec), {0xFFFB}, ValueQuality::Good, now, {}))
              .object();
    QCOMPARE(json.value(QStringLiteral("value")).toDouble(), -5.0);

    spec.address = addr("Y3");
    spec.format = DisplayFormat::Bit;
    const Message why = msg<MsgId::MqttClosed>("mqtt://x");
    const QByteArray stale
        = GatewayPayload::encodeItem(ItemValues(spec), {1}, ValueQuality::Stale, now, why);
    json = QJsonDocument::fromJson(stale).object();
    QCOMPARE(json.value(QStringLiteral("value")).toBool(), true);
    QCOMPARE(json.value(QStringLiteral("quality")).toString(), QStringLiteral("stale"));
    const auto decoded = GatewayPayload::decodeItem(stale);
    QVERIFY(decoded);
    QVERIFY(decoded->error == why);

    spec.address = addr("R0");
    spec.format = DisplayFormat::Float32;
    json = QJsonDocument::fromJson(GatewayPayload::encodeItem(ItemValues(spec), {0x0000, 0x7FC0},
                                                              ValueQuality::Good, now, {}))
               .object();
    QVERIFY(json.value(QStringLiteral("value")).isNull());
    QCOMPARE(json.value(QStringLiteral("text")).toString(), QStringLiteral("NaN"));

    // Never read: no words, and no value or text invented for them; Qt writes the same bytes.
    const QByteArray never
        = GatewayPayload::encodeItem(ItemValues(spec), {}, ValueQuality::Stale, now, why);
    const QJsonDocument document = QJsonDocument::fromJson(never);
    QCOMPARE(document.toJson(QJsonDocument::Compact), never);
    json = document.object();
    QVERIFY(json.value(QStringLiteral("value")).isNull());
    QVERIFY(json.value(QStringLiteral("text")).isNull());
    QCOMPARE(json.value(QStringLiteral("words")).toArray().size(), 0);
    const auto decodedNever = GatewayPayload::decodeItem(never);
    QVERIFY(decodedNever);
    QVERIFY(decodedNever->words.empty());
    QCOMPARE(decodedNever->quality, ValueQuality::Stale);
}

void TestMqtt::itemPayloadRejectsGarbage()
{
    for (const char *payload :
         {"", "not json", "[]", "{}",
          R"({"station":1,"address":"R70000","quality":"good","format":"signed","words":[1]})",
          R"({"station":1,"address":"R1","quality":"fine","format":"signed","words":[1]})",
          R"({"station":1,"address":"R1","quality":"good","format":"signed","words":[-1]})",
          R"({"station":1,"address":"R1","quality":"good","format":"signed","words":[1,2,3,4,5]})",
          R"({"station":300,"address":"R1","quality":"good","format":"signed","words":[1]})"})
        QVERIFY2(!GatewayPayload::decodeItem(QByteArray(payload)), payload);
}

void TestMqtt::itemPayloadIsQtsJson_data()
{
    QTest::addColumn<QString>("address");
    QTest::addColumn<DisplayFormat>("format");
    QTest::addColumn<QString>("name");
    QTest::addColumn<std::vector<std::uint32_t>>("words");
    QTest::addColumn<int>("quality");

    const QString awkward = QStringLiteral("Tank \"A\" \\ level\n\t") + QChar(0x01) + QChar(0x7F)
                            + QStringLiteral(" é 漢 😀 ") + QChar(0xD800) + QStringLiteral("end");
    const std::uint32_t f = floatBits(12.5f);
    QTest::newRow("float, awkward name")
        << "R100" << DisplayFormat::Float32 << awkward
        << std::vector<std::uint32_t>{f & 0xFFFF, f >> 16} << int(ValueQuality::Good);
    const std::uint32_t tiny = floatBits(-3.75e-5f);
    QTest::newRow("float, small") << "D10" << DisplayFormat::Float32 << QString()
                                  << std::vector<std::uint32_t>{tiny & 0xFFFF, tiny >> 16}
                                  << int(ValueQuality::Good);
    const std::uint32_t large = floatBits(1e17f);
    QTest::newRow("float, large integral")
        << "R12" << DisplayFormat::Float32 << QString()
        << std::vector<std::uint32_t>{large & 0xFFFF, large >> 16} << int(ValueQuality::Good);
    QTest::newRow("float NaN") << "R0" << DisplayFormat::Float32 << QStringLiteral("n")
                               << std::vector<std::uint32_t>{0x0000, 0x7FC0}
                               << int(ValueQuality::Good);
    QTest::newRow("double 1e20") << "R20" << DisplayFormat::Double64 << QStringLiteral("big")
                                 << std::vector<std::uint32_t>{0x0000, 0x1E44, 0xB5A5, 0x4415}
                                 << int(ValueQuality::Good);
    QTest::newRow("unsigned 32") << "DR30" << DisplayFormat::Unsigned << QString()
                                 << std::vector<std::uint32_t>{0xFFFFFFFF}
                                 << int(ValueQuality::Good);
    QTest::newRow("signed") << "R5" << DisplayFormat::Signed << QString()
                            << std::vector<std::uint32_t>{0xFFFB} << int(ValueQuality::Good);
    QTest::newRow("hex") << "R6" << DisplayFormat::Hex << QString()
                         << std::vector<std::uint32_t>{0xBEEF} << int(ValueQuality::Good);
    QTest::newRow("bcd") << "R7" << DisplayFormat::Bcd << QString()
                         << std::vector<std::uint32_t>{0x1234} << int(ValueQuality::Good);
    QTest::newRow("ascii, quote and tab")
        << "R8" << DisplayFormat::Ascii << QString() << std::vector<std::uint32_t>{0x2209}
        << int(ValueQuality::Good);
    QTest::newRow("bit, stale with reason")
        << "Y3" << DisplayFormat::Bit << QStringLiteral("lamp") << std::vector<std::uint32_t>{1}
        << int(ValueQuality::Stale);
    QTest::newRow("error with reason") << "R9" << DisplayFormat::Signed << QString()
                                       << std::vector<std::uint32_t>{0} << int(ValueQuality::Error);
}

// The encoder writes JSON text itself: it must be what QJsonDocument writes again after reading it,
// byte for byte (valid JSON, keys sorted, same escapes and number forms).
void TestMqtt::itemPayloadIsQtsJson()
{
    QFETCH(QString, address);
    QFETCH(DisplayFormat, format);
    QFETCH(QString, name);
    QFETCH(std::vector<std::uint32_t>, words);
    QFETCH(int, quality);
    WatchItemSpec spec;
    spec.address = addr(address.toLatin1().constData());
    spec.format = format;
    spec.name = name;
    spec.station = 7;
    const ItemValues item(spec);
    QCOMPARE(static_cast<int>(words.size()), item.elementCount());
    const Message why
        = msg<MsgId::MqttLinkLost>("mqtt://b\"roker", Message::text("Connection reset"));
    const QByteArray payload
        = GatewayPayload::encodeItem(item, words, static_cast<ValueQuality>(quality),
                                     QDateTime::fromMSecsSinceEpoch(1764111600123, Qt::UTC), why);
    QJsonParseError error{};
    const QJsonDocument document = QJsonDocument::fromJson(payload, &error);
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    QCOMPARE(document.toJson(QJsonDocument::Compact), payload);
    // The gateway's way: the head written once, the rest per value (issue 35).
    QCOMPARE(GatewayPayload::encodeItem(
                 GatewayPayload::encodeItemHead(item, static_cast<ValueQuality>(quality), why),
                 item, words, QDateTime::fromMSecsSinceEpoch(1764111600123, Qt::UTC)),
             payload);
    const auto decoded = GatewayPayload::decodeItem(payload);
    QVERIFY(decoded);
    QCOMPARE(decoded->name, name);
    QCOMPARE(decoded->words, words);
    QCOMPARE(decoded->text, item.text(item.join(words)));
    QCOMPARE(decoded->error == why, quality != int(ValueQuality::Good));
}

void TestMqtt::setCommands()
{
    Message error;
    auto command = GatewayPayload::decodeSet(" 12.5\n", &error);
    QVERIFY(command);
    QCOMPARE(command->value, QStringLiteral("12.5"));
    QVERIFY(!command->format);

    command = GatewayPayload::decodeSet(R"({"value":true,"id":"a1"})", &error);
    QVERIFY(command);
    QCOMPARE(command->value, QStringLiteral("ON"));
    QCOMPARE(command->id, QStringLiteral("a1"));

    command
        = GatewayPayload::decodeSet(R"({"value":-7,"format":"signed","swapWords":true})", &error);
    QVERIFY(command);
    QCOMPARE(command->value, QStringLiteral("-7"));
    QCOMPARE(command->format, DisplayFormat::Signed);
    QCOMPARE(command->swapWords, true);
    const auto again = GatewayPayload::decodeSet(GatewayPayload::encodeSet(*command), &error);
    QVERIFY(again);
    QCOMPARE(again->value, command->value);
    QCOMPARE(again->format, command->format);

    QVERIFY(!GatewayPayload::decodeSet("{broken", &error));
    QCOMPARE(englishText(error),
             QStringLiteral("The command starts with { but is not a JSON object."));
    QVERIFY(!GatewayPayload::decodeSet(R"({"value":"1","format":"quad"})", &error));
    QCOMPARE(englishText(error), QStringLiteral("\"quad\" is not a value format."));
    // A boolean key with another value is refused, not read as false (issue 33).
    QVERIFY(!GatewayPayload::decodeSet(R"({"value":"1","swapWords":"yes"})", &error));
    QCOMPARE(englishText(error), QStringLiteral("\"swapWords\" must be true or false."));
    QVERIFY(!GatewayPayload::decodeSet("  ", &error));
    QVERIFY(!GatewayPayload::decodeSet(R"({"id":"x"})", &error));

    // The raw value, as the studio sends a typed one: words win over a value.
    GatewayPayload::SetCommand raw;
    raw.words = std::vector<std::uint32_t>{0, 0x3FC0, 4294967295u};
    raw.format = DisplayFormat::Float32;
    raw.id = QStringLiteral("r1");
    const QByteArray encoded = GatewayPayload::encodeSet(raw);
    QVERIFY2(!encoded.contains("\"value\""), encoded.constData());
    command = GatewayPayload::decodeSet(encoded, &error);
    QVERIFY(command);
    QCOMPARE(command->words, raw.words);
    QCOMPARE(command->format, DisplayFormat::Float32);
    QCOMPARE(command->id, QStringLiteral("r1"));
    command = GatewayPayload::decodeSet(R"({"words":[5],"value":"7"})", &error);
    QVERIFY(command);
    QCOMPARE(command->words, std::optional(std::vector<std::uint32_t>{5}));
    for (const char *bad : {R"({"words":[]})", R"({"words":[-1]})", R"({"words":[4294967296]})",
                            R"({"words":[0.5]})", R"({"words":["1"]})", R"({"words":7})"}) {
        QVERIFY2(!GatewayPayload::decodeSet(bad, &error), bad);
        QCOMPARE(error.id, MsgId::GatewaySetBadWords);
    }

    // Issue 48: two equal keys are refused (QJsonDocument kept the last: 100, not 1), and an id
    // the reply could not give back as it was (an object became "").
    QVERIFY(!GatewayPayload::decodeSet(R"({"value":1,"id":"d","value":100})", &error));
    QCOMPARE(englishText(error), QStringLiteral("line 1: duplicate key \"value\""));
    QVERIFY(!GatewayPayload::decodeSet("{\"words\":[1],\n\"words\":[2]}", &error));
    QCOMPARE(englishText(error), QStringLiteral("line 2: duplicate key \"words\""));
    for (const char *bad : {R"({"value":1,"id":{"a":1}})", R"({"value":1,"id":[1]})",
                            R"({"value":1,"id":true})", R"({"value":1,"id":null})"}) {
        QVERIFY2(!GatewayPayload::decodeSet(bad, &error), bad);
        QCOMPARE(englishText(error), QStringLiteral("\"id\" must be text or a number."));
    }
    command = GatewayPayload::decodeSet(R"({"value":1,"id":42})", &error);
    QVERIFY(command);
    QCOMPARE(command->id, QStringLiteral("42"));
    // Equal values under different keys are no duplicate keys.
    QVERIFY(GatewayPayload::decodeSet(R"({"value":"1","id":"1","format":"signed"})", &error));
}

void TestMqtt::replyAndStatusRoundTrip()
{
    GatewayPayload::Reply reply;
    reply.id = QStringLiteral("42");
    reply.ok = false;
    reply.station = 1;
    reply.address = addr("R100");
    reply.value = QStringLiteral("5");
    reply.error = msg<MsgId::MqttClosed>("mqtt://x");
    reply.time = QDateTime::fromMSecsSinceEpoch(1000, Qt::UTC);
    const auto back = GatewayPayload::decodeReply(GatewayPayload::encodeReply(reply));
    QVERIFY(back);
    QCOMPARE(back->id, reply.id);
    QCOMPARE(back->ok, false);
    QCOMPARE(back->address, reply.address);
    QVERIFY(back->error == reply.error);
    QCOMPARE(back->time, reply.time);

    GatewayPayload::Status status;
    status.state = GatewayPayload::LinkStatus::Down;
    status.link = QStringLiteral("TCP 127.0.0.1:500, FACON");
    status.reason = msg<MsgId::MqttClosed>("mqtt://y");
    status.time = reply.time;
    const auto statusBack = GatewayPayload::decodeStatus(GatewayPayload::encodeStatus(status));
    QVERIFY(statusBack);
    QCOMPARE(statusBack->state, GatewayPayload::LinkStatus::Down);
    QCOMPARE(statusBack->link, status.link);
    QVERIFY(statusBack->reason == status.reason);
    QVERIFY(!GatewayPayload::decodeStatus(R"({"state":"sleeping"})"));
}

void TestMqtt::clientPublishesAndReceivesRetained()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));

    MqttClient publisher(settingsFor(broker));
    QSignalSpy publisherUp(&publisher, &MqttClient::connected);
    QVERIFY(publisher.open());
    QVERIFY(publisherUp.wait(5000));
    QVERIFY(publisher.isConnected());
    QVERIFY(publisher.publish(QStringLiteral("fatek/t/1/R0"), "retained-one", 1, true));
    QVERIFY(publisher.publish(QStringLiteral("fatek/t/1/R1"), "not retained", 0, false));
    QTRY_COMPARE_WITH_TIMEOUT(publisher.outstanding(), 0, 5000);

    // A subscriber coming later gets the retained message (and only that one).
    MqttClient subscriber(settingsFor(broker));
    Inbox inbox;
    inbox.connect(&subscriber);
    subscriber.subscribe(QStringLiteral("fatek/t/+/+"));
    QVERIFY(subscriber.open());
    QTRY_COMPARE_WITH_TIMEOUT(inbox.last.value(QStringLiteral("fatek/t/1/R0")),
                              QByteArray("retained-one"), 5000);
    QCOMPARE(inbox.retained.value(QStringLiteral("fatek/t/1/R0")), true);
    QVERIFY(!inbox.last.contains(QStringLiteral("fatek/t/1/R1")));

    // Live messages arrive as they are published.
    QVERIFY(publisher.publish(QStringLiteral("fatek/t/1/R1"), "live", 0, false));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.last.value(QStringLiteral("fatek/t/1/R1")), QByteArray("live"),
                              5000);
    QCOMPARE(inbox.retained.value(QStringLiteral("fatek/t/1/R1")), false);

    // Not connected: publish says so and keeps nothing.
    publisher.close();
    QVERIFY(!publisher.isConnected());
    QVERIFY(!publisher.publish(QStringLiteral("fatek/t/1/R2"), "lost", 0, false));
}

void TestMqtt::clientRefusedConnectionSaysWhy()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    broker.stop(); // the port is known and nobody listens on it

    MqttClient client(settingsFor(broker));
    QSignalSpy down(&client, &MqttClient::disconnected);
    QVERIFY(client.open());
    QVERIFY(down.wait(5000));
    const QString reason = englishText(down.first().first().value<Message>());
    QVERIFY2(reason.startsWith(
                 QStringLiteral("Cannot reach the broker %1:").arg(settingsFor(broker).toUrl())),
             qPrintable(reason));
    QVERIFY2(reason.contains(QStringLiteral("refused"), Qt::CaseInsensitive), qPrintable(reason));
    // It keeps trying: more attempts follow (50 ms, then 100, 200 ...).
    QTRY_VERIFY_WITH_TIMEOUT(down.count() >= 3, 5000);
    QVERIFY(!client.isConnected());

    // The broker comes up: the client connects by itself.
    QSignalSpy up(&client, &MqttClient::connected);
    QVERIFY2(broker.start(&error), qPrintable(error));
    QVERIFY(up.wait(5000));
}

void TestMqtt::clientWrongPasswordSaysWhy()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    // Anonymous access off and no password file: every login is refused as not authorised.
    QVERIFY2(broker.start(&error, QStringLiteral("allow_anonymous false")), qPrintable(error));

    MqttBrokerSettings settings = settingsFor(broker);
    settings.username = QStringLiteral("op");
    settings.password = QStringLiteral("wrong");
    MqttClient client(settings);
    QSignalSpy down(&client, &MqttClient::disconnected);
    QVERIFY(client.open());
    QVERIFY(down.wait(5000));
    const QString reason = englishText(down.first().first().value<Message>());
    QVERIFY2(reason.startsWith(QStringLiteral("The broker %1 refused us:").arg(settings.toUrl())),
             qPrintable(reason));
    QVERIFY2(reason.contains(QStringLiteral("authori"), Qt::CaseInsensitive), qPrintable(reason));
    QVERIFY(!client.isConnected());
}

void TestMqtt::clientReconnectsAfterBrokerRestart()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));

    MqttClient client(settingsFor(broker));
    Inbox inbox;
    inbox.connect(&client);
    client.subscribe(QStringLiteral("fatek/r/#"));
    QSignalSpy up(&client, &MqttClient::connected);
    QSignalSpy down(&client, &MqttClient::disconnected);
    QVERIFY(client.open());
    QVERIFY(up.wait(5000));

    broker.kill();
    QVERIFY(down.wait(5000));
    const QString reason = englishText(down.first().first().value<Message>());
    QVERIFY2(reason.startsWith(QStringLiteral("Link to the broker")), qPrintable(reason));
    QVERIFY(!client.isConnected());

    QVERIFY2(broker.start(&error), qPrintable(error));
    QTRY_VERIFY_WITH_TIMEOUT(up.count() == 2, 10000);
    // Subscribed again: a message published now arrives.
    MqttClient publisher(settingsFor(broker));
    QSignalSpy publisherUp(&publisher, &MqttClient::connected);
    QVERIFY(publisher.open());
    QVERIFY(publisherUp.wait(5000));
    QVERIFY(publisher.publish(QStringLiteral("fatek/r/x"), "after restart"));
    QTRY_COMPARE_WITH_TIMEOUT(inbox.last.value(QStringLiteral("fatek/r/x")),
                              QByteArray("after restart"), 5000);
}

// A broker that stops answering (SIGSTOP: its socket stays open) is given up after the
// keep-alive, and the reason says so (issue 33: libmosquitto's own text is "Unknown error").
void TestMqtt::clientStalledBrokerSaysKeepalive()
{
#ifndef Q_OS_UNIX
    QSKIP("stopping the broker (SIGSTOP) has no Windows counterpart");
#else
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    MqttBrokerSettings settings = settingsFor(broker);
    settings.keepAliveSec = 5; // the library's least
    MqttClient client(settings);
    QSignalSpy up(&client, &MqttClient::connected);
    QSignalSpy down(&client, &MqttClient::disconnected);
    QVERIFY(client.open());
    QVERIFY(up.wait(5000));
    const auto pid = static_cast<pid_t>(broker.processId());
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid, SIGSTOP), 0);
    const auto resume = qScopeGuard([pid] { ::kill(pid, SIGCONT); });
    QTRY_VERIFY_WITH_TIMEOUT(!down.isEmpty(), 20000);
    const QString reason = englishText(down.first().first().value<Message>());
    QVERIFY2(reason.endsWith(QStringLiteral("lost: keep-alive timeout: the broker did not answer "
                                            "within 5 s")),
             qPrintable(reason));
#endif
}

// Clients that lose the broker in the same instant try again at spread instants (issue 33: a
// gateway's links, all with the same backoff, hit a restarted broker together).
void TestMqtt::clientsDoNotReconnectInLockstep()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    MqttBrokerSettings settings = settingsFor(broker);
    settings.reconnectMinMs = 400;
    settings.reconnectMaxMs = 400;
    constexpr int Clients = 8;
    std::vector<std::unique_ptr<MqttClient>> clients;
    std::vector<std::vector<qint64>> downs(Clients); // when each reported a loss or a failed try
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < Clients; ++i) {
        clients.push_back(std::make_unique<MqttClient>(settings));
        connect(clients.back().get(), &MqttClient::disconnected, this, [&downs, &clock, i] {
            downs[static_cast<std::size_t>(i)].push_back(clock.elapsed());
        });
        QVERIFY(clients.back()->open());
    }
    for (const auto &client : clients)
        QTRY_VERIFY_WITH_TIMEOUT(client->isConnected(), 5000);
    // The loss, then the first try again (refused at once), after the backoff: 300..500 ms.
    // Measured from the kill, which is between these two instants (under Wine the broker's
    // wrapper kills it within 100 ms of being told) and comes before every client's loss. Not
    // from the loss report: the reports reach this thread late under load, the loss report up to
    // 130 ms more than the try's under Wine, and the delay between them came out short (270 ms).
    const qint64 killing = clock.elapsed();
    broker.kill();
    const qint64 killed = clock.elapsed();
    QTRY_VERIFY_WITH_TIMEOUT(
        std::all_of(downs.cbegin(), downs.cend(), [](const auto &d) { return d.size() >= 2; }),
        10000);
    std::vector<qint64> tries;
    for (const auto &d : downs)
        tries.push_back(d[1]);
    const auto [least, most] = std::minmax_element(tries.cbegin(), tries.cend());
    QVERIFY2(*least - killing >= 300 && *most - killed <= 600,
             qPrintable(QStringLiteral("%1..%2 after the kill (%3 ms to kill)")
                            .arg(*least - killing)
                            .arg(*most - killed)
                            .arg(killed - killing)));
    // Without jitter all eight wait 400 ms, within a few ms of each other.
    QVERIFY2(*most - *least >= 40, qPrintable(QStringLiteral("%1..%2").arg(*least).arg(*most)));
}

QTEST_GUILESS_MAIN(TestMqtt)
// A burst handed over faster than the network thread writes: publish() queues, the network thread
// writes whole batches (one wake-up each), the subscriber gets batches handed over. Nothing may be
// lost, doubled or reordered on the way, and the count of outstanding messages returns to 0.
void TestMqtt::clientBurstArrivesWholeAndInOrder()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    NumberedFeed feed(broker);
    feed.start(QStringLiteral("fatek/burst"));
    if (QTest::currentTestFailed())
        return;
    MqttClient &publisher = feed.publisher;
    const QList<int> &received = feed.received;

    constexpr int Count = 20000;
    int peak = 0;
    for (int i = 0; i < Count; ++i) {
        QVERIFY(publisher.publish(QStringLiteral("fatek/burst"), QByteArray::number(i)));
        peak = std::max(peak, publisher.outstanding());
    }
    QVERIFY2(peak > 1, "every publish() was written before the next: not a burst");
    // Time to drain (a liveness bound; speed is bench/'s): every socket call under Wine goes
    // through wineserver, and 20,000 messages took 10.5 s there on a busy 2-core machine.
    const int scale = TestUtil::underWine() ? 3 : 1;
    QTRY_COMPARE_WITH_TIMEOUT(publisher.outstanding(), 0, 10000 * scale);
    QTRY_COMPARE_WITH_TIMEOUT(received.size(), Count, 20000 * scale);
    for (int i = 0; i < Count; ++i)
        QCOMPARE(received.at(i), i);
}

// Issue 35: a broker that stops reading (SIGSTOP) while retained QoS 0 states keep coming. Once
// the socket holds all it takes, the states wait in the client's queue, where a newer state of a
// topic replaces the one waiting (counted as superseded): the queue stops growing, and when the
// broker reads again the newest state of every topic arrives, and fewer messages than were
// published.
void TestMqtt::clientStalledBrokerKeepsNewestPerTopic()
{
#ifndef Q_OS_UNIX
    QSKIP("stopping the broker (SIGSTOP) has no Windows counterpart");
#else
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    MqttClient subscriber(settingsFor(broker));
    QHash<QString, QByteArray> last;
    int received = 0;
    bool probed = false;
    QObject::connect(&subscriber, &MqttClient::messageReceived,
                     [&](const QString &topic, const QByteArray &payload, bool) {
                         if (payload == "probe") {
                             probed = true;
                             return;
                         }
                         ++received;
                         last.insert(topic, payload.left(payload.indexOf('|')));
                     });
    subscriber.subscribe(QStringLiteral("fatek/stall/#"));
    MqttClient publisher(settingsFor(broker));
    QVERIFY(subscriber.open());
    QVERIFY(publisher.open());
    QTRY_VERIFY_WITH_TIMEOUT(publisher.isConnected(), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(
        (publisher.publish(QStringLiteral("fatek/stall/probe"), "probe"), probed), 5000);

    const auto pid = static_cast<pid_t>(broker.processId());
    QVERIFY(pid > 0);
    QCOMPARE(::kill(pid, SIGSTOP), 0);
    auto resume = qScopeGuard([pid] { ::kill(pid, SIGCONT); });
    constexpr int Topics = 5;
    const QByteArray padding(32 * 1024, 'x'); // the socket's buffers fill after a few MB
    const auto topicOf = [](int t) {
        return QStringLiteral("fatek/stall/%1").arg(t);
    };
    int published = 0;
    int round = 0;
    const auto publishRound = [&] {
        for (int t = 0; t < Topics; ++t) {
            QVERIFY(
                publisher.publish(topicOf(t), QByteArray::number(round) + '|' + padding, 0, true));
            ++published;
        }
        ++round;
    };
    // Until the socket takes nothing more: what the network thread did not write in 20 ms stays.
    bool stuck = false;
    while (round < 5000 && !stuck) {
        for (int i = 0; i < 20; ++i)
            publishRound();
        QTest::qWait(20);
        stuck = publisher.outstanding() > 0 && publisher.superseded() >= 3 * Topics;
    }
    QVERIFY2(stuck, qPrintable(QStringLiteral("%1 rounds").arg(round)));
    // Nothing more is queued however many states come: each replaces its topic's.
    QTest::qWait(50);
    const int outstanding = publisher.outstanding();
    const quint64 superseded = publisher.superseded();
    for (int i = 0; i < 100; ++i)
        publishRound();
    // (At most one message per topic more: the outbox may have been empty, the library holding
    // the rest.)
    QVERIFY2(publisher.outstanding() <= outstanding + Topics,
             qPrintable(QStringLiteral("%1 -> %2").arg(outstanding).arg(publisher.outstanding())));
    QVERIFY(publisher.superseded() >= superseded + 99 * Topics);

    resume.dismiss();
    QCOMPARE(::kill(pid, SIGCONT), 0);
    const QByteArray newest = QByteArray::number(round - 1);
    const auto allNewest = [&] {
        for (int t = 0; t < Topics; ++t) {
            if (last.value(topicOf(t)) != newest)
                return false;
        }
        return true;
    };
    QTRY_VERIFY_WITH_TIMEOUT(allNewest(), 20000);
    QTRY_COMPARE_WITH_TIMEOUT(publisher.outstanding(), 0, 10000);
    // Each superseded state was never sent; the rest arrived (QoS 0 over loopback: none lost).
    QTRY_COMPARE_WITH_TIMEOUT(received, published - static_cast<int>(publisher.superseded()),
                              10000);
#endif
}

// The QoS 0 PUBLISH that MqttClient writes itself (MQTT 3.1.1, 3.3 and 2.2.3's length bytes).
void TestMqtt::publishPacketEncoding()
{
    QByteArray out;
    MqttPacket::appendPublishQos0(out, "a/b", "hi", true);
    QCOMPARE(out, QByteArray("\x31\x07\x00\x03"
                             "a/bhi",
                             9));
    out.clear();
    MqttPacket::appendPublishQos0(out, "t", QByteArray(), false);
    QCOMPARE(out, QByteArray("\x30\x03\x00\x01t", 5));
    // The remaining length in 7-bit groups, least significant first: 127, 128, 16,383, 16,384.
    for (const auto &[length, bytes] : {std::pair<int, QByteArray>{127, QByteArray("\x7f")},
                                        {128, QByteArray("\x80\x01")},
                                        {16383, QByteArray("\xff\x7f")},
                                        {16384, QByteArray("\x80\x80\x01")}}) {
        out.clear();
        MqttPacket::appendPublishQos0(out, "t", QByteArray(length - 3, 'x'), false);
        QCOMPARE(out.mid(1, bytes.size()), bytes);
        QCOMPARE(out.size(), 1 + bytes.size() + length);
    }
    QVERIFY(MqttPacket::fitsPublish(QByteArray(0xFFFF, 't'), "x"));
    QVERIFY(!MqttPacket::fitsPublish(QByteArray(0x10000, 't'), "x"));
}

// A reader with a receive window of one batch (issue 35): the network thread stops reading while a
// batch waits for this thread and reads on once it was taken. A burst that the broker keeps whole
// (fewer than its 1000 queued messages) arrives whole and in order, in several batches.
void TestMqtt::clientReceiveWindowReadsOn()
{
    TestUtil::MosquittoBroker broker;
    QString error;
    QVERIFY2(broker.start(&error), qPrintable(error));
    NumberedFeed feed(broker);
    feed.subscriber.setReceiveWindow(1);
    feed.start(QStringLiteral("fatek/window"));
    if (QTest::currentTestFailed())
        return;
    MqttClient &publisher = feed.publisher;
    const QList<int> &received = feed.received;
    constexpr int Count = 500;
    for (int i = 0; i < Count; ++i)
        QVERIFY(publisher.publish(QStringLiteral("fatek/window"), QByteArray::number(i)));
    QTRY_COMPARE_WITH_TIMEOUT(received.size(), Count, 10000);
    for (int i = 0; i < Count; ++i)
        QCOMPARE(received.at(i), i);
}

#include "tst_mqtt.moc"
