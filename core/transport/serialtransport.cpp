#include "serialtransport.h"

#include <QSerialPort>
#include <QSerialPortInfo>
#include <QTimer>

#include <algorithm>

#ifdef Q_OS_UNIX
#include <sys/ioctl.h>
#include <termios.h>
#endif

namespace Fatek {

SerialTransport::SerialTransport(const LinkSettings &settings, QObject *parent)
    : Transport(parent)
    , m_settings(settings)
{
    m_drainTimer.setSingleShot(true);
    connect(&m_drainTimer, &QTimer::timeout, this, &SerialTransport::checkSent);
}

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
        const Message reason = msg<MsgId::LinkCannotOpen>(
            describe().toStdString(), Message::text(m_port->errorString().toStdString()));
        close();
        // Asynchronous like the other transports, so callers see one code path.
        QTimer::singleShot(0, this, [this, reason] { Q_EMIT disconnected(reason); });
        return;
    }
    connect(m_port, &QSerialPort::bytesWritten, this, &SerialTransport::checkSent);
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
        const Message reason = deviceError(m_port->errorString());
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
    m_drainTimer.stop();
    if (QSerialPort *port = std::exchange(m_port, nullptr)) {
        port->disconnect(this);
        // What is still queued here is what the session gave up on (a stopped line): dropped, so
        // that closing does not wait for the driver to send it.
        if (port->isOpen() && port->bytesToWrite() > 0)
            port->clear(QSerialPort::Output);
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

qint64 SerialTransport::driverQueue() const
{
#ifdef Q_OS_UNIX
    int queued = 0;
    if (m_port && m_port->isOpen() && ::ioctl(m_port->handle(), TIOCOUTQ, &queued) == 0)
        return queued;
#endif
    return 0;
}

qint64 SerialTransport::unsentBytes() const
{
    if (!isOpen())
        return 0;
    return m_port->bytesToWrite() + driverQueue();
}

void SerialTransport::checkSent()
{
    if (!isOpen() || m_port->bytesToWrite() > 0)
        return; // bytesWritten() comes again
    const qint64 queued = driverQueue();
    if (queued == 0) {
        Q_EMIT allSent();
        return;
    }
    // The driver sends at the baud rate: look again when it should be done.
    const qint64 bitsPerChar = 1 + m_settings.dataBits + m_settings.stopBits
                               + (m_settings.parity == LinkSettings::Parity::None ? 0 : 1);
    const qint64 ms = queued * bitsPerChar * 1000 / std::max(1, m_settings.baudRate) + 1;
    m_drainTimer.start(static_cast<int>(std::min<qint64>(ms, 100)));
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
