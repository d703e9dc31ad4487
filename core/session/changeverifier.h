#pragma once

#include "core/protocol/request.h"
#include "session.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>

namespace Fatek {

// What a change to a PLC came to, as reported to the person or program that asked for it.
struct ChangeReport
{
    ChangeOutcome outcome = ChangeOutcome::Refused;
    // False only for the first report of an unknown outcome: a final one follows (done, not done,
    // or still unknown) once the change was read back or could no longer be.
    bool final = true;
    // Why refused, why unknown, or what the read-back found (empty when simply done).
    Message message;
    // The change's own result (the first report's; the read-back's verdict keeps it too).
    SessionResult result;
};

// The one rule for every path that changes a PLC (table writes, the CLI, the gateway's /set,
// forcing, the checkout, recipes, RUN/STOP): the outcome is done, refused (nothing sent, or the
// PLC said no), or unknown (sent, not answered). An unknown outcome is read back (ChangeCheck) as
// soon as the link answers again, and reported a second time, final: done or not done; still
// unknown only if the link is closed first or no read can tell. The read-back follows a fence (a
// loopback answered with its own data) so that no late answer of an earlier query is taken for
// it. Lives in the caller's thread.
class ChangeVerifier : public QObject
{
    Q_OBJECT

public:
    using Callback = std::function<void(const ChangeReport &report)>;

    // Submits `change` and reports on `context`'s thread: once, or twice (final = false, then
    // true) when its outcome is unknown. Dropped if `context` is destroyed first. Returns the
    // change's request id.
    static quint64 submit(Session *session, const Request &change, QObject *context,
                          Callback callback, RequestOptions options = {},
                          Priority priority = Priority::User);
    // Options for a change a person confirmed just now: not sent later than the link's timeout
    // from now (it must not land long after the question was answered). No session: defaults
    // (the request is refused anyway).
    static RequestOptions confirmedNow(const Session *session);
    // Reads back `change` (sent, its outcome unknown: `result`) and reports once, final.
    static void verify(Session *session, const Request &change, const SessionResult &result,
                       QObject *context, Callback callback);
    // The first report of a change's own result.
    static ChangeReport reportOf(const SessionResult &result);

private:
    ChangeVerifier(Session *session, const Request &change, const SessionResult &result,
                   QObject *context, Callback callback);
    void ask();
    void askFence();
    void onFence(const SessionResult &answer);
    void onAnswer(const SessionResult &answer);
    // Attempts to the change's station that went unanswered so far (the session's counters).
    quint64 stationTimeouts() const;
    void onLinkState(LinkState state);
    void conclude(ChangeOutcome outcome, Message message);

    QPointer<Session> m_session;
    Request m_change;
    Request m_read;
    SessionResult m_result;
    Callback m_callback;
    QTimer m_retry;
    bool m_asking = false;
    bool m_waitingForLink = false;
    // The fence: a loopback with data of its own, answered before the read-back is asked. The
    // PLC answers in order, so every late answer to an earlier query (same station, same shape:
    // FACON answers carry no address) has come and gone by then and none is taken for the
    // read-back's.
    Request m_fence;
    bool m_fenced = false;
    quint64 m_timeoutsAtFence = 0;
    int m_distrusted = 0; // read-backs answered but not trusted
};

} // namespace Fatek
