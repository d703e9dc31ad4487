#include "simconnection.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"

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
    std::vector<DeframedItem> shadow;
    auto deliver = [&](Protocol protocol, DeframedItem &item) {
        m_lastFrameBytes = static_cast<qsizetype>(item.frame.size());
        items.push_back({protocol, std::move(item)});
    };
    // Byte by byte, so a FACON frame followed by a binary one in the same chunk reaches the
    // right deframer each (a deframer would skip the other protocol as garbage).
    for (char c : bytes) {
        const auto b = static_cast<std::uint8_t>(c);
        const std::span<const std::uint8_t> one(&b, 1);
        if (!m_active) {
            if (b == FaconCodec::STX)
                m_active = &m_facon;
            else if (b == BinaryCodec::queryHeader)
                m_active = &m_binary;
            else {
                ++m_skipped;
                continue;
            }
        } else if (m_active == &m_facon && !m_binaryShadow && b == BinaryCodec::queryHeader) {
            // A binary query header inside a FACON frame in progress. Usually that "frame" is
            // noise (an STX byte in another station's binary answer on a multi-drop line) and a
            // binary query starts here; but FACON loopback data may hold 'Q' too. Both deframers
            // follow until one of them has a valid frame.
            m_binaryShadow = true;
        }
        const Protocol protocol = m_active == &m_facon ? Protocol::Facon : Protocol::Binary;
        out.clear();
        m_active->feed(one, out);
        if (m_binaryShadow) {
            shadow.clear();
            m_binary.feed(one, shadow);
            const auto valid = std::find_if(shadow.begin(), shadow.end(),
                                            [](const DeframedItem &i) { return !i.error; });
            if (valid != shadow.end()) {
                // The binary query is real: the FACON partial frame was noise.
                m_facon.reset();
                m_binaryShadow = false;
                m_active = &m_binary;
                deliver(Protocol::Binary, *valid);
                out.clear();
            } else if (std::any_of(out.begin(), out.end(),
                                   [](const DeframedItem &i) { return !i.error; })) {
                // The FACON frame is real: the binary candidate inside it was its data.
                m_binary.reset();
                m_binaryShadow = false;
            } else if (m_binary.bufferedBytes() == 0) {
                m_binaryShadow = false; // the binary candidate died (its errors are not reported)
            }
        }
        for (DeframedItem &item : out)
            deliver(protocol, item);
        if (m_active->bufferedBytes() == 0) {
            // A FACON frame that ended in an error leaves a binary candidate to follow alone.
            m_active = m_binaryShadow ? &m_binary : nullptr;
            m_binaryShadow = false;
        }
    }
    return items;
}

std::size_t SimConnection::discardedBytes() const
{
    return m_skipped + m_facon.discardedBytes() + m_binary.discardedBytes();
}

qint64 SimConnection::lineTimeUs(qsizetype bytes, int baud)
{
    if (baud <= 0 || bytes <= 0)
        return 0;
    const qint64 bits = static_cast<qint64>(bytes) * 10;
    return (bits * 1000000 + baud - 1) / baud; // rounded up: never faster than the line
}

qint64 SimConnection::nowUs() const
{
    return m_clock.nsecsElapsed() / 1000;
}

void SimConnection::send(const QByteArray &bytes, qint64 delayMs, qint64 lineUs)
{
    const qint64 now = nowUs();
    const qint64 due = std::max(
        now + std::max<qint64>(delayMs, 0) * 1000 + std::max<qint64>(lineUs, 0), m_lastDue);
    m_lastDue = due;
    m_pending.push_back({due, bytes});
    if (due <= now && m_pending.size() == 1) {
        flushDue(); // no delay asked and nothing queued: answer at once
        return;
    }
    armTimer();
}

qint64 SimConnection::busyForMs() const
{
    if (m_pending.empty())
        return 0;
    return (std::max<qint64>(m_lastDue - nowUs(), 0) + 999) / 1000;
}

void SimConnection::flushDue()
{
    const qint64 now = nowUs();
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
    // Whole milliseconds by the timer, the last fraction by re-checking on each event-loop pass:
    // a timer rounded up to the next millisecond would add up to 1 ms per answer, more than a
    // whole short frame takes at 115200 baud.
    const qint64 waitUs = std::max<qint64>(m_pending.front().due - nowUs(), 0);
    m_timer.start(static_cast<int>(waitUs / 1000));
}

} // namespace Fatek
