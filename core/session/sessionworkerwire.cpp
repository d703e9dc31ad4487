// SessionWorker, one query on the wire: attempts, answers, timeouts, retries, delivery.
#include "sessionworker.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "core/protocol/rawframe.h"
#include "core/transport/transport.h"
#include "crossthreadcall.h"
#include "qtbytes.h"
#include "trafficlog.h"

#include <algorithm>

namespace Fatek {

// ---- one query on the wire ----------------------------------------------------------------------

void SessionWorker::proceed()
{
    if (!m_current) {
        schedulePump();
        return;
    }
    if (m_state != LinkState::Connected)
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

void SessionWorker::startAttempt()
{
    SessionJob &job = *m_current;
    const std::optional<Protocol> chosen = job.probe ? job.probe
                                           : job.raw ? job.options.framing
                                                     : std::nullopt;
    const Codec *activeCodec
        = chosen ? (*chosen == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get())
                 : codec();

    // Stale bytes (a late answer to a timed-out query, noise) must not join the next answer. After
    // a clean answer with nothing behind it the line was quiet at the last read, and the kernel
    // is not asked again (a read that finds nothing, per transaction): only an attempt after a
    // timeout, an error or a raw frame can have a late answer coming.
    const QByteArray stale = m_lineQuiet ? QByteArray() : m_transport->takePending();
    m_lineQuiet = false;
    const std::size_t partial
        = m_faconDeframer->bufferedBytes() + m_binaryDeframer->bufferedBytes();
    m_faconDeframer->reset();
    m_binaryDeframer->reset();
    if (!stale.isEmpty()) {
        m_log->append(TrafficEntry::Direction::In, stale, msg<MsgId::LogStaleBytes>(),
                      msg<MsgId::LogOutsideAnswer>());
    }
    if (!stale.isEmpty() || partial > 0) {
        m_statistics.bytesDiscarded += static_cast<quint64>(stale.size()) + partial;
        m_statistics.total.bytesIn += static_cast<quint64>(stale.size());
    }

    QByteArray frame;
    if (job.raw) {
        frame = toQByteArray(RawFrame::frame(bytesOf(job.rawBytes),
                                             job.addFraming ? std::optional(activeCodec->protocol())
                                                            : std::nullopt));
    } else {
        const Result<Bytes> encoded = activeCodec->encodeRequest(job.request);
        if (!encoded) {
            finishCurrent(SessionResult::fromError(encoded.error()));
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
    const quint8 station = stationOf(job);
    if (job.attempts > 1)
        countForStation(station, [](StationStatistics &s) { ++s.retries; });
    m_answer.clear();
    m_sentFrame = frame;
    if (!m_transport->write(frame)) {
        // The transport reports the failure itself (disconnected); make sure the job ends. This
        // attempt never left: only earlier ones count as sent.
        --job.attempts;
        finishCurrent(SessionResult::fromError(
            makeError(ErrorKind::LinkError,
                      msg<MsgId::SessionCouldNotWrite>(m_transport->describe().toStdString())),
            {}, job.raw));
        return;
    }
    m_lastActivity.start();
    m_roundTrip.start();
    countForStation(station, [&frame](StationStatistics &s) {
        s.bytesOut += static_cast<quint64>(frame.size());
    });
    m_log->append(TrafficEntry::Direction::Out, frame, summarize(frame));

    if (!job.raw && job.request.station == Limits::broadcastStation) {
        // Broadcast: every PLC acts and none answers. Done once the frame has left this machine,
        // not when it is only queued: a close right after the result must not lose it.
        if (m_transport->unsentBytes() > 0) {
            m_awaitingSent = true;
            m_timeoutTimer.start(timeoutFor(job));
            return;
        }
        finishBroadcast();
        return;
    }
    m_timeoutTimer.start(timeoutFor(job));
}

void SessionWorker::finishExpired()
{
    SessionJob &job = *m_current;
    m_log->append(TrafficEntry::Direction::Event, {},
                  job.raw ? msg<MsgId::LogRawFrame>() : Message::text(job.request.describe()),
                  msg<MsgId::SessionExpired>());
    finishCurrent(SessionResult::fromError(
        makeError(ErrorKind::Expired, msg<MsgId::SessionExpired>()), {}, job.raw));
}

void SessionWorker::finishBroadcast()
{
    Response response;
    response.station = 0;
    response.command = m_current->request.command;
    finishCurrent(SessionResult(Result<Response>(response)));
}

Message SessionWorker::summarize(const QByteArray &frame) const
{
    if (const Codec *c = codec())
        return c->summary(bytesOf(frame));
    // Protocol not known yet: the frame's first byte tells.
    return RawFrame::summary(bytesOf(frame));
}

void SessionWorker::onBytes(const QByteArray &bytes)
{
    m_lastActivity.start();
    if (!m_current || !m_timeoutTimer.isActive() || m_awaitingSent) {
        // Nothing asked: a late answer or noise. Dropped now, logged, and counted.
        m_log->append(TrafficEntry::Direction::In, bytes, msg<MsgId::LogUnexpectedBytes>(),
                      msg<MsgId::LogNoQueryPending>());
        m_statistics.total.bytesIn += static_cast<quint64>(bytes.size());
        m_statistics.bytesDiscarded += static_cast<quint64>(bytes.size());
        statisticsChangedInternally();
        return;
    }
    SessionJob &job = *m_current;
    const quint8 station = stationOf(job);
    countForStation(station, [&bytes](StationStatistics &s) {
        s.bytesIn += static_cast<quint64>(bytes.size());
    });
    if (job.raw) {
        onRawBytes(bytes);
        return;
    }

    const Protocol protocol = job.probe ? *job.probe : *m_protocol;
    const Codec *activeCodec
        = protocol == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get();
    Deframer *deframer
        = protocol == Protocol::Facon ? m_faconDeframer.get() : m_binaryDeframer.get();
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    countDeframerNoise();
    for (DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        if (item.error) {
            m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                          item.error->message);
            if (item.error->kind == ErrorKind::BadChecksum)
                countForStation(station, [](StationStatistics &s) { ++s.checksumErrors; });
            else
                countForStation(station, [](StationStatistics &s) { ++s.frameErrors; });
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
            m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                          decoded.error().message);
            continue;
        }
        m_log->append(TrafficEntry::Direction::In, frame, summarize(frame),
                      decoded ? Message{} : decoded.error().message);
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        const bool refusal = !decoded && decoded.error().kind == ErrorKind::PlcError;
        // A poll asking again for an element the PLC refused before expects the refusal.
        const bool plcError = refusal && !m_current->options.expectRefusal;
        const bool malformed = !decoded && !refusal;
        countForStation(station, [rtt, plcError, malformed](StationStatistics &s) {
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
        finishCurrent(SessionResult(std::move(decoded), frame));
        return;
    }
}

void SessionWorker::onRawBytes(const QByteArray &bytes)
{
    m_answer += bytes;
    if (m_answer.size() > maxRawAnswerBytes) {
        // A peer that floods the console: keep what fits and end now rather than at the timeout.
        m_answer.truncate(maxRawAnswerBytes);
        m_log->append(TrafficEntry::Direction::In, m_answer, msg<MsgId::LogRawAnswer>(),
                      msg<MsgId::LogRestNotRead>(maxRawAnswerBytes));
        finishCurrent(SessionResult::fromRaw(m_answer));
        return;
    }
    // End early once a complete frame of the link's protocol came back (or of the protocol the
    // frame was framed in, or looks like); otherwise collect until the timeout.
    std::optional<Protocol> protocol = m_protocol;
    if (!protocol)
        protocol = m_current->options.framing;
    if (!protocol && RawFrame::protocolOf(bytesOf(m_sentFrame)) == Protocol::Facon)
        protocol = Protocol::Facon;
    if (!protocol)
        return;
    Deframer *deframer
        = *protocol == Protocol::Facon ? m_faconDeframer.get() : m_binaryDeframer.get();
    std::vector<DeframedItem> items;
    deframer->feed(bytesOf(bytes), items);
    // Bytes around a console answer are the answer, not noise.
    m_deframerNoise = m_faconDeframer->discardedBytes() + m_binaryDeframer->discardedBytes();
    for (const DeframedItem &item : items) {
        const QByteArray frame = toQByteArray(item.frame);
        const double rtt = static_cast<double>(m_roundTrip.nsecsElapsed()) / 1e6;
        countForStation(0, [rtt](StationStatistics &s) {
            ++s.answers;
            s.addRoundTrip(rtt);
        });
        if (item.error)
            countForStation(0, [](StationStatistics &s) { ++s.checksumErrors; });
        m_log->append(TrafficEntry::Direction::In, m_answer, summarize(frame),
                      item.error ? item.error->message : Message{});
        finishCurrent(SessionResult::fromRaw(m_answer));
        return;
    }
}

void SessionWorker::onTimeout()
{
    if (!m_current)
        return;
    SessionJob &job = *m_current;
    const int timeout = timeoutFor(job);
    if (m_awaitingSent) {
        // Never retried: the stuck copy may still leave, and the PLC would act twice.
        m_awaitingSent = false;
        const std::string link = m_transport->describe().toStdString();
        const Message message = msg<MsgId::SessionFrameNotTaken>(
            link, timeout, std::min<qint64>(m_transport->unsentBytes(), m_sentFrame.size()),
            m_sentFrame.size());
        m_log->append(TrafficEntry::Direction::Event, {}, Message::text(job.request.describe()),
                      message);
        // The frame did not leave whole: a PLC acts on no part of a frame.
        --job.attempts;
        finishCurrent(SessionResult::fromError(makeError(ErrorKind::LinkError, message)));
        // Reported as not sent, so it must never leave later: drop the link and what it holds.
        m_transport->close();
        onDisconnected(msg<MsgId::LinkDoesNotTakeData>(link));
        return;
    }
    if (job.raw) {
        if (m_answer.isEmpty()) {
            countForStation(0, [](StationStatistics &s) { ++s.timeouts; });
            m_log->append(TrafficEntry::Direction::Event, {}, msg<MsgId::LogRawFrame>(),
                          msg<MsgId::LogNoAnswerWithin>(timeout));
            finishCurrent(SessionResult::fromError(
                makeError(ErrorKind::Timeout, msg<MsgId::SessionNoAnswerWithin>(timeout)), {},
                true));
        } else {
            m_log->append(TrafficEntry::Direction::In, m_answer, msg<MsgId::LogRawAnswer>(),
                          msg<MsgId::LogNoCompleteFrame>());
            finishCurrent(SessionResult::fromRaw(m_answer));
        }
        return;
    }
    const quint8 station = stationOf(job);
    countForStation(station, [](StationStatistics &s) { ++s.timeouts; });
    const int attempts = retriesFor(job) + 1;
    const Message message
        = msg<MsgId::SessionNoAnswerFromStation>(station, timeout, job.attempts, attempts);
    m_log->append(TrafficEntry::Direction::Event, {}, Message::text(job.request.describe()),
                  message);
    retryOrFail(makeError(ErrorKind::Timeout, message));
}

void SessionWorker::retryOrFail(ProtocolError error)
{
    SessionJob &job = *m_current;
    if (job.attempts <= retriesFor(job) && !job.options.deadline.hasExpired()) {
        proceed();
        return;
    }
    finishCurrent(SessionResult::fromError(std::move(error), m_answer, job.raw));
}

void SessionWorker::finishCurrent(SessionResult result)
{
    m_timeoutTimer.stop();
    m_awaitingSent = false;
    m_faconDeframer->reset();
    m_binaryDeframer->reset();
    SessionJob job = std::move(*m_current);
    m_current.reset();
    result.setAttempts(job.attempts);
    if (!job.probe)
        countForStation(stationOf(job), [](StationStatistics &s) { ++s.requests; });
    // Probes count too: with auto-detect a silent station never gets past them.
    if (!job.raw && !result.ok() && result.errorKind() == ErrorKind::Timeout)
        countForStation(stationOf(job), [](StationStatistics &s) { ++s.unanswered; });
    if (!job.raw && !job.probe && !job.fromPoller
        && job.request.station != Limits::broadcastStation)
        m_poller->noteAnswer(job.request.station, result);
    publishStatistics(); // before the result, so statistics() already counts it
    deliver(job, std::move(result));
    schedulePump();
}

void SessionWorker::deliver(SessionJob &job, SessionResult result)
{
    if (job.pendingWrite) {
        job.pendingWrite = false;
        m_shared->pendingWrites.fetch_sub(1);
    }
    // Also when a job on the wire is cut off (link lost, close): its frame may have been acted on.
    result.setAttempts(job.attempts);
    if (job.done) {
        auto done = std::move(job.done);
        done(result);
    } else if (job.id != 0) {
        Q_EMIT finished(job.id, result);
    }
}

} // namespace Fatek
