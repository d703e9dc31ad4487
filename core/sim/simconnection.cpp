#include "simconnection.h"

#include "binarycodec.h"
#include "faconcodec.h"

#include <algorithm>

namespace Fatek {

SimConnection::SimConnection(const QString &peer, Writer writer, QObject *parent)
    : QObject(parent)
    , m_peer(peer)
    , m_writer(std::move(writer))
{
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimConnection::flushDue);
}

std::vector<SimConnection::Item> SimConnection::feed(const QByteArray &bytes)
{
    std::vector<Item> items;
    std::vector<DeframedItem> out;
    // Byte by byte, so a FACON frame followed by a binary one in the same chunk reaches the
    // right deframer each (a deframer would skip the other protocol as garbage).
    for (char c : bytes) {
        const auto b = static_cast<std::uint8_t>(c);
        if (!m_active) {
            if (b == FaconCodec::STX)
                m_active = &m_facon;
            else if (b == BinaryCodec::queryHeader)
                m_active = &m_binary;
            else {
                ++m_skipped;
                continue;
            }
        }
        const Protocol protocol = m_active == &m_facon ? Protocol::Facon : Protocol::Binary;
        out.clear();
        m_active->feed(std::span<const std::uint8_t>(&b, 1), out);
        for (DeframedItem &item : out)
            items.push_back({protocol, std::move(item)});
        if (m_active->bufferedBytes() == 0)
            m_active = nullptr;
    }
    return items;
}

std::size_t SimConnection::discardedBytes() const
{
    return m_skipped + m_facon.discardedBytes() + m_binary.discardedBytes();
}

void SimConnection::send(const QByteArray &bytes, qint64 delayMs)
{
    const qint64 due = std::max(m_clock.elapsed() + std::max<qint64>(delayMs, 0), m_lastDue);
    m_lastDue = due;
    m_pending.push_back({due, bytes});
    if (due <= m_clock.elapsed() && m_pending.size() == 1) {
        flushDue(); // no delay asked and nothing queued: answer at once
        return;
    }
    armTimer();
}

qint64 SimConnection::busyForMs() const
{
    if (m_pending.empty())
        return 0;
    return std::max<qint64>(m_lastDue - m_clock.elapsed(), 0);
}

void SimConnection::flushDue()
{
    const qint64 now = m_clock.elapsed();
    while (!m_pending.empty() && m_pending.front().due <= now) {
        const QByteArray bytes = std::move(m_pending.front().bytes);
        m_pending.pop_front();
        m_writer(bytes);
    }
    armTimer();
}

void SimConnection::armTimer()
{
    if (m_pending.empty()) {
        m_timer.stop();
        return;
    }
    const qint64 wait = std::max<qint64>(m_pending.front().due - m_clock.elapsed(), 0);
    m_timer.start(static_cast<int>(wait));
}

} // namespace Fatek
