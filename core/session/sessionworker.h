#pragma once

#include "core/protocol/codec.h"
#include "core/protocol/deframer.h"
#include "core/transport/linksettings.h"
#include "crossthreadqueue.h"
#include "poller.h"
#include "sessionresult.h"
#include "sessionstatistics.h"
#include "sessiontypes.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace Fatek {

class TrafficLog;
class Transport;

// State shared between the Session front and its worker (read by any thread).
struct SessionShared
{
    std::atomic<bool> readOnly{false};
    std::atomic<int> linkState{static_cast<int>(LinkState::Closed)};
    std::atomic<int> protocol{-1}; // Protocol value, -1 while auto-detect has not decided
    // Accepted writes (write commands, RUN/STOP, raw frames) not finished yet, queued or on the
    // wire: what closing the link waits for.
    std::atomic<int> pendingWrites{0};
    std::atomic<int> closeDrainMs{3000}; // how long a close waits for them
    mutable std::mutex mutex;
    SessionStatistics statistics; // under mutex
};

// One queued request of the worker.
struct SessionJob
{
    quint64 id = 0; // 0: internal (poller, protocol probe), answered through `done`
    bool raw = false;
    Request request;
    QByteArray rawBytes;
    bool addFraming = false;
    Priority priority = Priority::User;
    RequestOptions options;
    std::optional<Protocol> probe; // protocol auto-detect probe in this protocol
    bool fromPoller = false;       // the poller's own (it keeps the stations' health itself)
    std::function<void(const SessionResult &)> done;
    int attempts = 0;
    bool pendingWrite = false; // counted in SessionShared::pendingWrites
};

// The session's engine, living on its worker thread: one query on the wire at a time, priority
// queues, retries, timeouts, reconnects, statistics and the traffic log. Only the Session calls
// it, through its inbox().
class SessionWorker : public QObject
{
    Q_OBJECT

public:
    // Requests a user or background queue holds at most; more are refused (LimitExceeded).
    static constexpr std::size_t maxQueuedRequests = 1000;
    // Bytes a raw console answer collects at most.
    static constexpr qsizetype maxRawAnswerBytes = 65536;

    SessionWorker(const LinkSettings &settings, std::shared_ptr<SessionShared> shared,
                  TrafficLog *log);
    ~SessionWorker() override;

    // On the worker thread, when it starts. A timer already running when its object moves to
    // another thread is re-registered there by a queued call that leaks if the thread ends first.
    void startTimers();
    void open();
    // Closes the link. With `drain`, accepted writes and unsent bytes go out first (at most
    // SessionShared::closeDrainMs; reads and polls are cancelled at once); without, they are
    // cancelled. `closed` runs once the link is closed.
    void close(bool drain = true, std::function<void()> closed = {});
    void enqueue(SessionJob job);
    void cancel(quint64 id);
    void resetStatistics();
    void setWatchList(const QList<WatchEntry> &entries);

    // Runs the calls posted to this object (CrossThreadCall, inbox()).
    bool event(QEvent *event) override;
    // The calls for this worker, from any thread (thread-safe).
    CrossThreadQueue &inbox() { return m_inbox; }

Q_SIGNALS:
    void finished(quint64 id, const Fatek::SessionResult &result);
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    void statisticsChanged(const Fatek::SessionStatistics &statistics);
    void protocolDetected(Fatek::Protocol protocol);
    void values(const QList<Fatek::WatchValue> &values);

private:
    std::deque<SessionJob> &queueFor(Priority priority);
    bool takeNext(SessionJob &job);
    void schedulePump();
    void pump();
    bool prepare(SessionJob &job); // false: job finished or deferred
    void proceed();
    void startAttempt();
    void onBytes(const QByteArray &bytes);
    void onRawBytes(const QByteArray &bytes);
    void onTimeout();
    void retryOrFail(ProtocolError error);
    void finishCurrent(SessionResult result);
    void deliver(SessionJob &job, SessionResult result);
    void failAll(ErrorKind kind, const Message &reason, bool includePolls);
    static bool isWriteJob(const SessionJob &job);
    void finishBroadcast();
    void finishExpired();
    void onAllSent();
    void cancelReadsForClose();
    void checkDrained();
    void closeNow(const Message &reason);

    void onOpened();
    void onDisconnected(const Message &reason);
    void setState(LinkState state, const Message &reason);
    void startConnect();
    void setProtocol(Protocol protocol);
    const Codec *codec() const;
    int timeoutFor(const SessionJob &job) const;
    int retriesFor(const SessionJob &job) const;
    quint8 stationOf(const SessionJob &job) const;
    void countForStation(quint8 station, const std::function<void(StationStatistics &)> &update);
    void statisticsChangedInternally();
    void countDeframerNoise();
    void publishStatistics();
    void onStationHealth(quint8 station, bool demoted, const QDateTime &nextTry, int unanswered);
    Message summarize(const QByteArray &frame) const;

    LinkSettings m_settings;
    std::shared_ptr<SessionShared> m_shared;
    TrafficLog *m_log;
    Transport *m_transport = nullptr;
    std::unique_ptr<Codec> m_faconCodec;
    std::unique_ptr<Codec> m_binaryCodec;
    std::unique_ptr<Deframer> m_faconDeframer;
    std::unique_ptr<Deframer> m_binaryDeframer;
    std::optional<Protocol> m_protocol;

    std::deque<SessionJob> m_userQueue;
    std::deque<SessionJob> m_backgroundQueue;
    std::deque<SessionJob> m_pollQueue;
    std::optional<SessionJob> m_current;
    QByteArray m_sentFrame;
    QByteArray m_answer;          // bytes of the current attempt's answer
    bool m_lineQuiet = false;     // the last attempt ended with its answer and nothing after it
    bool m_pumpScheduled = false; // a queued pump() is on its way
    bool m_pumpDue = false;       // pump() when the inbox's batch or the answer's handling ends
    bool m_pumpHeld = false;      // an answer is being handled
    // Requests handed over together are all queued before the next one is chosen (priorities),
    // and the next one goes in the same turn of the event loop, not in a queued pump().
    CrossThreadQueue m_inbox{this, [this] {
                                 if (std::exchange(m_pumpDue, false))
                                     pump();
                             }};
    // The current job needs no answer and waits for its frame to leave (Transport::allSent).
    bool m_awaitingSent = false;
    // close(drain) in progress: writes still go, nothing new is accepted.
    bool m_closing = false;
    std::vector<std::function<void()>> m_whenClosed;
    QTimer m_drainTimer{this};

    LinkState m_state = LinkState::Closed;
    bool m_wantOpen = false;
    int m_backoffMs = 0;
    // Children, so that moveToThread() takes them along.
    QTimer m_timeoutTimer{this};
    QTimer m_silenceTimer{this};
    QTimer m_reconnectTimer{this};
    QTimer m_statsTimer{this};
    QElapsedTimer m_lastActivity; // last byte on the line (serial inter-frame silence)
    QElapsedTimer m_roundTrip;

    SessionStatistics m_statistics;
    std::size_t m_deframerNoise = 0; // deframers' discardedBytes() already counted
    bool m_statsDirty = false;       // statisticsChanged() due
    bool m_sharedStale = false;      // SessionShared::statistics behind

    Poller *m_poller = nullptr;
};

} // namespace Fatek
