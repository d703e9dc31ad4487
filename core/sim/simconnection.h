#pragma once

#include "binarydeframer.h"
#include "facondeframer.h"
#include "request.h"

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

    // Sends `bytes` no earlier than `delayMs` from now and never before what was queued earlier.
    void send(const QByteArray &bytes, qint64 delayMs);
    // Time (ms from now) at which the last queued bytes go out; 0 when idle.
    qint64 busyForMs() const;
    bool hasPending() const { return !m_pending.empty(); }

private:
    void flushDue();
    void armTimer();

    struct Pending
    {
        qint64 due = 0;
        QByteArray bytes;
    };

    QString m_peer;
    Writer m_writer;
    FaconDeframer m_facon;
    BinaryDeframer m_binary{BinaryDeframer::Direction::Query};
    Deframer *m_active = nullptr;
    std::size_t m_skipped = 0;
    QElapsedTimer m_clock;
    QTimer m_timer;
    std::deque<Pending> m_pending;
    qint64 m_lastDue = 0;
};

} // namespace Fatek
