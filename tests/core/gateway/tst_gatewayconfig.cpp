// The gateway's configuration file (issue 20): loading, every validation error named with its
// place, and `fatek-gateway --check` (exit codes, summary, one clear error).
#include "core/gateway/gatewayconfig.h"
#include "testutil.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

class TestGatewayConfig : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void loadsEverything();
    void linkAsUrl();
    void allowlistMembership();
    void errors_data();
    void errors();
    void passwordFile();
    void alarmJournal();
    void duplicateKeysNamed();
    void watchListUnknownKeys_data();
    void watchListUnknownKeys();
    void checkValid();
    void checkInvalid();
    void checkUsage();

private:
    QString write(const QString &name, const QByteArray &content);

    QTemporaryDir m_dir;
};

// After the test class: moc reads raw strings as ordinary ones and can lose its way in them.
namespace {

const char *const emptyList
    = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[]})json";
const char *const twiceList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"A","items":[{"address":"R1"},{"address":"R2"},{"address":"R1","format":"hex"}]}]})json";
const char *const badList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"A","items":[{"address":"R1"},{"address":"R2"},{"address":"Q7"}]}]})json";

const char *const watchList = R"json({"format":"fatek-studio-watchlist","version":1,"tables":[
  {"name":"Main","intervalMs":250,"items":[{"address":"R100"},{"address":"R200","format":"float"},
   {"address":"Y0"}]},
  {"name":"Slow","intervalMs":2000,"items":[{"address":"DR10","station":2}]}]})json";

QJsonObject validConfig()
{
    return QJsonDocument::fromJson(R"json({"format":"fatek-gateway","version":1,
      "broker":{"url":"mqtt://127.0.0.1:1883","keepAliveSec":20},
      "prefix":"plant/fatek","readOnly":false,
      "connections":[{"name":"line1",
        "link":{"kind":"tcp","host":"10.0.0.5","port":500,"protocol":"binary","timeoutMs":800,
                "retries":1},
        "watchLists":[{"file":"line1.json"}],
        "allow":["R100..R199","Y0..Y7","M10"],
        "statisticsIntervalMs":2000},
       {"name":"line2",
        "link":{"kind":"serial","portName":"/dev/ttyUSB0","baud":19200,"format":"8N1",
                "protocol":"facon"},
        "watchLists":[{"file":"line1.json","intervalMs":1000}]}]})json")
        .object();
}

// Replaces the value at a path of keys and indexes ("connections", 0, "link", "port").
QJsonValue replaced(const QJsonValue &root, QVariantList path, const QJsonValue &value)
{
    if (path.isEmpty())
        return value;
    const QVariant key = path.takeFirst();
    if (key.typeId() == QMetaType::Int) {
        QJsonArray array = root.toArray();
        array[key.toInt()] = replaced(array.at(key.toInt()), path, value);
        return array;
    }
    QJsonObject object = root.toObject();
    if (path.isEmpty() && value.isUndefined())
        object.remove(key.toString());
    else
        object[key.toString()] = replaced(object.value(key.toString()), path, value);
    return object;
}

} // namespace

QString TestGatewayConfig::write(const QString &name, const QByteArray &content)
{
    QFile file(m_dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        return {};
    return file.fileName();
}

void TestGatewayConfig::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(!write(QStringLiteral("line1.json"), watchList).isEmpty());
    QVERIFY(!write(QStringLiteral("empty.json"), emptyList).isEmpty());
    QVERIFY(!write(QStringLiteral("twice.json"), twiceList).isEmpty());
    QVERIFY(!write(QStringLiteral("bad.json"), badList).isEmpty());
}

void TestGatewayConfig::loadsEverything()
{
    const Result<GatewayConfig> config
        = GatewayConfig::load(QJsonDocument(validConfig()).toJson(), m_dir.path());
    QVERIFY2(config.ok(), config.ok() ? "" : config.error().text().c_str());
    QCOMPARE(config->broker.host, QStringLiteral("127.0.0.1"));
    QCOMPARE(config->broker.port, quint16(1883));
    QCOMPARE(config->broker.keepAliveSec, 20);
    QCOMPARE(config->prefix, QStringLiteral("plant/fatek"));
    QCOMPARE(config->readOnly, false);
    QCOMPARE(config->connections.size(), 2);
    const GatewayConnectionConfig &line1 = config->connections.at(0);
    QCOMPARE(line1.name, QStringLiteral("line1"));
    QCOMPARE(line1.link.kind, LinkSettings::Kind::Tcp);
    QCOMPARE(line1.link.host, QStringLiteral("10.0.0.5"));
    QCOMPARE(line1.link.protocol, LinkSettings::ProtocolChoice::Binary);
    QCOMPARE(line1.link.timeoutMs, 800);
    QCOMPARE(line1.link.retries, 1);
    QVERIFY(line1.link.autoReconnect);
    QCOMPARE(line1.statisticsIntervalMs, 2000);
    QCOMPARE(line1.tables.size(), 2);
    QCOMPARE(line1.tables.at(0).intervalMs, 250); // the file's own intervals ...
    QCOMPARE(line1.tables.at(1).intervalMs, 2000);
    QCOMPARE(line1.itemCount(), 4);
    QCOMPARE(line1.tables.at(1).items.at(0).station, quint8(2));
    QCOMPARE(line1.allow.size(), std::size_t(3));
    const GatewayConnectionConfig &line2 = config->connections.at(1);
    QCOMPARE(line2.link.kind, LinkSettings::Kind::Serial);
    QCOMPARE(line2.link.portName, QStringLiteral("/dev/ttyUSB0"));
    QCOMPARE(line2.link.baudRate, 19200);
    QCOMPARE(line2.link.serialFormat(), QStringLiteral("8N1"));
    QCOMPARE(line2.tables.at(0).intervalMs, 1000); // ... or the override, for every table
    QCOMPARE(line2.tables.at(1).intervalMs, 1000);
    QVERIFY(line2.allow.empty());
    QCOMPARE(line2.statisticsIntervalMs, 5000);
}

void TestGatewayConfig::allowlistMembership()
{
    GatewayConnectionConfig c;
    for (const char *text : {"R100..R199", "WY0..WY32", "M10"})
        c.allow.push_back(*AddressRange::parse(text));
    QVERIFY(c.allows(*Address::parse("R100")));
    QVERIFY(c.allows(*Address::parse("R199")));
    QVERIFY(!c.allows(*Address::parse("R200")));
    QVERIFY(!c.allows(*Address::parse("R99")));
    QVERIFY(!c.allows(*Address::parse("D100"))); // another type, same number
    QVERIFY(c.allows(*Address::parse("WY16")));
    QVERIFY(c.allows(*Address::parse("WY32")));
    QVERIFY(!c.allows(*Address::parse("WY48")));
    QVERIFY(c.allows(*Address::parse("M10")));
    QVERIFY(!c.allows(*Address::parse("M11")));
    QVERIFY(!GatewayConnectionConfig{}.allows(*Address::parse("R100"))); // none: no writes
}

// Issue 32: a connection's link may be the URL fatek-cli --link takes; the same settings come
// out as from the object form, and a station in it (the watch lists' business) is refused.
void TestGatewayConfig::linkAsUrl()
{
    QJsonObject json = replaced(validConfig(), {"connections", 0, "link"},
                                QJsonValue("tcp://10.0.0.5:500?protocol=binary&timeout=800&"
                                           "retries=1"))
                           .toObject();
    json = replaced(json, {"connections", 1, "link"},
                    QJsonValue("serial:///dev/ttyUSB0?baud=19200&format=8N1&protocol=facon"))
               .toObject();
    const Result<GatewayConfig> fromUrl
        = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY2(fromUrl.ok(), fromUrl.ok() ? "" : fromUrl.error().text().c_str());
    const Result<GatewayConfig> fromObject
        = GatewayConfig::load(QJsonDocument(validConfig()).toJson(), m_dir.path());
    QVERIFY(fromObject.ok());
    QCOMPARE(fromUrl->connections.at(0).link, fromObject->connections.at(0).link);
    QCOMPARE(fromUrl->connections.at(1).link, fromObject->connections.at(1).link);

    json = replaced(validConfig(), {"connections", 0, "link"},
                    QJsonValue("tcp://10.0.0.5?station=3"))
               .toObject();
    Result<GatewayConfig> bad = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY(!bad.ok());
    QVERIFY2(QString::fromStdString(bad.error().text())
                 .contains(QLatin1String("no setting \"station\"")),
             bad.error().text().c_str());
    json = replaced(validConfig(), {"connections", 0, "link"}, QJsonValue("10.0.0.5:500"))
               .toObject();
    bad = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY(!bad.ok());
    QVERIFY2(
        QString::fromStdString(bad.error().text()).contains(QLatin1String("start it with tcp://")),
        bad.error().text().c_str());
}

void TestGatewayConfig::errors_data()
{
    QTest::addColumn<QVariantList>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expected");
    const QJsonValue absent = QJsonValue(QJsonValue::Undefined);
    QTest::newRow("format") << QVariantList{"format"} << QJsonValue("fatek-studio-watchlist")
                            << "Not a gateway configuration: \"format\" must be \"fatek-gateway\".";
    QTest::newRow("version") << QVariantList{"version"} << QJsonValue(2)
                             << "Configuration version 2 is not supported (this program reads "
                                "version 1).";
    QTest::newRow("no version") << QVariantList{"version"} << absent << "\"version\" is missing.";
    QTest::newRow("prefix")
        << QVariantList{"prefix"} << QJsonValue("a/+/b")
        << "\"a/+/b\" is not a usable topic prefix: levels separated by '/', "
           "none empty, without '+', '#' or a NUL character, not starting with '$'.";
    // Issue 55: a NUL cut every topic at the broker (the gateway took its own values for
    // commands), a '$' prefix is the broker's and everything published there was dropped.
    QTest::newRow("prefix NUL") << QVariantList{"prefix"}
                                << QJsonValue(QStringLiteral("pl\u0000ant"))
                                << "\"pl\\x00ant\" is not a usable topic prefix: levels separated "
                                   "by '/', none empty, without '+', '#' or a NUL character, not "
                                   "starting with '$'.";
    QTest::newRow("prefix $SYS") << QVariantList{"prefix"} << QJsonValue("$SYS/x")
                                 << "\"$SYS/x\" is not a usable topic prefix";
    QTest::newRow("homeAssistant prefix $")
        << QVariantList{"homeAssistant", "prefix"} << QJsonValue("$ha")
        << "homeAssistant: \"$ha\" is not a usable topic prefix";
    QTest::newRow("readOnly type")
        << QVariantList{"readOnly"} << QJsonValue("yes") << "\"readOnly\" must be true or false.";
    QTest::newRow("homeAssistant discovery type")
        << QVariantList{"homeAssistant", "discovery"} << QJsonValue("yes")
        << "homeAssistant: \"discovery\" must be true or false.";
    QTest::newRow("homeAssistant prefix")
        << QVariantList{"homeAssistant", "prefix"} << QJsonValue("ha/#")
        << "homeAssistant: \"ha/#\" is not a usable topic prefix: levels separated by '/', "
           "none empty, without '+', '#' or a NUL character, not starting with '$'.";
    QTest::newRow("homeAssistant unknown key")
        << QVariantList{"homeAssistant", "discover"} << QJsonValue(true)
        << "homeAssistant: \"discover\" is not a known setting; did you mean \"discovery\"?";
    QTest::newRow("broker url") << QVariantList{"broker", "url"} << QJsonValue("http://x")
                                << "broker: \"http://x\" is not a broker address: write "
                                   "mqtt://host:1883 or mqtts://user@host:8883.";
    QTest::newRow("broker keepalive") << QVariantList{"broker", "keepAliveSec"} << QJsonValue(1)
                                      << "broker: keepAliveSec 1 is out of range (5..65535)";
    QTest::newRow("broker ca") << QVariantList{"broker", "caFile"} << QJsonValue("nothere.pem")
                               << "broker: cannot read the TLS file";
    QTest::newRow("password twice")
        << QVariantList{"broker", "passwordFile"} << QJsonValue("pw")
        << "broker: give the broker \"password\" or a \"passwordFile\", not both.";
    QTest::newRow("no connections") << QVariantList{"connections"} << QJsonValue(QJsonArray())
                                    << "No connections: the configuration needs at least one.";
    QTest::newRow("bad name") << QVariantList{"connections", 1, "name"} << QJsonValue("line 2")
                              << "connection 2 (line 2): \"line 2\" is not a usable connection "
                                 "name";
    QTest::newRow("numeric name") << QVariantList{"connections", 1, "name"} << QJsonValue("12")
                                  << "connection 2 (12): \"12\" is not a usable connection name";
    QTest::newRow("no name") << QVariantList{"connections", 1, "name"} << absent
                             << "connection 2: \"name\" is missing.";
    QTest::newRow("duplicate name")
        << QVariantList{"connections", 1, "name"} << QJsonValue("line1")
        << "connection 2 (line1): the connection name \"line1\" is used twice.";
    QTest::newRow("no link") << QVariantList{"connections", 0, "link"} << absent
                             << "connection 1 (line1): \"link\" is missing.";
    QTest::newRow("host") << QVariantList{"connections", 0, "link", "host"} << QJsonValue(" ")
                          << "connection 1 (line1): link: enter the PLC's IP address or host name.";
    QTest::newRow("port range") << QVariantList{"connections", 0, "link", "port"}
                                << QJsonValue(70000)
                                << "connection 1 (line1): link: port 70000 is out of range "
                                   "(1..65535)";
    QTest::newRow("port type") << QVariantList{"connections", 0, "link", "port"}
                               << QJsonValue("500")
                               << "connection 1 (line1): link: \"port\" must be a whole number.";
    QTest::newRow("kind") << QVariantList{"connections", 0, "link", "kind"} << QJsonValue("can")
                          << "connection 1 (line1): link: \"can\" is not a link kind";
    QTest::newRow("protocol") << QVariantList{"connections", 0, "link", "protocol"}
                              << QJsonValue("modbus")
                              << "connection 1 (line1): link: \"modbus\" is not a protocol";
    QTest::newRow("serial format")
        << QVariantList{"connections", 1, "link", "format"} << QJsonValue("9X1")
        << "connection 2 (line2): link: serial format \"9X1\": data bits "
           "must be 7 or 8, not 9.";
    QTest::newRow("baud") << QVariantList{"connections", 1, "link", "baud"} << QJsonValue(300)
                          << "connection 2 (line2): link: baud rate 300 is out of range (1200 to "
                             "921600).";
    // Issue 55: the range of a link URL's timeout= (the object took 1..60000, the URL 10..60000).
    QTest::newRow("timeout") << QVariantList{"connections", 0, "link", "timeoutMs"} << QJsonValue(5)
                             << "connection 1 (line1): link: timeoutMs 5 is out of range "
                                "(10..60000)";
    // Issue 55, items 3 and 9: what a start refused (or did silently wrong) is refused at load,
    // so by --check, a start and a reload alike.
    QTest::newRow("url unknown setting")
        << QVariantList{"connections", 0, "link"} << QJsonValue("tcp://10.0.0.5?colour=red")
        << "connection 1 (line1): link: link \"tcp://10.0.0.5?colour=red\": no setting "
           "\"colour\" (this link takes protocol, timeout, retries).";
    QTest::newRow("url station")
        << QVariantList{"connections", 1, "link"} << QJsonValue("serial:///dev/ttyUSB0?station=2")
        << "connection 2 (line2): link: link \"serial:///dev/ttyUSB0?station=2\": no setting "
           "\"station\" (this link takes baud, format, flow, protocol, timeout, retries).";
    QTest::newRow("keepalive huge")
        << QVariantList{"broker", "keepAliveSec"} << QJsonValue(1e300) << "broker: keepAliveSec 1";
    QTest::newRow("serial format type")
        << QVariantList{"connections", 1, "link", "format"} << QJsonValue(5)
        << "connection 2 (line2): link: \"format\" must be a string.";
    QTest::newRow("host syntax")
        << QVariantList{"connections", 0, "link", "host"} << QJsonValue("not a host!")
        << "connection 1 (line1): link: \"not a host!\" is not a host: write an IP address "
           "(192.168.1.5) or a host name (letters, digits, '-' and '.').";
    QTest::newRow("url host syntax")
        << QVariantList{"connections", 0, "link"} << QJsonValue("tcp://plc_1..local")
        << "connection 1 (line1): link: \"plc_1..local\" is not a host";
    // Issue 55, item 6: both would be Home Assistant's device plant_fatek_line_1, one
    // connection's entities lost.
    QTest::newRow("discovery ids collide")
        << QVariantList{"connections", 1, "name"} << QJsonValue("line_1")
        << "connection 2 (line_1): connections \"line.1\" and \"line_1\" would get the same Home "
           "Assistant id \"plant_fatek_line_1\"";
    QTest::newRow("ca without tls")
        << QVariantList{"broker", "caFile"} << QJsonValue("line1.json")
        << "broker: caFile is a TLS setting, but the broker URL is mqtt:// (clear text): write "
           "mqtts://, or remove caFile.";
    QTest::newRow("insecure without tls")
        << QVariantList{"broker", "tlsInsecure"} << QJsonValue(true)
        << "broker: tlsInsecure is a TLS setting, but the broker URL is mqtt://";
    QTest::newRow("allow") << QVariantList{"connections", 0, "allow", 1} << QJsonValue("Q1..Q9")
                           << "connection 1 (line1): allow \"Q1..Q9\": ";
    QTest::newRow("allow type") << QVariantList{"connections", 0, "allow", 0} << QJsonValue(5)
                                << "connection 1 (line1): \"allow\" must be a string.";
    QTest::newRow("statistics") << QVariantList{"connections", 0, "statisticsIntervalMs"}
                                << QJsonValue(5)
                                << "connection 1 (line1): statisticsIntervalMs 5 is out of range";
    QTest::newRow("no watch list")
        << QVariantList{"connections", 0, "watchLists"} << QJsonValue(QJsonArray())
        << "connection 1 (line1): nothing to watch: give at least one "
           "watch list with items.";
    QTest::newRow("empty watch list")
        << QVariantList{"connections", 0, "watchLists", 0, "file"} << QJsonValue("empty.json")
        << "connection 1 (line1): nothing to watch";
    QTest::newRow("missing watch list")
        << QVariantList{"connections", 0, "watchLists", 0, "file"} << QJsonValue("gone.json")
        << "connection 1 (line1): watch list gone.json: ";
    QTest::newRow("bad item") << QVariantList{"connections", 0, "watchLists", 0, "file"}
                              << QJsonValue("bad.json")
                              << "connection 1 (line1): watch list bad.json: table 1, item 3: ";
    QTest::newRow("item twice") << QVariantList{"connections", 0, "watchLists", 0, "file"}
                                << QJsonValue("twice.json")
                                << "connection 1 (line1): table 1, item 3: station 1 R1 is "
                                   "watched twice (each address has one topic)";
    // A misspelt or unknown setting is an error at load (issue 33), with the place and the
    // known key it most likely means.
    QTest::newRow("unknown root key")
        << QVariantList{"readonly"} << QJsonValue(true)
        << "\"readonly\" is not a known setting; did you mean \"readOnly\"?";
    QTest::newRow("unknown broker key")
        << QVariantList{"broker", "keepalive"} << QJsonValue(30)
        << "broker: \"keepalive\" is not a known setting; did you mean \"keepAliveSec\"?";
    QTest::newRow("unknown link key")
        << QVariantList{"connections", 0, "link", "hots"} << QJsonValue("10.0.0.6")
        << "connection 1 (line1): link: \"hots\" is not a known setting; did you mean "
           "\"host\"?";
    QTest::newRow("unknown watch list key")
        << QVariantList{"connections", 0, "watchLists", 0, "interval"} << QJsonValue(500)
        << "connection 1 (line1): watch list 1: \"interval\" is not a known setting; did you "
           "mean \"intervalMs\"?";
    QTest::newRow("unknown key, none near")
        << QVariantList{"connections", 1, "colour"} << QJsonValue("red")
        << "connection 2 (line2): \"colour\" is not a known setting.";
    // Issue 50: the alarm journal's file.
    QTest::newRow("journal empty")
        << QVariantList{"alarmJournal"} << QJsonValue(" ") << "\"alarmJournal\" must name a file.";
    QTest::newRow("journal type") << QVariantList{"alarmJournal"} << QJsonValue(true)
                                  << "\"alarmJournal\" must be a string.";
    QTest::newRow("journal misspelt")
        << QVariantList{"alarmjournal"} << QJsonValue("a.db")
        << "\"alarmjournal\" is not a known setting; did you mean \"alarmJournal\"?";
    QTest::newRow("interval") << QVariantList{"connections", 0, "watchLists", 0, "intervalMs"}
                              << QJsonValue(1)
                              << "connection 1 (line1): watch list 1: intervalMs 1 is out of "
                                 "range (10..3600000)";
}

void TestGatewayConfig::errors()
{
    QFETCH(QVariantList, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expected);
    QJsonObject json = validConfig();
    if (QTest::currentDataTag() == QByteArray("password twice"))
        json = replaced(json, {"broker", "password"}, QJsonValue("x")).toObject();
    if (QTest::currentDataTag() == QByteArray("discovery ids collide")) {
        json = replaced(json, {"homeAssistant", "discovery"}, QJsonValue(true)).toObject();
        json = replaced(json, {"connections", 0, "name"}, QJsonValue("line.1")).toObject();
    }
    json = replaced(json, path, value).toObject();
    const Result<GatewayConfig> config
        = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY(!config.ok());
    const QString text = QString::fromStdString(config.error().text());
    QVERIFY2(text.startsWith(expected), qPrintable(text));
}

// Issue 48: QJsonDocument keeps the last of two equal keys, so a configuration that said
// "readOnly":true and then "readOnly":false allowed writes. The key and its line are named, also
// in a watch list the configuration reads.
void TestGatewayConfig::duplicateKeysNamed()
{
    QByteArray json = QJsonDocument(validConfig()).toJson(QJsonDocument::Compact);
    json.replace(R"("readOnly":false)", "\"readOnly\":true,\n\"readOnly\":false");
    Result<GatewayConfig> config = GatewayConfig::load(json, m_dir.path());
    QVERIFY(!config.ok());
    QCOMPARE(QString::fromStdString(config.error().text()),
             QStringLiteral("line 2: duplicate key \"readOnly\""));

    json = QJsonDocument(validConfig()).toJson(QJsonDocument::Compact);
    json.replace(R"("timeoutMs":800)", "\n\n\"timeoutMs\":800,\"timeoutMs\":50");
    config = GatewayConfig::load(json, m_dir.path());
    QVERIFY(!config.ok());
    QCOMPARE(QString::fromStdString(config.error().text()),
             QStringLiteral("line 3: duplicate key \"timeoutMs\""));

    QVERIFY(!write(QStringLiteral("dup.json"),
                   "{\"format\":\"fatek-studio-watchlist\",\"version\":1,\"tables\":[\n"
                   "{\"items\":[{\"address\":\"R1\",\"address\":\"R2\"}]}]}")
                 .isEmpty());
    QJsonObject withList = validConfig();
    withList
        = replaced(withList, {"connections", 0, "watchLists", 0, "file"}, QJsonValue("dup.json"))
              .toObject();
    config = GatewayConfig::load(QJsonDocument(withList).toJson(), m_dir.path());
    QVERIFY(!config.ok());
    const QString text = QString::fromStdString(config.error().text());
    QVERIFY2(text.endsWith(QStringLiteral("dup.json: line 2: duplicate key \"address\"")),
             qPrintable(text));
}

// Issue 55: a watch list's misspelt key once passed --check and ran (R200 read as signed, station 1
// polled instead of 2, interval 500, an empty table). Refused, naming the file, the place, the
// line and the key it most likely means, by the library and by the real program.
void TestGatewayConfig::watchListUnknownKeys_data()
{
    QTest::addColumn<QByteArray>("list");
    QTest::addColumn<QString>("expected");
    const QByteArray head = "{\"format\":\"fatek-studio-watchlist\",\"version\":1,\n\"tables\":[\n";
    const QString item = QStringLiteral("unknown key \"%1\" (known: address, station, format, "
                                        "swapWords, allowNonFinite, name, comment, alarms, "
                                        "history); did you mean \"%2\"?");
    const QString table = QStringLiteral("unknown key \"%1\" (known: name, intervalMs, "
                                         "confirmWrites, items); did you mean \"%2\"?");
    QTest::newRow("fromat") << head + R"({"items":[{"address":"R100"},
{"address":"R200",
"fromat":"float"}]}]})"
                            << "table 1, item 2: line 5: " + item.arg("fromat", "format");
    QTest::newRow("staton") << head + R"({"items":[{"address":"DR10",
"staton":2}]}]})"
                            << "table 1, item 1: line 4: " + item.arg("staton", "station");
    QTest::newRow("swapwords") << head + R"({"items":[{"address":"DR10","format":"float",
"swapwords":true}]}]})"
                               << "table 1, item 1: line 4: " + item.arg("swapwords", "swapWords");
    QTest::newRow("intervalMS") << head + R"({"name":"Fast",
"intervalMS":50,"items":[{"address":"R1"}]}]})"
                                << "table 1: line 4: " + table.arg("intervalMS", "intervalMs");
    QTest::newRow("itmes") << head + R"({"items":[{"address":"R1"}]},
{"name":"Second",
"itmes":[{"address":"R2"}]}]})"
                           << "table 2: line 5: " + table.arg("itmes", "items");
    QTest::newRow("root key")
        << head + R"({"items":[{"address":"R1"}]}],
"tabels":[]})"
        << "line 4: unknown key \"tabels\" (known: format, version, tables, symbols); "
           "did you mean \"tables\"?";
}

void TestGatewayConfig::watchListUnknownKeys()
{
    QFETCH(QByteArray, list);
    QFETCH(QString, expected);
    const QString file = QStringLiteral("hostile-%1.json").arg(QTest::currentDataTag());
    QVERIFY(!write(file, list).isEmpty());
    const QJsonObject json
        = replaced(validConfig(), {"connections", 0, "watchLists", 0, "file"}, QJsonValue(file))
              .toObject();
    const QString message = QStringLiteral("connection 1 (line1): watch list ") + file
                            + QStringLiteral(": ") + expected;
    const Result<GatewayConfig> config
        = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY(!config.ok());
    QCOMPARE(QString::fromStdString(config.error().text()), message);

    const QString path
        = write(QStringLiteral("hostile-gateway.json"), QJsonDocument(json).toJson());
    const TestUtil::ProgramRun run
        = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", path});
    QCOMPARE(run.code, 2);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(run.err.trimmed(),
             QStringLiteral("fatek-gateway: ") + path + QStringLiteral(": ") + message);
}

void TestGatewayConfig::passwordFile()
{
    const QString file = write(QStringLiteral("secret.txt"), "s3cret\n");
    QVERIFY(!file.isEmpty());
    QJsonObject json = replaced(validConfig(), {"broker", "username"}, QJsonValue("op")).toObject();
    json = replaced(json, {"broker", "passwordFile"}, QJsonValue("secret.txt")).toObject();
    const Result<GatewayConfig> config
        = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY2(config.ok(), config.ok() ? "" : config.error().text().c_str());
    QCOMPARE(config->broker.username, QStringLiteral("op"));
    QCOMPARE(config->broker.password, QStringLiteral("s3cret"));
}

// Issue 50: "alarmJournal" relative to the configuration file; absent, systemd's state
// directory, else beside the configuration file.
void TestGatewayConfig::alarmJournal()
{
    QJsonObject json
        = replaced(validConfig(), {"alarmJournal"}, QJsonValue("alarms/j.db")).toObject();
    Result<GatewayConfig> config = GatewayConfig::load(QJsonDocument(json).toJson(), m_dir.path());
    QVERIFY(config.ok());
    QCOMPARE(config->alarmJournal, m_dir.filePath(QStringLiteral("alarms/j.db")));
    QCOMPARE(config->alarmCount(), 0);
    const QByteArray state = qgetenv("STATE_DIRECTORY");
    qunsetenv("STATE_DIRECTORY");
    config = GatewayConfig::load(QJsonDocument(validConfig()).toJson(), m_dir.path());
    QVERIFY(config.ok());
    QCOMPARE(config->alarmJournal, m_dir.filePath(QStringLiteral("alarms.db")));
    qputenv("STATE_DIRECTORY", "/var/lib/fatek-gateway:/var/lib/other");
    QCOMPARE(GatewayConfig::defaultAlarmJournal(m_dir.path()),
             QStringLiteral("/var/lib/fatek-gateway/alarms.db"));
    if (state.isNull())
        qunsetenv("STATE_DIRECTORY");
    else
        qputenv("STATE_DIRECTORY", state);
}

void TestGatewayConfig::checkValid()
{
    const QString path
        = write(QStringLiteral("gateway.json"), QJsonDocument(validConfig()).toJson());
    TestUtil::ProgramRun run
        = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", path});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.err.isEmpty(), qPrintable(run.err));
    const QStringList lines = run.lines();
    QCOMPARE(lines.value(0), path + QStringLiteral(": OK"));
    QVERIFY2(lines.contains(QStringLiteral("broker     mqtt://127.0.0.1")), qPrintable(run.out));
    QVERIFY2(lines.contains(QStringLiteral("discovery  off")), qPrintable(run.out));
    QVERIFY2(lines.contains(QStringLiteral(
                 "connection line1: TCP 10.0.0.5:500, binary, 4 items in 2 tables, writes "
                 "allowed: R100-199, Y0-7, M10")),
             qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("connection line2: "))
                 && run.out.contains(QStringLiteral("writes allowed: none (no writes)")),
             qPrintable(run.out));

    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH),
                               {"--check", "--read-only", path});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.lines().contains(QStringLiteral("read-only  yes")), qPrintable(run.out));
    QVERIFY(!run.out.contains(QStringLiteral("R100-199")));

    // Home Assistant discovery on: --check says so, with the prefix.
    QJsonObject discovery = validConfig();
    discovery[QStringLiteral("homeAssistant")]
        = QJsonObject{{QStringLiteral("discovery"), true}, {QStringLiteral("prefix"), "ha"}};
    const QString discoveryPath
        = write(QStringLiteral("discovery.json"), QJsonDocument(discovery).toJson());
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", discoveryPath});
    QCOMPARE(run.code, 0);
    QVERIFY2(run.lines().contains(QStringLiteral("discovery  Home Assistant, under ha/")),
             qPrintable(run.out));
}

void TestGatewayConfig::checkInvalid()
{
    const QString path = write(
        QStringLiteral("bad-port.json"),
        QJsonDocument(replaced(validConfig(), {"connections", 0, "link", "port"}, 70000).toObject())
            .toJson());
    TestUtil::ProgramRun run
        = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", path});
    QCOMPARE(run.code, 2);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(run.err.trimmed(), QStringLiteral("fatek-gateway: ") + path
                                    + QStringLiteral(": connection 1 (line1): link: port 70000 "
                                                     "is out of range (1..65535)"));
    QCOMPARE(run.err.count(u'\n'), 1); // one line

    // The misspelling that once left writes enabled while --check said "read-only no".
    const QString misspelt
        = write(QStringLiteral("misspelt.json"),
                QJsonDocument(replaced(validConfig(), {"readonly"}, true).toObject()).toJson());
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", misspelt});
    QCOMPARE(run.code, 2);
    QVERIFY(run.out.isEmpty());
    QCOMPARE(run.err.trimmed(),
             QStringLiteral("fatek-gateway: ") + misspelt
                 + QStringLiteral(": \"readonly\" is not a known setting; did you mean "
                                  "\"readOnly\"?"));

    const QString garbage = write(QStringLiteral("garbage.json"), "{\"format\":");
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--check", garbage});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(QStringLiteral("The configuration is not a JSON object")),
             qPrintable(run.err));

    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH),
                               {"--check", m_dir.filePath(QStringLiteral("missing.json"))});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(QStringLiteral("Cannot read ")), qPrintable(run.err));
}

void TestGatewayConfig::checkUsage()
{
    TestUtil::ProgramRun run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(QStringLiteral("give one configuration file")), qPrintable(run.err));
    // An unknown option is a usage error: exit 2, in the words of the other programs.
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--bogus", "x.json"});
    QCOMPARE(run.code, 2);
    QVERIFY2(run.err.contains(QStringLiteral("Unknown option --bogus (see --help).")),
             qPrintable(run.err));
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--help"});
    QCOMPARE(run.code, 0);
    for (const char *option : {"--check", "--read-only", "--version"})
        QVERIFY2(run.out.contains(QLatin1StringView(option)), option);
    run = TestUtil::runProgram(QStringLiteral(FATEK_GATEWAY_PATH), {"--version"});
    QCOMPARE(run.code, 0);
    QVERIFY(run.out.startsWith(QStringLiteral("fatek-gateway ")));
}

QTEST_GUILESS_MAIN(TestGatewayConfig)
#include "tst_gatewayconfig.moc"
