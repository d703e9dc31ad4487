#pragma once

#include "transport.h"

#include <QList>
#include <QTimer>

class QSerialPort;

namespace Fatek {

// A serial port for the port pick list.
struct SerialPortEntry
{
    QString name;         // "ttyUSB0", "COM3"
    QString systemPath;   // "/dev/ttyUSB0", "COM3"
    QString description;  // "USB-Serial Controller"
    QString manufacturer; // "Prolific"
};

// RS-232 / RS-485 through QSerialPort.
class SerialTransport final : public Transport
{
    Q_OBJECT

public:
    explicit SerialTransport(const LinkSettings &settings, QObject *parent = nullptr);
    ~SerialTransport() override;

    static QList<SerialPortEntry> availablePorts();

    void open() override;
    void close() override;
    bool isOpen() const override;
    bool write(const QByteArray &bytes) override;
    qint64 unsentBytes() const override;
    QByteArray takePending() override;
    QString describe() const override;

private:
    // Bytes the driver still holds for the line (0 where the system does not tell).
    qint64 driverQueue() const;
    void checkSent();

    LinkSettings m_settings;
    QSerialPort *m_port = nullptr;
    // Re-checks the driver's queue until the line has sent it (no signal says so).
    QTimer m_drainTimer{this};
};

} // namespace Fatek
