#pragma once

#include "core/protocol/binarydeframer.h"
#include "core/protocol/facondeframer.h"
#include "core/protocol/request.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <vector>

namespace Fatek {

// One peer of the simulator (a TCP client, a UDP sender or the serial line): splits its byte
// stream into frames of either protocol and sends answers in order at their due time.
class SimConnection : public QObject
{
    Q_OBJECT

public:
    using Writer = std::function<void(const QByteArray &)>;

    struct Item
    {
        Protocol protocol = Protocol::Facon;
        DeframedItem item;
    };

    SimConnection(const QString &peer, Writer writer, QObject *parent = nullptr);

    QString peer() const { return m_peer; }

    // Feeds received bytes; the protocol of each frame is told by its first byte (STX: FACON,
    // 0x51: binary). Bytes outside frames are skipped.
    std::vector<Item> feed(const QByteArray &bytes);
    std::size_t discardedBytes() const;

    // Sends `bytes` no earlier than `delayMs` (plus `lineUs` microseconds of line time) from now
    // and never before what was queued earlier. Due times are kept in microseconds so that the
    // line-speed emulation at 115200 baud (87 us per byte) is not rounded to whole milliseconds.
    void send(const QByteArray &bytes, qint64 delayMs, qint64 lineUs = 0);
    // Size of the last complete frame fed in (the query being answered), 0 before the first.
    qsizetype lastFrameBytes() const { return m_lastFrameBytes; }
    // Time `bytes` take on a line at `baud` (10 bits per byte), rounded up; 0 when baud <= 0.
    static qint64 lineTimeUs(qsizetype bytes, int baud);
    // Time (ms from now) at which the last queued bytes go out; 0 when idle.
    qint64 busyForMs() const;
    bool hasPending() const { return !m_pending.empty(); }

private:
    void flushDue();
    void armTimer();
    qint64 nowUs() const;

    struct Pending
    {
        qint64 due = 0; // microseconds on m_clock
        QByteArray bytes;
    };

    QString m_peer;
    Writer m_writer;
    FaconDeframer m_facon;
    BinaryDeframer m_binary{BinaryDeframer::Direction::Query};
    Deframer *m_active = nullptr;
    bool m_binaryShadow = false; // m_binary also follows a FACON frame in progress
    std::size_t m_skipped = 0;
    QElapsedTimer m_clock;
    QTimer m_timer;
    std::deque<Pending> m_pending;
    qint64 m_lastDue = 0; // microseconds on m_clock
    qsizetype m_lastFrameBytes = 0;
};

} // namespace Fatek
