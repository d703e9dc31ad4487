#pragma once

#include "core/transport/linksettings.h"
#include "crossthreadqueue.h"
#include "linkkeeper.h"
#include "poller.h"
#include "queryexchange.h"
#include "requestqueue.h"
#include "sessionjob.h"
#include "sessionprotocol.h"
#include "sessionresult.h"
#include "sessionshared.h"
#include "sessionstatistics.h"
#include "sessiontypes.h"
#include "statisticskeeper.h"

#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>
#include <vector>

namespace Fatek {

class TrafficLog;

// The session's engine, living on its worker thread. It orchestrates: which request goes next
// (RequestQueue), when the link may carry it (LinkKeeper), the query on the wire (QueryExchange),
// the protocol and its auto-detect (SessionProtocol), the counters (StatisticsKeeper), the
// poller, and closing with accepted writes drained. Only the Session calls it, through its
// inbox().
class SessionWorker : public QObject
{
    Q_OBJECT

public:
    // Requests a user or background queue holds at most; more are refused (LimitExceeded).
    static constexpr std::size_t maxQueuedRequests = RequestQueue::maxQueued;
    // Bytes a raw console answer collects at most.
    static constexpr qsizetype maxRawAnswerBytes = QueryExchange::maxRawAnswerBytes;

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
    void schedulePump();
    void pump();
    bool prepare(SessionJob &job); // false: job finished or deferred
    void detectProtocol(SessionJob job);
    void finishCurrent(SessionResult result);
    void deliver(SessionJob &job, SessionResult result);
    void failAll(ErrorKind kind, const Message &reason, bool includePolls);
    void onAllSent();
    void cancelReadsForClose();
    void checkDrained();
    void closeNow(const Message &reason);

    void onOpened();
    void onDisconnected(const Message &reason);
    void setProtocol(Protocol protocol);
    void onStationHealth(quint8 station, bool demoted, const QDateTime &nextTry, int unanswered);

    LinkSettings m_settings;
    std::shared_ptr<SessionShared> m_shared;
    TrafficLog *m_log;
    SessionProtocol m_protocol{m_shared};
    RequestQueue m_queue;
    // Children, so that moveToThread() takes them (and their timers) along.
    StatisticsKeeper m_statistics{m_shared, this};
    LinkKeeper m_link{m_settings, m_shared, this};
    QueryExchange m_exchange;

    bool m_pumpScheduled = false; // a queued pump() is on its way
    bool m_pumpDue = false;       // pump() when the inbox's batch or the answer's handling ends
    bool m_pumpHeld = false;      // an answer is being handled
    // Requests handed over together are all queued before the next one is chosen (priorities),
    // and the next one goes in the same turn of the event loop, not in a queued pump().
    CrossThreadQueue m_inbox{this, [this] {
                                 if (std::exchange(m_pumpDue, false))
                                     pump();
                             }};
    // close(drain) in progress: writes still go, nothing new is accepted.
    bool m_closing = false;
    std::vector<std::function<void()>> m_whenClosed;
    QTimer m_drainTimer{this};

    Poller *m_poller = nullptr;
};

} // namespace Fatek
