// LinkSettings' serial format ("7E1"): the one parser fatek-sim, fatek-cli (--data --parity
// --stop) and the summary text share.
#include "core/transport/linksettings.h"

#include <QTest>

using namespace Fatek;
using Parity = LinkSettings::Parity;

class TestLinkSettings : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parse_data();
    void parse();
    void reject_data();
    void reject();
    void formatRoundTrip();
    void parts();
    void urls_data();
    void urls();
    void badUrls_data();
    void badUrls();
};

void TestLinkSettings::parse_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("dataBits");
    QTest::addColumn<int>("parity");
    QTest::addColumn<int>("stopBits");
    QTest::newRow("7E1") << "7E1" << 7 << int(Parity::Even) << 1;
    QTest::newRow("8N1") << "8N1" << 8 << int(Parity::None) << 1;
    QTest::newRow("8N2") << "8N2" << 8 << int(Parity::None) << 2;
    QTest::newRow("7O2") << "7O2" << 7 << int(Parity::Odd) << 2;
    QTest::newRow("lower case") << "8e1" << 8 << int(Parity::Even) << 1;
    QTest::newRow("blanks") << " 7N2 " << 7 << int(Parity::None) << 2;
}

void TestLinkSettings::parse()
{
    QFETCH(QString, text);
    QFETCH(int, dataBits);
    QFETCH(int, parity);
    QFETCH(int, stopBits);
    LinkSettings s = LinkSettings::serial(QStringLiteral("/dev/ttyS0"));
    s.dataBits = 5; // not a value any format gives: the parser must set every field
    s.stopBits = 9;
    s.parity = parity == int(Parity::Odd) ? Parity::Even : Parity::Odd;
    QCOMPARE(s.setSerialFormat(text), QString());
    QCOMPARE(s.dataBits, dataBits);
    QCOMPARE(int(s.parity), parity);
    QCOMPARE(s.stopBits, stopBits);
}

void TestLinkSettings::reject_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("9X3") << "9X3"
                         << "Serial format \"9X3\": data bits must be 7 or 8, not 9.";
    QTest::newRow("bad parity") << "8X1"
                                << "Serial format \"8X1\": parity must be N, E or O, not X.";
    QTest::newRow("bad stop") << "7E3"
                              << "Serial format \"7E3\": stop bits must be 1 or 2, not 3.";
    QTest::newRow("too short") << "7E"
                               << "Serial format \"7E\" is not valid: write data bits, parity "
                                  "and stop bits, e.g. 7E1 or 8N1.";
    QTest::newRow("too long") << "7E11"
                              << "Serial format \"7E11\" is not valid: write data bits, parity "
                                 "and stop bits, e.g. 7E1 or 8N1.";
    QTest::newRow("empty") << ""
                           << "Serial format \"\" is not valid: write data bits, parity and "
                              "stop bits, e.g. 7E1 or 8N1.";
    QTest::newRow("words") << "8-N-1"
                           << "Serial format \"8-N-1\" is not valid: write data bits, parity "
                              "and stop bits, e.g. 7E1 or 8N1.";
}

void TestLinkSettings::reject()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    LinkSettings s = LinkSettings::serial(QStringLiteral("/dev/ttyS0"));
    const LinkSettings before = s;
    QCOMPARE(s.setSerialFormat(text), message);
    QVERIFY(s == before); // a rejected format changes nothing
}

void TestLinkSettings::formatRoundTrip()
{
    LinkSettings s = LinkSettings::serial(QStringLiteral("COM3"), 19200);
    QCOMPARE(s.serialFormat(), QStringLiteral("7E1"));
    for (const char *text : {"7E1", "7O1", "7N2", "8N1", "8E2", "8O1"}) {
        QCOMPARE(s.setSerialFormat(QLatin1String(text)), QString());
        QCOMPARE(s.serialFormat(), QLatin1String(text));
        QVERIFY(s.toString().startsWith(QStringLiteral("COM3 19200 %1,").arg(QLatin1String(text))));
    }
}

void TestLinkSettings::parts()
{
    QVERIFY(LinkSettings::parityFromText(QStringLiteral("none")) == Parity::None);
    QVERIFY(LinkSettings::parityFromText(QStringLiteral("Even")) == Parity::Even);
    QVERIFY(LinkSettings::parityFromText(QStringLiteral("o")) == Parity::Odd);
    QVERIFY(!LinkSettings::parityFromText(QStringLiteral("M")));
    QVERIFY(!LinkSettings::parityFromText(QString()));
    QVERIFY(LinkSettings::dataBitsFromText(QStringLiteral(" 8 ")) == 8);
    QVERIFY(!LinkSettings::dataBitsFromText(QStringLiteral("6")));
    QVERIFY(!LinkSettings::dataBitsFromText(QStringLiteral("seven")));
    QVERIFY(LinkSettings::stopBitsFromText(QStringLiteral("2")) == 2);
    QVERIFY(!LinkSettings::stopBitsFromText(QStringLiteral("0")));
    QCOMPARE(LinkSettings::parityLetter(Parity::Odd), QChar(u'O'));
}

// Links a script can name (issue 32): every form reads to the settings meant, and toUrl() reads
// back to equal settings.
void TestLinkSettings::urls_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<LinkSettings>("expected");
    QTest::addColumn<int>("station"); // -1: none named
    LinkSettings tcp = LinkSettings::tcp(QStringLiteral("plc1"), 502);
    QTest::newRow("tcp") << QStringLiteral("tcp://plc1:502") << tcp << -1;
    QTest::newRow("tcp default port")
        << QStringLiteral("TCP://plc1") << LinkSettings::tcp(QStringLiteral("plc1")) << -1;
    QTest::newRow("ipv6") << QStringLiteral("udp://[fe80::1]:600")
                          << LinkSettings::udp(QStringLiteral("fe80::1"), 600) << -1;
    LinkSettings tuned = tcp;
    tuned.protocol = LinkSettings::ProtocolChoice::Binary;
    tuned.timeoutMs = 250;
    tuned.retries = 0;
    QTest::newRow("settings") << QStringLiteral("tcp://plc1:502?protocol=binary&timeout=250&"
                                                "retries=0&station=7")
                              << tuned << 7;
    LinkSettings serial = LinkSettings::serial(QStringLiteral("/dev/ttyUSB0"), 19200);
    serial.setSerialFormat(QStringLiteral("8N2"));
    serial.flowControl = LinkSettings::FlowControl::Hardware;
    QTest::newRow("serial") << QStringLiteral(
        "serial:///dev/ttyUSB0?baud=19200&format=8N2&flow=rtscts")
                            << serial << -1;
    QTest::newRow("plain device") << QStringLiteral("/dev/ttyS1")
                                  << LinkSettings::serial(QStringLiteral("/dev/ttyS1")) << -1;
    QTest::newRow("com name") << QStringLiteral("COM3?station=2")
                              << LinkSettings::serial(QStringLiteral("COM3")) << 2;
    QTest::newRow("com url") << QStringLiteral("serial://COM12")
                             << LinkSettings::serial(QStringLiteral("COM12")) << -1;
}

void TestLinkSettings::urls()
{
    QFETCH(QString, url);
    QFETCH(LinkSettings, expected);
    QFETCH(int, station);
    Message error;
    const auto parsed = LinkSettings::fromUrl(url, &error);
    QVERIFY2(parsed, english(error).c_str());
    QCOMPARE(parsed->settings, expected);
    QCOMPARE(parsed->station.value_or(-1), station);
    const QString back = parsed->settings.toUrl(station);
    const auto again = LinkSettings::fromUrl(back, &error);
    QVERIFY2(again, qPrintable(back));
    QCOMPARE(again->settings, expected);
    QCOMPARE(again->station.value_or(-1), station);
}

void TestLinkSettings::badUrls_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("id");
    QTest::newRow("empty") << QString() << QStringLiteral("SettingsUrlEmpty");
    QTest::newRow("no scheme") << QStringLiteral("plc1:500") << QStringLiteral("SettingsUrlScheme");
    QTest::newRow("other scheme") << QStringLiteral("modbus://plc1")
                                  << QStringLiteral("SettingsUrlScheme");
    QTest::newRow("no host") << QStringLiteral("tcp://:500")
                             << QStringLiteral("SettingsUrlHostPort");
    QTest::newRow("bad port") << QStringLiteral("tcp://plc1:70000")
                              << QStringLiteral("SettingsUrlHostPort");
    QTest::newRow("three parts") << QStringLiteral("tcp://h:p:5")
                                 << QStringLiteral("SettingsUrlHostPort");
    QTest::newRow("no serial port")
        << QStringLiteral("serial://") << QStringLiteral("SettingsUrlNoPort");
    QTest::newRow("serial setting on tcp")
        << QStringLiteral("tcp://plc1?baud=9600") << QStringLiteral("SettingsUrlUnknown");
    QTest::newRow("bad value") << QStringLiteral("serial://COM3?format=7X1")
                               << QStringLiteral("SettingsUrlValue");
    QTest::newRow("bad station") << QStringLiteral("tcp://plc1?station=255")
                                 << QStringLiteral("SettingsUrlValue");
}

void TestLinkSettings::badUrls()
{
    QFETCH(QString, url);
    QFETCH(QString, id);
    Message error;
    QVERIFY(!LinkSettings::fromUrl(url, &error));
    QCOMPARE(QString::fromLatin1(error.id.name()), id);
}

QTEST_GUILESS_MAIN(TestLinkSettings)
#include "tst_linksettings.moc"
