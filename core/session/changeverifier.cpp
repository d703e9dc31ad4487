#include "changeverifier.h"

#include "core/protocol/changecheck.h"

#include <QAtomicInteger>

#include <algorithm>

namespace Fatek {

namespace {
// Read-backs not trusted in a row: the line keeps dropping answers, the outcome stays unknown.
constexpr int maxDistrusted = 4;
} // namespace

ChangeReport ChangeVerifier::reportOf(const SessionResult &result)
{
    ChangeReport report;
    report.outcome = result.outcome();
    report.result = result;
    if (report.outcome == ChangeOutcome::Refused)
        report.message = result.errorMessage();
    else if (report.outcome == ChangeOutcome::Unknown)
        report.message = msg<MsgId::ChangeUnknown>(result.errorMessage());
    report.final = report.outcome != ChangeOutcome::Unknown;
    return report;
}

RequestOptions ChangeVerifier::confirmedNow(const Session *session)
{
    RequestOptions options;
    if (session)
        options.deadline.setRemainingTime(session->settings().timeoutMs);
    return options;
}

quint64 ChangeVerifier::submit(Session *session, const Request &change, QObject *context,
                               Callback callback, RequestOptions options, Priority priority)
{
    QPointer<Session> guarded(session);
    // Without a context the read-back lives as long as the session.
    QPointer<QObject> owner(context ? context : session);
    return session->submit(
        change, context,
        [guarded, change, owner, callback = std::move(callback)](const SessionResult &result) {
            const ChangeReport first = reportOf(result);
            callback(first);
            if (!first.final && owner)
                verify(guarded.data(), change, result, owner.data(), callback);
        },
        priority, options);
}

void ChangeVerifier::verify(Session *session, const Request &change, const SessionResult &result,
                            QObject *context, Callback callback)
{
    // Parented to the context: a tool or a table that goes away takes its checks with it.
    auto *verifier = new ChangeVerifier(session, change, result, context, std::move(callback));
    verifier->ask();
}

ChangeVerifier::ChangeVerifier(Session *session, const Request &change, const SessionResult &result,
                               QObject *context, Callback callback)
    : QObject(context)
    , m_session(session)
    , m_change(change)
    , m_result(result)
    , m_callback(std::move(callback))
{
    m_retry.setSingleShot(true);
    connect(&m_retry, &QTimer::timeout, this, &ChangeVerifier::ask);
    if (session) {
        connect(session, &Session::linkStateChanged, this,
                [this](LinkState state) { onLinkState(state); });
        connect(session, &QObject::destroyed, this, [this] { onLinkState(LinkState::Closed); });
    }
}

void ChangeVerifier::ask()
{
    if (m_asking)
        return;
    const std::optional<Request> read = ChangeCheck::readBack(m_change);
    if (!read) {
        conclude(ChangeOutcome::Unknown, msg<MsgId::ChangeNoReadBack>());
        return;
    }
    if (!m_session || m_session->linkState() == LinkState::Closed) {
        conclude(ChangeOutcome::Unknown,
                 msg<MsgId::ChangeStillUnknown>(msg<MsgId::LinkSessionClosed>()));
        return;
    }
    if (m_session->linkState() != LinkState::Connected) {
        m_waitingForLink = true; // asked when the link is back (onLinkState)
        return;
    }
    if (!m_fenced) {
        askFence();
        return;
    }
    m_read = *read;
    m_asking = true;
    m_session->submit(m_read, this, [this](const SessionResult &answer) { onAnswer(answer); });
}

void ChangeVerifier::askFence()
{
    // Data no earlier query carried: an older fence's late echo differs and is not taken.
    static QAtomicInteger<quint32> counter;
    const QByteArray data
        = "FENCE" + QByteArray::number(++counter, 16).toUpper().rightJustified(8, '0');
    m_fence = Request::loopback(m_change.station, Bytes(data.begin(), data.end()));
    m_asking = true;
    m_session->submit(m_fence, this, [this](const SessionResult &answer) { onFence(answer); });
}

void ChangeVerifier::onFence(const SessionResult &answer)
{
    m_asking = false;
    const ErrorKind kind = answer.ok() ? ErrorKind::InvalidRequest : answer.errorKind();
    if (answer.ok() || kind == ErrorKind::PlcError || kind == ErrorKind::Unsupported
        || kind == ErrorKind::InvalidRequest) {
        // Answered in order: nothing sent before it is still owed. (A PLC that refuses the
        // loopback is read back without the fence, as before.)
        m_fenced = true;
        m_timeoutsAtFence = stationTimeouts();
        ask();
        return;
    }
    if (kind == ErrorKind::MalformedResponse) {
        // An earlier fence's echo (other data): this one's answer is behind it.
        ask();
        return;
    }
    if (!m_session || m_session->linkState() == LinkState::Closed) {
        conclude(ChangeOutcome::Unknown, msg<MsgId::ChangeStillUnknown>(answer.errorMessage()));
        return;
    }
    m_retry.start(std::max(500, m_session->settings().timeoutMs));
}

quint64 ChangeVerifier::stationTimeouts() const
{
    if (!m_session)
        return 0;
    return m_session->statistics().stations.value(m_change.station).timeouts;
}

void ChangeVerifier::onAnswer(const SessionResult &answer)
{
    m_asking = false;
    if (answer.ok()) {
        // Another query to this station went unanswered since the fence: its late answer may be
        // the one taken for the read-back's. Fenced again (the read-back's own retries are its
        // own reads, after the fence).
        const quint64 own = answer.attempts() > 1 ? static_cast<quint64>(answer.attempts() - 1) : 0;
        if (stationTimeouts() - m_timeoutsAtFence > own) {
            if (++m_distrusted >= maxDistrusted) {
                conclude(ChangeOutcome::Unknown,
                         msg<MsgId::ChangeStillUnknown>(msg<MsgId::ChangeAnswersLost>()));
                return;
            }
            m_fenced = false;
            ask();
            return;
        }
        if (ChangeCheck::inPlace(m_change, answer.response()))
            conclude(ChangeOutcome::Done, msg<MsgId::ChangeReadBackDone>());
        else
            conclude(ChangeOutcome::Refused, msg<MsgId::ChangeReadBackNotDone>());
        return;
    }
    if (answer.errorKind() == ErrorKind::PlcError || answer.errorKind() == ErrorKind::ReadOnly
        || answer.errorKind() == ErrorKind::InvalidRequest
        || answer.errorKind() == ErrorKind::InvalidAddress
        || answer.errorKind() == ErrorKind::Unsupported) {
        // The PLC (or the protocol) will not let this be read: asking again tells nothing more.
        conclude(ChangeOutcome::Unknown, msg<MsgId::ChangeStillUnknown>(answer.errorMessage()));
        return;
    }
    // No answer yet (timeout, link lost): again once the link is up, a timeout's length later.
    if (!m_session || m_session->linkState() == LinkState::Closed) {
        conclude(ChangeOutcome::Unknown, msg<MsgId::ChangeStillUnknown>(answer.errorMessage()));
        return;
    }
    m_retry.start(std::max(500, m_session->settings().timeoutMs));
}

void ChangeVerifier::onLinkState(LinkState state)
{
    if (state == LinkState::Closed) {
        if (!m_asking) // an asked read-back still gets its own answer (Cancelled)
            conclude(ChangeOutcome::Unknown,
                     msg<MsgId::ChangeStillUnknown>(msg<MsgId::LinkSessionClosed>()));
        return;
    }
    if (state == LinkState::Connected && std::exchange(m_waitingForLink, false))
        ask();
}

void ChangeVerifier::conclude(ChangeOutcome outcome, Message message)
{
    if (!m_callback)
        return;
    m_retry.stop();
    ChangeReport report;
    report.outcome = outcome;
    report.final = true;
    report.message = std::move(message);
    report.result = m_result;
    auto callback = std::exchange(m_callback, {});
    deleteLater();
    callback(report);
}

} // namespace Fatek
