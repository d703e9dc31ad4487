#pragma once

#include "core/transport/linksettings.h"
#include "sessionjob.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>
#include <optional>

namespace Fatek {

class LinkKeeper;
class SessionProtocol;
class StatisticsKeeper;
class TrafficLog;

// One query on the wire at a time: its frame out (after the serial line's silence), its answer
// in, timeouts, retries and the attempts that count, and the deadline checked before each
// attempt. The worker chooses the query and hears how it ended.
class QueryExchange : public QObject
{
    Q_OBJECT

public:
    // Bytes a raw console answer collects at most.
    static constexpr qsizetype maxRawAnswerBytes = 65536;

    struct Hooks
    {
        std::function<void(SessionResult result)> finished; // the query ended: end() it
        std::function<void()> idle;                    // nothing to send: choose the next query
        std::function<void(const Message &)> linkLost; // the link was dropped: a loss
    };

    QueryExchange(const LinkSettings &settings, LinkKeeper &link, SessionProtocol &protocol,
                  StatisticsKeeper &statistics, TrafficLog *log, Hooks hooks, QObject *parent);

    bool isBusy() const { return m_current.has_value(); }
    // The query on the wire (or waiting for the line's silence); null when none.
    SessionJob *current() { return m_current ? &*m_current : nullptr; }
    // Waiting for the frame to leave (a broadcast, which no PLC answers).
    bool isAwaitingSent() const { return m_awaitingSent; }
    // Sends `job` (after the line's silence).
    void begin(SessionJob job);
    // Takes the finished query out, its timer and the deframers cleared.
    SessionJob end();
    // Takes the query out as it is, timers left alone (the link is gone).
    std::optional<SessionJob> abandon();
    void stopTimers();
    // stopTimers(), and no longer waiting for a frame to leave (the link is closed).
    void halt();
    void linkOpened();
    void onBytes(const QByteArray &bytes);
    void onAllSent();

private:
    void proceed();
    void startAttempt();
    void onRawBytes(const QByteArray &bytes);
    void onTimeout();
    void retryOrFail(ProtocolError error);
    void finishExpired();
    void finishBroadcast();

    const LinkSettings &m_settings;
    LinkKeeper &m_link;
    SessionProtocol &m_protocol;
    StatisticsKeeper &m_statistics;
    TrafficLog *m_log;
    Hooks m_hooks;

    std::optional<SessionJob> m_current;
    QByteArray m_sentFrame;
    QByteArray m_answer;      // bytes of the current attempt's answer
    bool m_lineQuiet = false; // the last attempt ended with its answer and nothing after it
    // The current job needs no answer and waits for its frame to leave (Transport::allSent).
    bool m_awaitingSent = false;
    QTimer m_timeoutTimer{this};
    QTimer m_silenceTimer{this};
    QElapsedTimer m_lastActivity; // last byte on the line (serial inter-frame silence)
    QElapsedTimer m_roundTrip;
};

} // namespace Fatek
