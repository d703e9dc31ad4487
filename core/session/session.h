#pragma once

#include "core/protocol/request.h"
#include "core/transport/linksettings.h"
#include "sessionresult.h"
#include "sessionstatistics.h"
#include "sessiontypes.h"
#include "trafficlog.h"
#include "watchvalue.h"

#include <QObject>
#include <QThread>

#include <atomic>
#include <functional>
#include <memory>

namespace Fatek {

class CrossThreadQueue;
class SessionWorker;
struct SessionCompletions;
struct SessionJob;
struct SessionShared;

// One link (one transport, one protocol) serving one or several stations. The Session object
// lives in the caller's thread; the I/O runs on a worker QThread it owns. Every public function
// is thread-safe and returns at once; each submitted request gets exactly one finished() with its
// id, and, if it was submitted with a completion, one call of that completion.
class Session : public QObject
{
    Q_OBJECT

public:
    // What a request submitted with a context object is answered with (see submit()).
    using Completion = std::function<void(const SessionResult &result)>;

    explicit Session(const LinkSettings &settings, QObject *parent = nullptr);
    // Closes like close(CloseMode::Drain) (blocking at most closeDrainMs() and a little more),
    // then stops the worker thread; results that come meanwhile are not signalled.
    ~Session() override;

    LinkSettings settings() const { return m_settings; }

    // Connects (and keeps reconnecting with backoff if the settings say so).
    void open();
    // Disconnects. Drain: accepted writes (write commands, RUN/STOP, raw frames) and bytes not
    // yet sent go first, bounded by closeDrainMs(); reads and polls finish with
    // ErrorKind::Cancelled at once, as does what the bound cut off. linkStateChanged(Closed) comes
    // when the link is closed. Discard: everything finishes with Cancelled at once.
    void close(CloseMode mode = CloseMode::Drain);
    // Writes accepted and not finished yet (queued, or on the wire waiting to leave or for the
    // answer): what a close would wait for.
    int pendingWrites() const;
    // How long a close waits for pending writes [3000 ms].
    void setCloseDrainMs(int ms);
    int closeDrainMs() const;

    // Queues a request; returns its id (never 0). Requests submitted while the link is down
    // (and not connecting) finish at once with ErrorKind::LinkError.
    quint64 submit(const Request &request, Priority priority = Priority::User,
                   RequestOptions options = {});
    // The same, and `completion` is called once with the result on `context`'s thread, right after
    // finished() (queued there if `context` lives in another thread): on success and on every
    // error, cancel and close included. It is dropped, never called, if `context` is destroyed
    // first, or if this Session is destroyed before the result comes (as finished() is).
    quint64 submit(const Request &request, QObject *context, Completion completion,
                   Priority priority = Priority::User, RequestOptions options = {});
    // Raw console: sends `bytes` as typed (or wrapped in the protocol's framing and checksum when
    // addFraming is set) and returns whatever comes back within the timeout.
    quint64 sendRaw(const QByteArray &bytes, bool addFraming, RequestOptions options = {});
    quint64 sendRaw(const QByteArray &bytes, bool addFraming, QObject *context,
                    Completion completion, RequestOptions options = {});
    // Drops a queued request (finished() with Cancelled); a request already on the wire completes.
    void cancel(quint64 id);
    // cancel() for every request submitted with `context` and not finished yet.
    void cancelAll(const QObject *context);

    // Operator mode: write commands and raw frames are refused (ErrorKind::ReadOnly) before the
    // wire.
    void setReadOnly(bool readOnly);
    bool isReadOnly() const;

    // The protocol in use; with auto-detect, whether it is known yet.
    Protocol protocol() const;
    bool isProtocolKnown() const;
    LinkState linkState() const;

    // Latest counters (updated as requests finish).
    SessionStatistics statistics() const;
    void resetStatistics();

    TrafficLog *trafficLog() const { return m_log; }

    // Polling: replaces the watch list (re-plans); an empty list stops polling.
    void setWatchList(const QList<WatchEntry> &entries);

    // Runs the calls posted to this object (CrossThreadCall, CrossThreadQueue).
    bool event(QEvent *event) override;

Q_SIGNALS:
    void finished(quint64 id, const Fatek::SessionResult &result);
    void linkStateChanged(Fatek::LinkState state, const Fatek::Message &reason);
    // At most 4 times a second.
    void statisticsChanged(const Fatek::SessionStatistics &statistics);
    void protocolDetected(Fatek::Protocol protocol);
    // One batch per completed poll cycle.
    void values(const QList<Fatek::WatchValue> &values);

private:
    quint64 enqueue(SessionJob &job, QObject *context, Completion completion);
    // On this object's thread, after finished(id).
    void complete(quint64 id, const SessionResult &result);

    LinkSettings m_settings;
    std::shared_ptr<SessionShared> m_shared;
    TrafficLog *m_log;
    QThread m_thread;
    SessionWorker *m_worker;
    std::atomic<quint64> m_nextId{1};
    std::unique_ptr<SessionCompletions> m_completions;
    // The worker's signals, relayed to this object's thread in batches and in order.
    std::unique_ptr<CrossThreadQueue> m_inbox;
};

void registerSessionMetaTypes();

} // namespace Fatek
