#include "simserver.h"

#include "simconnection.h"
#include "simulatedplc.h"

#include <QNetworkDatagram>
#include <QNetworkProxy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QUdpSocket>

namespace Fatek {

namespace {

constexpr int ladderPeriodMs = 10;
constexpr qsizetype maxUdpPeers = 256;

QString hexCode(std::uint8_t code)
{
    return QString::number(code, 16).toUpper();
}

QString peerText(const QString &transport, const QHostAddress &address, quint16 port)
{
    return QStringLiteral("%1 %2:%3").arg(transport, address.toString()).arg(port);
}

} // namespace

SimServer::SimServer(SimulatedPlc *plc, QObject *parent)
    : QObject(parent)
    , m_plc(plc)
    , m_random(m_faults.seed)
{
    m_ladderTimer.setInterval(ladderPeriodMs);
    connect(&m_ladderTimer, &QTimer::timeout, this,
            [this] { m_plc->scan(m_ladderClock.elapsed()); });
}

SimServer::~SimServer()
{
    close();
}

void SimServer::setFaults(const FaultConfig &faults)
{
    m_faults = faults;
    m_random.seed(faults.seed);
}

void SimServer::setDemoLadder(bool enabled)
{
    if (enabled && !m_ladderTimer.isActive()) {
        m_ladderClock.start();
        m_ladderTimer.start();
    } else if (!enabled) {
        m_ladderTimer.stop();
    }
}

bool SimServer::listenTcp(quint16 port, QString *error)
{
    if (!m_tcp) {
        m_tcp = new QTcpServer(this);
        // A PLC endpoint is never a proxy client (and libproxy stays out of the process).
        m_tcp->setProxy(QNetworkProxy::NoProxy);
        connect(m_tcp, &QTcpServer::newConnection, this, &SimServer::acceptTcp);
    }
    if (m_tcp->isListening())
        m_tcp->close();
    if (!m_tcp->listen(m_bind, port)) {
        if (error) {
            *error = QStringLiteral("Cannot listen on TCP %1:%2: %3")
                         .arg(m_bind.toString())
                         .arg(port)
                         .arg(m_tcp->errorString());
        }
        return false;
    }
    return true;
}

bool SimServer::listenUdp(quint16 port, QString *error)
{
    if (!m_udp) {
        m_udp = new QUdpSocket(this);
        m_udp->setProxy(QNetworkProxy::NoProxy);
        connect(m_udp, &QUdpSocket::readyRead, this, &SimServer::readUdp);
    }
    if (m_udp->state() != QAbstractSocket::UnconnectedState)
        m_udp->close();
    if (!m_udp->bind(m_bind, port)) {
        if (error) {
            *error = QStringLiteral("Cannot listen on UDP %1:%2: %3")
                         .arg(m_bind.toString())
                         .arg(port)
                         .arg(m_udp->errorString());
        }
        return false;
    }
    return true;
}

bool SimServer::openSerial(const SerialSettings &settings, QString *error)
{
    if (m_serial) {
        delete m_serial; // also deletes its connection
        m_serial = nullptr;
        m_serialConnection = nullptr;
    }
    auto *port = new QSerialPort(this);
    port->setPortName(settings.portName);
    port->setBaudRate(settings.baudRate);
    port->setDataBits(settings.dataBits);
    port->setParity(settings.parity);
    port->setStopBits(settings.stopBits);
    port->setFlowControl(QSerialPort::NoFlowControl);
    if (!port->open(QIODevice::ReadWrite)) {
        if (error) {
            *error = QStringLiteral("Cannot open serial port %1: %2")
                         .arg(settings.portName, port->errorString());
        }
        delete port;
        return false;
    }
    m_serial = port;
    m_serialConnection = new SimConnection(
        QStringLiteral("serial ") + settings.portName,
        [port](const QByteArray &bytes) { port->write(bytes); }, port);
    connect(port, &QSerialPort::readyRead, m_serialConnection,
            [this, port] { handleBytes(m_serialConnection, port->readAll()); });
    connect(port, &QSerialPort::errorOccurred, this, [this, port](QSerialPort::SerialPortError e) {
        if (e != QSerialPort::NoError)
            Q_EMIT logLine(
                QStringLiteral("serial %1: %2").arg(port->portName(), port->errorString()));
    });
    return true;
}

quint16 SimServer::tcpPort() const
{
    return m_tcp && m_tcp->isListening() ? m_tcp->serverPort() : 0;
}

quint16 SimServer::udpPort() const
{
    return m_udp && m_udp->state() == QAbstractSocket::BoundState ? m_udp->localPort() : 0;
}

bool SimServer::isListening() const
{
    return tcpPort() != 0 || udpPort() != 0 || (m_serial && m_serial->isOpen());
}

int SimServer::tcpClientCount() const
{
    return m_tcpClients;
}

void SimServer::close()
{
    if (m_tcp) {
        m_tcp->close();
        // Detach first: a socket destroyed while connected emits disconnected().
        for (QTcpSocket *socket : m_tcp->findChildren<QTcpSocket *>()) {
            disconnect(socket, nullptr, this, nullptr);
            socket->abort();
            delete socket;
        }
        delete m_tcp;
        m_tcp = nullptr;
        if (m_tcpClients != 0) {
            m_tcpClients = 0;
            Q_EMIT clientCountChanged(0);
        }
    }
    if (m_udp) {
        qDeleteAll(m_udpPeers);
        m_udpPeers.clear();
        delete m_udp;
        m_udp = nullptr;
    }
    if (m_serial) {
        delete m_serial;
        m_serial = nullptr;
        m_serialConnection = nullptr;
    }
}

void SimServer::acceptTcp()
{
    while (QTcpSocket *socket = m_tcp->nextPendingConnection()) {
        const QString peer
            = peerText(QStringLiteral("tcp"), socket->peerAddress(), socket->peerPort());
        auto *connection = new SimConnection(
            peer,
            [socket](const QByteArray &bytes) {
                if (socket->state() == QAbstractSocket::ConnectedState)
                    socket->write(bytes);
            },
            socket);
        connect(socket, &QTcpSocket::readyRead, connection,
                [this, socket, connection] { handleBytes(connection, socket->readAll()); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket, peer] {
            --m_tcpClients;
            log(peer + QStringLiteral(" disconnected"));
            Q_EMIT clientCountChanged(m_tcpClients);
            socket->deleteLater();
        });
        if (m_faults.closeEverySeconds > 0) {
            QTimer::singleShot(m_faults.closeEverySeconds * 1000, socket, [this, socket, peer] {
                ++m_counters.closed;
                log(peer + QStringLiteral(" closed by fault injection"));
                socket->disconnectFromHost();
            });
        }
        ++m_tcpClients;
        log(peer + QStringLiteral(" connected"));
        Q_EMIT clientCountChanged(m_tcpClients);
    }
}

void SimServer::readUdp()
{
    while (m_udp && m_udp->hasPendingDatagrams()) {
        const QNetworkDatagram datagram = m_udp->receiveDatagram();
        if (!datagram.isValid())
            continue;
        const QHostAddress address = datagram.senderAddress();
        const quint16 port = static_cast<quint16>(datagram.senderPort());
        const QString key = peerText(QStringLiteral("udp"), address, port);
        SimConnection *connection = m_udpPeers.value(key);
        if (!connection) {
            if (m_udpPeers.size() >= maxUdpPeers) {
                // Forget idle peers: UDP has no disconnect to tell us they are gone.
                for (auto it = m_udpPeers.begin(); it != m_udpPeers.end();) {
                    if (!it.value()->hasPending()) {
                        delete it.value();
                        it = m_udpPeers.erase(it);
                    } else {
                        ++it;
                    }
                }
            }
            QUdpSocket *udp = m_udp;
            connection = new SimConnection(
                key,
                [udp, address, port](const QByteArray &bytes) {
                    udp->writeDatagram(bytes, address, port);
                },
                m_udp);
            m_udpPeers.insert(key, connection);
        }
        handleBytes(connection, datagram.data());
    }
}

void SimServer::handleBytes(SimConnection *connection, const QByteArray &bytes)
{
    m_counters.bytesIn += static_cast<quint64>(bytes.size());
    for (SimConnection::Item &item : connection->feed(bytes)) {
        if (item.item.error) {
            ++m_counters.rejected;
            log(QStringLiteral("[%1] %2 frame rejected, no answer: %3")
                    .arg(connection->peer(), QString::fromUtf8(protocolName(item.protocol).data()),
                         QString::fromStdString(item.item.error->text())));
            continue;
        }
        handleFrame(connection, item.protocol, item.item.frame);
    }
}

void SimServer::handleFrame(SimConnection *connection, Protocol protocol, const Bytes &frame)
{
    const Codec &codec = protocol == Protocol::Facon ? static_cast<const Codec &>(m_faconCodec)
                                                     : static_cast<const Codec &>(m_binaryCodec);
    const QString prefix
        = QStringLiteral("[%1] %2 ")
              .arg(connection->peer(), QString::fromUtf8(protocolName(protocol).data()));
    const std::optional<FrameHeader> header = codec.frameHeader(frame);
    if (!header) {
        ++m_counters.rejected;
        log(prefix + QStringLiteral("frame without header, no answer"));
        return;
    }
    const bool broadcast = header->station == Limits::broadcastStation;
    if (!broadcast && header->station != m_station) {
        ++m_counters.otherStation;
        log(prefix + QStringLiteral("frame for station %1 ignored").arg(header->station));
        return;
    }
    ++m_counters.frames;
    // The wrong-station fault answers as the next station (1..254).
    const bool wrongStation = !broadcast && chance(m_faults.wrongStationRate);
    const auto otherStation = static_cast<std::uint8_t>(m_station % Limits::maxStation + 1);

    Result<Request> decoded = codec.decodeRequest(frame);
    if (!decoded) {
        const int code = decoded.error().plcCode;
        log(prefix
            + QStringLiteral("command %1: %2 -> %3")
                  .arg(hexCode(header->command), QString::fromStdString(decoded.error().text()),
                       code == 0 || broadcast
                           ? QStringLiteral("no answer")
                           : QStringLiteral("error ") + hexCode(static_cast<std::uint8_t>(code))));
        if (code == 0 || broadcast)
            return;
        FrameHeader answerHeader = *header;
        if (wrongStation)
            answerHeader.station = otherStation;
        sendAnswer(connection,
                   codec.encodeErrorResponse(answerHeader, static_cast<std::uint8_t>(code)),
                   wrongStation);
        return;
    }
    Request request = std::move(decoded).value();
    Response response = m_plc->execute(request, protocol);
    log(prefix + QString::fromStdString(request.describe()) + QStringLiteral(" -> ")
        + (response.errorCode == 0 ? QStringLiteral("OK")
                                   : QStringLiteral("error ") + hexCode(response.errorCode))
        + (broadcast ? QStringLiteral(", broadcast: no answer") : QString()));
    if (broadcast)
        return;
    if (wrongStation) {
        request.station = otherStation;
        response.station = otherStation;
    }
    sendAnswer(connection, codec.encodeResponse(request, response), wrongStation);
}

void SimServer::sendAnswer(SimConnection *connection, Bytes answer, bool wrongStation)
{
    if (chance(m_faults.dropRate)) {
        ++m_counters.dropped;
        ++m_counters.faultyAnswers;
        log(QStringLiteral("[%1] answer dropped by fault injection").arg(connection->peer()));
        return;
    }
    ++m_counters.answers;
    QByteArray out;
    for (int i = 0; i < m_faults.garbageBytes; ++i) {
        // Printable noise, never 'R' (0x52, binary answer header); STX is not printable.
        char c = 'R';
        while (c == 'R')
            c = static_cast<char>(0x20 + m_random.bounded(0x5F));
        out.append(c);
    }
    m_counters.garbageBytes
        += static_cast<quint64>(m_faults.garbageBytes > 0 ? m_faults.garbageBytes : 0);
    bool corrupted = false;
    for (std::uint8_t b : answer) {
        if (chance(m_faults.corruptRate)) {
            b = static_cast<std::uint8_t>(b ^ (1 + m_random.bounded(255)));
            corrupted = true;
        }
        out.append(static_cast<char>(b));
    }
    if (corrupted)
        ++m_counters.corrupted;
    if (wrongStation)
        ++m_counters.wrongStation;
    if (corrupted || wrongStation)
        ++m_counters.faultyAnswers;
    qint64 delay = m_faults.turnaroundMs + m_faults.latencyMs;
    // Half-duplex line: the query's own wire time passes before the answer's (in microseconds).
    const qint64 lineUs
        = SimConnection::lineTimeUs(connection->lastFrameBytes() + out.size(), m_faults.baud);
    if (m_faults.jitterMs > 0)
        delay += m_random.bounded(m_faults.jitterMs + 1);
    if (m_faults.spikeMs > 0 && chance(m_faults.spikeRate)) {
        ++m_counters.spikes;
        delay += m_faults.spikeMs;
    }
    if (m_faults.chunkSize > 0) {
        for (qsizetype pos = 0, i = 0; pos < out.size(); pos += m_faults.chunkSize, ++i)
            connection->send(out.mid(pos, m_faults.chunkSize), delay + i * m_faults.chunkDelayMs,
                             lineUs);
    } else {
        connection->send(out, delay, lineUs);
    }
}

bool SimServer::chance(double rate)
{
    if (rate <= 0.0)
        return false;
    if (rate >= 1.0)
        return true;
    return m_random.generateDouble() < rate;
}

void SimServer::log(const QString &line)
{
    if (m_verbose)
        Q_EMIT logLine(line);
}

} // namespace Fatek
