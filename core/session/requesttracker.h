#pragma once

#include "changeverifier.h"
#include "core/protocol/request.h"
#include "session.h"

#include <QObject>
#include <QPointer>

namespace Fatek {

// The requests of one tool (a panel, a scan, a CLI command) to one session at a time, each
// answered by its callback on the tracker's thread (Session::submit with the tracker as the
// context). Answers meant for a previous session, or forgotten with forgetPending(), are dropped;
// a session deleted under us simply stops answering: nothing ever blocks waiting for the wire.
class RequestTracker : public QObject
{
    Q_OBJECT

public:
    using Callback = Session::Completion;

    explicit RequestTracker(QObject *parent = nullptr);

    // A new session forgets what is pending on the old one.
    void setSession(Session *session);
    Session *session() const { return m_session.data(); }

    // Returns the request id, or 0 when there is no session (the callback is then not called).
    quint64 submit(const Request &request, Callback callback, RequestOptions options = {},
                   Priority priority = Priority::User);
    quint64 sendRaw(const QByteArray &bytes, bool addFraming, Callback callback,
                    RequestOptions options = {});
    // A change (write, RUN/STOP, forcing) under the one rule of ChangeVerifier: reported once, or
    // twice for an unknown outcome (first not final, then what the read-back found). Pending until
    // the final report.
    quint64 submitChange(const Request &change, ChangeVerifier::Callback callback,
                         RequestOptions options = {});
    // Forgets the callbacks of the requests still pending (their answers are ignored).
    void forgetPending();
    // Cancels in the session what this tracker submitted and is still queued, and forgets it all.
    void cancelPending();
    // Requests submitted and not answered yet (forgotten ones not counted).
    int pendingCount() const { return m_pendingCount; }

Q_SIGNALS:
    // The session set here was deleted (its link closed for good): a tool shows "no connection".
    void sessionDestroyed();

private:
    Callback track(Callback callback);

    QPointer<Session> m_session;
    QMetaObject::Connection m_destroyed;
    // Callbacks of an older generation (forgotten, or of a previous session) do nothing.
    quint64 m_generation = 0;
    int m_pendingCount = 0;
};

} // namespace Fatek
