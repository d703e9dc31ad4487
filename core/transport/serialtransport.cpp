#include "serialtransport.h"

#include <QSerialPort>
#include <QSerialPortInfo>
#include <QTimer>

namespace Fatek {

SerialTransport::SerialTransport(const LinkSettings &settings, QObject *parent)
    : Transport(parent)
    , m_settings(settings)
{}

SerialTransport::~SerialTransport()
{
    close();
}

QList<SerialPortEntry> SerialTransport::availablePorts()
{
    QList<SerialPortEntry> ports;
    const auto infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo &info : infos)
        ports.append(
            {info.portName(), info.systemLocation(), info.description(), info.manufacturer()});
    return ports;
}

void SerialTransport::open()
{
    close();
    m_port = new QSerialPort(m_settings.portName, this);
    m_port->setBaudRate(m_settings.baudRate);
    m_port->setDataBits(m_settings.dataBits == 7 ? QSerialPort::Data7 : QSerialPort::Data8);
    switch (m_settings.parity) {
    case LinkSettings::Parity::None: m_port->setParity(QSerialPort::NoParity); break;
    case LinkSettings::Parity::Even: m_port->setParity(QSerialPort::EvenParity); break;
    case LinkSettings::Parity::Odd: m_port->setParity(QSerialPort::OddParity); break;
    }
    m_port->setStopBits(m_settings.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
    switch (m_settings.flowControl) {
    case LinkSettings::FlowControl::None: m_port->setFlowControl(QSerialPort::NoFlowControl); break;
    case LinkSettings::FlowControl::Hardware:
        m_port->setFlowControl(QSerialPort::HardwareControl);
        break;
    case LinkSettings::FlowControl::Software:
        m_port->setFlowControl(QSerialPort::SoftwareControl);
        break;
    }

    const bool ok = m_port->open(QIODevice::ReadWrite);
    if (!ok) {
        const QString reason
            = QStringLiteral("cannot open %1: %2").arg(describe(), m_port->errorString());
        close();
        // Asynchronous like the other transports, so callers see one code path.
        QTimer::singleShot(0, this, [this, reason] { Q_EMIT disconnected(reason); });
        return;
    }
    connect(m_port, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = m_port->readAll();
        if (!bytes.isEmpty())
            Q_EMIT bytesReceived(bytes);
    });
    connect(m_port, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError error) {
        // Parity/framing errors are line noise (the checksum catches them); a vanished adapter is
        // not.
        if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError)
            return;
        if (error != QSerialPort::ResourceError && error != QSerialPort::PermissionError
            && error != QSerialPort::DeviceNotFoundError)
            return;
        const QString reason = QStringLiteral("%1: %2").arg(describe(), m_port->errorString());
        close();
        Q_EMIT disconnected(reason);
    });
    QTimer::singleShot(0, this, [this] {
        if (m_port)
            Q_EMIT opened();
    });
}

void SerialTransport::close()
{
    if (QSerialPort *port = std::exchange(m_port, nullptr)) {
        port->disconnect(this);
        if (port->isOpen())
            port->close();
        port->deleteLater();
    }
}

bool SerialTransport::isOpen() const
{
    return m_port && m_port->isOpen();
}

bool SerialTransport::write(const QByteArray &bytes)
{
    if (!isOpen())
        return false;
    return m_port->write(bytes) == bytes.size();
}

QByteArray SerialTransport::takePending()
{
    return isOpen() ? m_port->readAll() : QByteArray();
}

QString SerialTransport::describe() const
{
    return m_settings.portName.isEmpty() ? QStringLiteral("serial port") : m_settings.portName;
}

} // namespace Fatek
