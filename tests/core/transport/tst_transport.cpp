// Transports against plain peers written here (echo servers, a socat pty pair): no PLC logic.
#include "core/transport/linksettings.h"
#include "core/transport/serialtransport.h"
#include "core/transport/tcptransport.h"
#include "core/transport/udptransport.h"

#include <QFile>
#include <QNetworkDatagram>
#include <QNetworkProxy>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QUdpSocket>

using namespace Fatek;

class TestTransport : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void linkSettingsText();
    void linkSettingsValidation_data();
    void linkSettingsValidation();
    void tcpEcho();
    void tcpPeerCloses();
    void tcpRefused();
    void udpLargeDatagram();
    void udpIgnoresOtherSenders();
    void serialPty();
    void serialMissingPort();
};

void TestTransport::initTestCase()
{
    // The test's own peer sockets never go through a desktop proxy either (the transports set
    // NoProxy themselves); it also keeps libproxy's thread out of ThreadSanitizer runs.
    QNetworkProxy::setApplicationProxy(QNetworkProxy::NoProxy);
}

void TestTransport::linkSettingsText()
{
    QCOMPARE(LinkSettings::tcp(QStringLiteral("127.0.0.1")).toString(),
             QStringLiteral("TCP 127.0.0.1:500, FACON"));
    QCOMPARE(LinkSettings::udp(QStringLiteral("plc1"), 600, LinkSettings::ProtocolChoice::Binary)
                 .toString(),
             QStringLiteral("UDP plc1:600, binary"));
    LinkSettings serial = LinkSettings::serial(QStringLiteral("/dev/ttyUSB0"), 19200,
                                               LinkSettings::ProtocolChoice::Auto);
    QCOMPARE(serial.toString(), QStringLiteral("/dev/ttyUSB0 19200 7E1, auto-detect"));
    serial.dataBits = 8;
    serial.parity = LinkSettings::Parity::None;
    serial.stopBits = 2;
    QCOMPARE(serial.toString(), QStringLiteral("/dev/ttyUSB0 19200 8N2, auto-detect"));
}

void TestTransport::linkSettingsValidation_data()
{
    QTest::addColumn<LinkSettings>("settings");
    QTest::addColumn<QString>("fragment"); // empty: valid

    QTest::newRow("tcp ok") << LinkSettings::tcp(QStringLiteral("10.0.0.5")) << QString();
    QTest::newRow("no host") << LinkSettings::tcp(QStringLiteral(" "))
                             << QStringLiteral("IP address");
    QTest::newRow("port 0") << LinkSettings::udp(QStringLiteral("h"), 0)
                            << QStringLiteral("Port 0");
    QTest::newRow("no serial port")
        << LinkSettings::serial(QString()) << QStringLiteral("serial port");
    QTest::newRow("baud low") << LinkSettings::serial(QStringLiteral("COM1"), 300)
                              << QStringLiteral("Baud rate 300");
    QTest::newRow("baud high") << LinkSettings::serial(QStringLiteral("COM1"), 1000000)
                               << QStringLiteral("Baud rate");
    LinkSettings bits = LinkSettings::serial(QStringLiteral("COM1"));
    bits.dataBits = 6;
    QTest::newRow("data bits") << bits << QStringLiteral("Data bits");
    LinkSettings timeout = LinkSettings::tcp(QStringLiteral("h"));
    timeout.timeoutMs = 0;
    QTest::newRow("timeout") << timeout << QStringLiteral("Timeout");
}

void TestTransport::linkSettingsValidation()
{
    QFETCH(LinkSettings, settings);
    QFETCH(QString, fragment);
    const QString problem = englishText(settings.validate());
    if (fragment.isEmpty())
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    else
        QVERIFY2(problem.contains(fragment), qPrintable(problem));
}

void TestTransport::tcpEcho()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    connect(&server, &QTcpServer::newConnection, &server, [&server] {
        QTcpSocket *peer = server.nextPendingConnection();
        connect(peer, &QTcpSocket::readyRead, peer, [peer] { peer->write(peer->readAll()); });
    });

    TcpTransport transport(LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort()));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy lost(&transport, &Transport::disconnected);
    QVERIFY(!transport.write("x")); // not open yet: refused
    transport.open();
    QVERIFY(opened.wait(5000));
    QVERIFY(transport.isOpen());

    QByteArray received;
    connect(&transport, &Transport::bytesReceived, this,
            [&received](const QByteArray &b) { received += b; });
    const QByteArray query("\x02"
                           "0140C7\x03",
                           8);
    QVERIFY(transport.write(query));
    QTRY_COMPARE_WITH_TIMEOUT(received, query, 5000);
    // More than one read's chunk (the socket is unbuffered: reads go to the kernel), in order.
    QByteArray big(20000, Qt::Uninitialized);
    for (qsizetype i = 0; i < big.size(); ++i)
        big[i] = static_cast<char>('A' + i % 26);
    received.clear();
    QVERIFY(transport.write(big));
    QTRY_COMPARE_WITH_TIMEOUT(received.size(), big.size(), 5000);
    QCOMPARE(received, big);
    QCOMPARE(lost.count(), 0);
    transport.close();
    QVERIFY(!transport.isOpen());
    QCOMPARE(lost.count(), 0); // close() is not a failure
}

void TestTransport::tcpPeerCloses()
{
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    TcpTransport transport(LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort()));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy lost(&transport, &Transport::disconnected);
    transport.open();
    QVERIFY(opened.wait(5000));
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), 5000);
    QTcpSocket *peer = server.nextPendingConnection();
    QByteArray received;
    connect(&transport, &Transport::bytesReceived, this,
            [&received](const QByteArray &b) { received += b; });
    // Its last words arrive before the loss is reported.
    peer->write("last words");
    peer->flush();
    peer->close();
    QTRY_COMPARE_WITH_TIMEOUT(lost.count(), 1, 5000);
    QCOMPARE(received, QByteArray("last words"));
    QVERIFY2(englishText(lost.at(0).at(0).value<Message>()).contains(QStringLiteral("closed")),
             qPrintable(englishText(lost.at(0).at(0).value<Message>())));
    QVERIFY(!transport.isOpen());
    QVERIFY(!transport.write("x"));
}

void TestTransport::tcpRefused()
{
    quint16 port = 0;
    {
        QTcpServer server; // find a free port, then free it again
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        port = server.serverPort();
    }
    TcpTransport transport(LinkSettings::tcp(QStringLiteral("127.0.0.1"), port));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy lost(&transport, &Transport::disconnected);
    transport.open();
    QTRY_COMPARE_WITH_TIMEOUT(lost.count(), 1, 5000);
    QCOMPARE(opened.count(), 0);
    QVERIFY(englishText(lost.at(0).at(0).value<Message>())
                .contains(QStringLiteral("TCP 127.0.0.1:%1").arg(port)));
}

void TestTransport::udpLargeDatagram()
{
    QUdpSocket peer;
    QVERIFY(peer.bind(QHostAddress::LocalHost, 0));
    connect(&peer, &QUdpSocket::readyRead, &peer, [&peer] {
        while (peer.hasPendingDatagrams()) {
            const QNetworkDatagram d = peer.receiveDatagram();
            peer.writeDatagram(d.makeReply(d.data()));
        }
    });
    UdpTransport transport(LinkSettings::udp(QStringLiteral("127.0.0.1"), peer.localPort()));
    QSignalSpy opened(&transport, &Transport::opened);
    transport.open();
    QVERIFY(opened.count() == 1 || opened.wait(5000));

    QList<QByteArray> datagrams;
    connect(&transport, &Transport::bytesReceived, this,
            [&datagrams](const QByteArray &b) { datagrams.append(b); });
    // Larger than any "usual" 512-byte buffer: must arrive whole, as one datagram.
    QByteArray big(1400, '\0');
    for (int i = 0; i < big.size(); ++i)
        big[i] = static_cast<char>('0' + i % 10);
    QVERIFY(transport.write(big));
    QTRY_COMPARE_WITH_TIMEOUT(datagrams.size(), 1, 5000);
    QCOMPARE(datagrams.at(0), big);
    QVERIFY(transport.write("small"));
    QTRY_COMPARE_WITH_TIMEOUT(datagrams.size(), 2, 5000);
    QCOMPARE(datagrams.at(1), QByteArray("small"));
}

void TestTransport::udpIgnoresOtherSenders()
{
    QUdpSocket plc;
    QVERIFY(plc.bind(QHostAddress::LocalHost, 0));
    UdpTransport transport(LinkSettings::udp(QStringLiteral("127.0.0.1"), plc.localPort()));
    QSignalSpy opened(&transport, &Transport::opened);
    transport.open();
    QVERIFY(opened.count() == 1 || opened.wait(5000));
    QList<QByteArray> datagrams;
    connect(&transport, &Transport::bytesReceived, this,
            [&datagrams](const QByteArray &b) { datagrams.append(b); });
    QVERIFY(transport.write("hello"));
    QTRY_VERIFY_WITH_TIMEOUT(plc.hasPendingDatagrams(), 5000);
    const QNetworkDatagram query = plc.receiveDatagram();
    // A stranger writes to our port first; then the PLC answers.
    QUdpSocket stranger;
    stranger.writeDatagram("intruder", query.senderAddress(),
                           static_cast<quint16>(query.senderPort()));
    plc.writeDatagram(query.makeReply("answer"));
    QTRY_COMPARE_WITH_TIMEOUT(datagrams.size(), 1, 5000);
    QTest::qWait(100); // let a wrongly accepted datagram show up
    QCOMPARE(datagrams, QList<QByteArray>{"answer"});
}

void TestTransport::serialPty()
{
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        QSKIP("socat is not installed");
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a"));
    const QString b = dir.filePath(QStringLiteral("b"));
    QProcess process;
    process.start(socat, {QStringLiteral("pty,raw,echo=0,link=") + a,
                          QStringLiteral("pty,raw,echo=0,link=") + b});
    QVERIFY(process.waitForStarted(5000));
    QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(a) && QFile::exists(b), 5000);

    QSerialPort peer(b);
    QVERIFY(peer.open(QIODevice::ReadWrite));
    LinkSettings settings = LinkSettings::serial(a, 9600);
    settings.dataBits = 8;
    settings.parity = LinkSettings::Parity::None;
    {
        SerialTransport transport(settings);
        QSignalSpy opened(&transport, &Transport::opened);
        transport.open();
        QVERIFY(opened.wait(5000));
        QByteArray received;
        connect(&transport, &Transport::bytesReceived, this,
                [&received](const QByteArray &bytes) { received += bytes; });
        QVERIFY(transport.write("query"));
        QByteArray atPeer;
        QTRY_VERIFY_WITH_TIMEOUT((atPeer += peer.readAll()) == "query", 5000);
        peer.write("answer");
        QTRY_COMPARE_WITH_TIMEOUT(received, QByteArray("answer"), 5000);
        transport.close();
        QVERIFY(!transport.isOpen());
    }
    peer.close();
    process.terminate();
    process.waitForFinished(5000);
}

void TestTransport::serialMissingPort()
{
    SerialTransport transport(LinkSettings::serial(QStringLiteral("/dev/does-not-exist-fatek")));
    QSignalSpy opened(&transport, &Transport::opened);
    QSignalSpy lost(&transport, &Transport::disconnected);
    transport.open();
    QTRY_COMPARE_WITH_TIMEOUT(lost.count(), 1, 5000);
    QCOMPARE(opened.count(), 0);
    QVERIFY2(englishText(lost.at(0).at(0).value<Message>())
                 .contains(QStringLiteral("/dev/does-not-exist-fatek")),
             qPrintable(englishText(lost.at(0).at(0).value<Message>())));
}

QTEST_GUILESS_MAIN(TestTransport)
#include "tst_transport.moc"
