#include "queryexchange.h"

#include "core/protocol/rawframe.h"
#include "core/transport/transport.h"
#include "linkkeeper.h"
#include "qtbytes.h"
#include "sessionprotocol.h"
#include "statisticskeeper.h"
#include "trafficlog.h"

#include <algorithm>

namespace Fatek {

QueryExchange::QueryExchange(const LinkSettings &settings, LinkKeeper &link,
                             SessionProtocol &protocol, StatisticsKeeper &statistics,
                             TrafficLog *log, Hooks hooks, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_link(link)
    , m_protocol(protocol)
    , m_statistics(statistics)
    , m_log(log)
    , m_hooks(std::move(hooks))
{
    m_timeoutTimer.setSingleShot(true);
    m_silenceTimer.setSingleShot(true);
    m_timeoutTimer.setTimerType(Qt::PreciseTimer);
    m_silenceTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &QueryExchange::onTimeout);
    connect(&m_silenceTimer, &QTimer::timeout, this, &QueryExchange::proceed);
    m_lastActivity.start();
}

void QueryExchange::begin(SessionJob job)
{
    m_current = std::move(job);
    proceed();
}

SessionJob QueryExchange::end()
{
    m_timeoutTimer.stop();
    m_awaitingSent = false;
    m_protocol.resetDeframers();
    SessionJob job = std::move(*m_current);
    m_current.reset();
    return job;
}

std::optional<SessionJob> QueryExchange::abandon()
{
    // The wait for a broadcast's frame is the query's: a later query must not inherit it.
    m_awaitingSent = false;
    return std::exchange(m_current, std::nullopt);
}

void QueryExchange::stopTimers()
{
    m_silenceTimer.stop();
    m_timeoutTimer.stop();
}

void QueryExchange::halt()
{
    m_awaitingSent = false;
    stopTimers();
}

void QueryExchange::linkOpened()
{
    m_lineQuiet = false;
    m_lastActivity.start();
}

void QueryExchange::proceed()
{
    if (!m_current) {
        m_hooks.idle();
        return;
    }
    if (m_link.state() != LinkState::Connected)
        return;
    // Serial: the PLC needs a silent line between frames.
    if (m_settings.kind == LinkSettings::Kind::Serial && m_settings.interFrameMs > 0) {
        const qint64 quiet = m_lastActivity.elapsed();
        if (quiet < m_settings.interFrameMs) {
            m_silenceTimer.start(static_cast<int>(m_settings.interFrameMs - quiet));
            return;
        }
    }
    startAttempt();
}

void QueryExchange::startAttempt()
{
    SessionJob &job = *m_current;
    Transport *transport = m_link.transport();
    const std::optional<Protocol> chosen = job.probe ? job.probe
                                           : job.raw ? job.options.framing
                                                     : std::nullopt;
    const Codec *activeCodec = chosen ? m_protocol.codecFor(*chosen) : m_protocol.codec();

    // Stale bytes (a late answer to a timed-out query, noise) must not join the next answer. After
    // a clean answer with nothing behind it the line was quiet at the last read, and the kernel
    // is not asked again (a read that finds nothing, per transaction): only an attempt after a
    // timeout, an error or a raw frame can have a late answer coming.
    const QByteArray stale = m_lineQuiet ? QByteArray() : transport->takePending();
    m_lineQuiet = false;
    const std::size_t partial = m_protocol.resetDeframers();
    if (!stale.isEmpty()) {
        m_log->append(TrafficEntry::Direction::In, stale, msg<MsgId::LogStaleBytes>(),
                      msg<MsgId::LogOutsideAnswer>());
    }
    if (!stale.isEmpty() || partial > 0)
        m_statistics.discardStale(static_cast<quint64>(stale.size()), partial);

    QByteArray frame;
    if (job.raw) {
        frame = toQByteArray(RawFrame::frame(bytesOf(job.rawBytes),
                                             job.addFraming ? std::optional(activeCodec->protocol())
                                                            : std::nullopt));
    } else {
        const Result<Bytes> encoded = activeCodec->encodeRequest(job.request);
        if (!encoded) {
            m_hooks.finished(SessionResult::fromError(encoded.error()));
            return;
        }
        frame = toQByteArray(*encoded);
    }

    if (job.options.deadline.hasExpired()) {
        // Waited too long (behind other requests, a slow line, a retry's turn): not sent now.
        finishExpired();
        return;
    }
    ++job.attempts;
    const quint8 station = job.station();
    if (job.attempts > 1)
        m_statistics.count(station, [](StationStatistics &s) { ++s.retries; });
    m_answer.clear();
    m_sentFrame = frame;
    if (!transport->write(frame)) {
        // The transport reports the failure itself (disconnected); make sure the job ends. This
        // attempt never left: only earlier ones count as sent.
        --job.attempts;
        m_hooks.finished(SessionResult::fromError(
            makeError(ErrorKind::LinkError,
                      msg<MsgId::SessionCouldNotWrite>(transport->describe().toStdString())),
            {}, job.raw));
        return;
    }
    m_lastActivity.start();
    m_roundTrip.start();
    m_statistics.count(station, [&frame](StationStatistics &s) {
        s.bytesOut += static_cast<quint64>(frame.size());
    });
    m_log->append(TrafficEntry::Direction::Out, frame, m_protocol.summarize(frame));

    if (!job.raw && job.request.station == Limits::broadcastStation) {
        // Broadcast: every PLC acts and none answers. Done once the frame has left this machine,
        // not when it is only queued: a close right after the result must not lose it.
        if (transport->unsentBytes() > 0) {
            m_awaitingSent = true;
            m_timeoutTimer.start(job.timeoutMs(m_settings));
            return;
        }
        finishBroadcast();
        return;
    }
    m_timeoutTimer.start(job.timeoutMs(m_settings));
}

void QueryExchange::finishExpired()
{
    SessionJob &job = *m_current;
    m_log->append(TrafficEntry::Direction::Event, {},
                  job.raw ? msg<MsgId::LogRawFrame>() : Message::text(job.request.describe()),
                  msg<MsgId::SessionExpired>());
    m_hooks.finished(SessionResult::fromError(
        makeError(ErrorKind::Expired, msg<MsgId::SessionExpired>()), {}, job.raw));
}

void QueryExchange::finishBroadcast()
{
    Response response;
    response.station = 0;
    response.command = m_current->request.command;
    m_hooks.finished(SessionResult(Result<Response>(response)));
}

void QueryExchange::onAllSent()
{
    if (m_awaitingSent && m_current) {
        m_awaitingSent = false;
        m_timeoutTimer.stop();
        finishBroadcast();
    }
}

void QueryExchange::onBytes(const QByteArray &bytes)
{
    m_lastActivity.start();
    if (!m_current || !m_timeoutTimer.isActive() || m_awaitingSent) {
        // Nothing asked: a late answer or noise. Dropped now, logged, and counted.
        m_log->append(TrafficEntry::Direction::In, bytes, msg<MsgId::LogUnexpectedBytes>(),
                      msg<MsgId::LogNoQueryPending>());
        m_statistics.discardUnexpected(static_cast<quint64>(bytes.size()));
        return;
    }
    SessionJob &job = *m_current;
    const quint8 station = job.station();
    m_statistics.count(station, [&bytes](StationStatistics &s) {
        s.bytesIn += static_cast<quint64>(bytes.size());
    });
    if (job.raw) {
        onRawBytes(bytes);
        return;
    }

    const Protocol protocol = job.probe ? *job.probe : *m_protocol.protocol();
    const Codec *activeCodec = m_protocol.codecFor(protocol);
    Deframer *deframer = m_protocol.deframerFor(protocol);
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    if (const std::size_t noise = m_protocol.takeNoise())
        m_statistics.discardNoise(static_cast<quint64>(noise));
    for (DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        if (item.error) {
            m_log->append(TrafficEntry::Direction::In, frame, m_protocol.summarize(frame),
                          item.error->message);
            if (item.error->kind == ErrorKind::BadChecksum)
                m_statistics.count(station, [](StationStatistics &s) { ++s.checksumErrors; });
            else
                m_statistics.count(station, [](StationStatistics &s) { ++s.frameErrors; });
            // A damaged answer: ask again (or give up with this error).
            m_timeoutTimer.stop();
            retryOrFail(*item.error);
            return;
        }
        Result<Response> decoded = activeCodec->decodeResponse(item.frame, job.request);
        if (!decoded && frame == m_sentFrame) {
            // 2-wire RS-485 hears its own query. (Only when it does not decode as an answer: a
            // FACON STOP or loopback answer is byte for byte the query.)
            m_log->append(TrafficEntry::Direction::In, frame, msg<MsgId::LogEchoOfQuery>(), {});
            continue;
        }
        if (!decoded
            && (decoded.error().kind == ErrorKind::StationMismatch
                || decoded.error().kind == ErrorKind::CommandMismatch)) {
            // Another station on the bus, or a late answer to an earlier query: keep waiting.
            m_log->append(TrafficEntry::Direction::In, frame, m_protocol.summarize(frame),
                          decoded.error().message);
            continue;
        }
        m_log->append(TrafficEntry::Direction::In, frame, m_protocol.summarize(frame),
                      decoded ? Message{} : decoded.error().message);
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        const bool refusal = !decoded && decoded.error().kind == ErrorKind::PlcError;
        // A poll asking again for an element the PLC refused before expects the refusal.
        const bool plcError = refusal && !m_current->options.expectRefusal;
        const bool malformed = !decoded && !refusal;
        m_statistics.count(station, [rtt, plcError, malformed](StationStatistics &s) {
            ++s.answers;
            s.unanswered = 0;
            s.addRoundTrip(rtt);
            if (plcError)
                ++s.plcErrors;
            if (malformed)
                ++s.frameErrors;
        });
        m_answer = frame;
        // TCP only: UDP may deliver a datagram twice, and a serial bus may carry other talkers.
        m_lineQuiet = m_settings.kind == LinkSettings::Kind::Tcp && &item == &items.back()
                      && deframer->bufferedBytes() == 0;
        m_hooks.finished(SessionResult(std::move(decoded), frame));
        return;
    }
}

void QueryExchange::onRawBytes(const QByteArray &bytes)
{
    m_answer += bytes;
    if (m_answer.size() > maxRawAnswerBytes) {
        // A peer that floods the console: keep what fits and end now rather than at the timeout.
        m_answer.truncate(maxRawAnswerBytes);
        m_log->append(TrafficEntry::Direction::In, m_answer, msg<MsgId::LogRawAnswer>(),
                      msg<MsgId::LogRestNotRead>(maxRawAnswerBytes));
        m_hooks.finished(SessionResult::fromRaw(m_answer));
        return;
    }
    // End early once a complete frame of the link's protocol came back (or of the protocol the
    // frame was framed in, or looks like); otherwise collect until the timeout.
    std::optional<Protocol> protocol = m_protocol.protocol();
    if (!protocol)
        protocol = m_current->options.framing;
    if (!protocol && RawFrame::protocolOf(bytesOf(m_sentFrame)) == Protocol::Facon)
        protocol = Protocol::Facon;
    if (!protocol)
        return;
    Deframer *deframer = m_protocol.deframerFor(*protocol);
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    // Bytes around a console answer are the answer, not noise.
    m_protocol.skipNoise();
    for (const DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        m_statistics.count(0, [rtt](StationStatistics &s) {
            ++s.answers;
            s.addRoundTrip(rtt);
        });
        if (item.error)
            m_statistics.count(0, [](StationStatistics &s) { ++s.checksumErrors; });
        m_log->append(TrafficEntry::Direction::In, m_answer, m_protocol.summarize(frame),
                      item.error ? item.error->message : Message{});
        m_hooks.finished(SessionResult::fromRaw(m_answer));
        return;
    }
}

void QueryExchange::onTimeout()
{
    if (!m_current)
        return;
    SessionJob &job = *m_current;
    const int timeout = job.timeoutMs(m_settings);
    if (m_awaitingSent) {
        // Never retried: the stuck copy may still leave, and the PLC would act twice.
        m_awaitingSent = false;
        Transport *transport = m_link.transport();
        const std::string link = transport->describe().toStdString();
        const Message message = msg<MsgId::SessionFrameNotTaken>(
            link, timeout, std::min<qint64>(transport->unsentBytes(), m_sentFrame.size()),
            m_sentFrame.size());
        m_log->append(TrafficEntry::Direction::Event, {}, Message::text(job.request.describe()),
                      message);
        // The frame did not leave whole: a PLC acts on no part of a frame.
        --job.attempts;
        m_hooks.finished(SessionResult::fromError(makeError(ErrorKind::LinkError, message)));
        // Reported as not sent, so it must never leave later: drop the link and what it holds.
        transport->close();
        m_hooks.linkLost(msg<MsgId::LinkDoesNotTakeData>(link));
        return;
    }
    if (job.raw) {
        if (m_answer.isEmpty()) {
            m_statistics.count(0, [](StationStatistics &s) { ++s.timeouts; });
            m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogRawFrame>(),
                          msg<MsgId::LogNoAnswerWithin>(timeout));
            m_hooks.finished(SessionResult::fromError(
                makeError(ErrorKind::Timeout, msg<MsgId::SessionNoAnswerWithin>(timeout)), {},
                true));
        } else {
            m_log->append(TrafficEntry::Direction::In, m_answer, msg<MsgId::LogRawAnswer>(),
                          msg<MsgId::LogNoCompleteFrame>());
            m_hooks.finished(SessionResult::fromRaw(m_answer));
        }
        return;
    }
    const quint8 station = job.station();
    m_statistics.count(station, [](StationStatistics &s) { ++s.timeouts; });
    const int attempts = job.retries(m_settings) + 1;
    const Message message
        = msg<MsgId::SessionNoAnswerFromStation>(station, timeout, job.attempts, attempts);
    m_log->append(TrafficEntry::Direction::Event, {}, Message::text(job.request.describe()),
                  message);
    retryOrFail(makeError(ErrorKind::Timeout, message));
}

void QueryExchange::retryOrFail(ProtocolError error)
{
    SessionJob &job = *m_current;
    if (job.attempts <= job.retries(m_settings) && !job.options.deadline.hasExpired()) {
        proceed();
        return;
    }
    m_hooks.finished(SessionResult::fromError(std::move(error), m_answer, job.raw));
}

} // namespace Fatek
