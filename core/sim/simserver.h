#pragma once

#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "faultconfig.h"

#include <QElapsedTimer>
#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QRandomGenerator>
#include <QSerialPort>
#include <QTimer>

#include <cstdint>

class QTcpServer;
class QTcpSocket;
class QUdpSocket;

namespace Fatek {

class SimConnection;
class SimulatedPlc;

struct SerialSettings
{
    QString portName;
    qint32 baudRate = 9600; // FBs defaults: 9600 7E1
    QSerialPort::DataBits dataBits = QSerialPort::Data7;
    QSerialPort::Parity parity = QSerialPort::EvenParity;
    QSerialPort::StopBits stopBits = QSerialPort::OneStop;
};

// Puts a SimulatedPlc on the wire: TCP (many clients), UDP and a serial port, both protocols on
// each endpoint. Answers like a PLC (station filter, broadcast silence, no answer to a bad
// checksum) and injects the faults of its FaultConfig. Lives in one thread; never blocks.
class SimServer : public QObject
{
    Q_OBJECT

public:
    struct Counters
    {
        quint64 frames = 0;       // checksum-valid frames for this station or broadcast
        quint64 answers = 0;      // answers queued for sending
        quint64 dropped = 0;      // answers withheld by the drop fault
        quint64 rejected = 0;     // broken frames (bad checksum, framing): no answer
        quint64 otherStation = 0; // frames for another station: ignored
        quint64 closed = 0;       // connections closed by the close-every fault
        // Injected faults, for reliability tests comparing them with what a master counted.
        quint64 faultyAnswers = 0; // answers hit by drop, corruption or wrong station (once each)
        quint64 corrupted = 0;     // answers sent with at least one byte flipped
        quint64 wrongStation = 0;  // answers sent with another station number
        quint64 spikes = 0;        // answers delayed by a latency spike
        quint64 garbageBytes = 0;  // noise bytes sent before answers
        quint64 bytesIn = 0;       // every byte received from masters (what reached the wire)
    };

    explicit SimServer(SimulatedPlc *plc, QObject *parent = nullptr);
    ~SimServer() override;

    SimulatedPlc *plc() const { return m_plc; }

    void setStation(std::uint8_t station) { m_station = station; }
    std::uint8_t station() const { return m_station; }
    void setBindAddress(const QHostAddress &address) { m_bind = address; }
    QHostAddress bindAddress() const { return m_bind; }
    void setFaults(const FaultConfig &faults);
    FaultConfig faults() const { return m_faults; }
    // One log line per request through logLine().
    void setVerbose(bool verbose) { m_verbose = verbose; }
    // Runs the demo ladder every 10 ms (it acts only while the PLC is in RUN).
    void setDemoLadder(bool enabled);
    bool demoLadder() const { return m_ladderTimer.isActive(); }

    // Port 0 picks a free port; tcpPort()/udpPort() tell which. On failure `error` says why.
    bool listenTcp(quint16 port, QString *error = nullptr);
    bool listenUdp(quint16 port, QString *error = nullptr);
    bool openSerial(const SerialSettings &settings, QString *error = nullptr);
    quint16 tcpPort() const;
    quint16 udpPort() const;
    bool isListening() const;
    int tcpClientCount() const;
    void close();

    Counters counters() const { return m_counters; }

Q_SIGNALS:
    void logLine(const QString &line);
    void clientCountChanged(int clients);

private:
    void acceptTcp();
    void readUdp();
    void handleBytes(SimConnection *connection, const QByteArray &bytes);
    void handleFrame(SimConnection *connection, Protocol protocol, const Bytes &frame);
    void sendAnswer(SimConnection *connection, Bytes answer, bool wrongStation);
    bool chance(double rate);
    void log(const QString &line);

    SimulatedPlc *m_plc;
    std::uint8_t m_station = 1;
    QHostAddress m_bind = QHostAddress(QHostAddress::LocalHost);
    FaultConfig m_faults;
    QRandomGenerator m_random;
    bool m_verbose = false;
    FaconCodec m_faconCodec;
    BinaryCodec m_binaryCodec;

    QTcpServer *m_tcp = nullptr;
    QUdpSocket *m_udp = nullptr;
    QHash<QString, SimConnection *> m_udpPeers;
    QSerialPort *m_serial = nullptr;
    SimConnection *m_serialConnection = nullptr;
    int m_tcpClients = 0;

    QTimer m_ladderTimer;
    QElapsedTimer m_ladderClock;
    Counters m_counters;
};

} // namespace Fatek
