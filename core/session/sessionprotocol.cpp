#include "sessionprotocol.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "core/protocol/faconcodec.h"
#include "core/protocol/facondeframer.h"
#include "core/protocol/rawframe.h"
#include "qtbytes.h"
#include "sessionshared.h"

namespace Fatek {

SessionProtocol::SessionProtocol(std::shared_ptr<SessionShared> shared)
    : m_shared(std::move(shared))
    , m_faconCodec(std::make_unique<FaconCodec>())
    , m_binaryCodec(std::make_unique<BinaryCodec>())
    , m_faconDeframer(std::make_unique<FaconDeframer>())
    , m_binaryDeframer(std::make_unique<BinaryDeframer>(BinaryDeframer::Direction::Response))
{}

SessionProtocol::~SessionProtocol() = default;

bool SessionProtocol::set(Protocol protocol)
{
    const bool changed = !m_protocol || *m_protocol != protocol;
    m_protocol = protocol;
    m_shared->protocol.store(static_cast<int>(protocol));
    return changed;
}

const Codec *SessionProtocol::codec() const
{
    if (!m_protocol)
        return nullptr;
    return codecFor(*m_protocol);
}

const Codec *SessionProtocol::codecFor(Protocol protocol) const
{
    return protocol == Protocol::Facon ? m_faconCodec.get() : m_binaryCodec.get();
}

Deframer *SessionProtocol::deframerFor(Protocol protocol)
{
    return protocol == Protocol::Facon ? m_faconDeframer.get() : m_binaryDeframer.get();
}

std::size_t SessionProtocol::resetDeframers()
{
    const std::size_t partial
        = m_faconDeframer->bufferedBytes() + m_binaryDeframer->bufferedBytes();
    m_faconDeframer->reset();
    m_binaryDeframer->reset();
    return partial;
}

std::size_t SessionProtocol::takeNoise()
{
    const std::size_t total
        = m_faconDeframer->discardedBytes() + m_binaryDeframer->discardedBytes();
    const std::size_t added = total > m_noise ? total - m_noise : 0;
    m_noise = total;
    return added;
}

void SessionProtocol::skipNoise()
{
    m_noise = m_faconDeframer->discardedBytes() + m_binaryDeframer->discardedBytes();
}

Message SessionProtocol::summarize(const QByteArray &frame) const
{
    if (const Codec *c = codec())
        return c->summary(bytesOf(frame));
    // Protocol not known yet: the frame's first byte tells.
    return RawFrame::summary(bytesOf(frame));
}

void SessionProtocol::detect(SessionJob waiting, quint8 station, ProbeHooks hooks)
{
    auto held = std::make_shared<SessionJob>(std::move(waiting));
    auto shared = std::make_shared<ProbeHooks>(std::move(hooks));
    using ProbeFn = std::function<void(Protocol)>;
    auto probeIn = std::make_shared<ProbeFn>();
    // The probe callback holds the function strongly, the function itself weakly: no cycle.
    std::weak_ptr<ProbeFn> weakProbeIn = probeIn;
    *probeIn = [station, held, shared, weakProbeIn](Protocol protocol) {
        SessionJob probe;
        probe.request = Request::briefStatus(station);
        probe.probe = protocol;
        // As many attempts as the request waiting for it would get: a timeout says "attempt 3
        // of 3" under the retries in force, not "1 of 1".
        probe.options.retries = held->options.retries;
        probe.done = [station, held, shared, next = weakProbeIn.lock(),
                      protocol](const SessionResult &result) {
            // A PLC error is an answer too: the protocol is right.
            const bool answered = result.ok() || result.errorKind() == ErrorKind::PlcError;
            const bool linkDown = !result.ok()
                                  && (result.errorKind() == ErrorKind::LinkError
                                      || result.errorKind() == ErrorKind::Cancelled);
            if (answered) {
                shared->detected(protocol, *held);
            } else if (protocol == Protocol::Facon && !linkDown) {
                (*next)(Protocol::Binary);
            } else {
                const ErrorKind kind = linkDown ? result.errorKind() : ErrorKind::Timeout;
                shared->failed(*held, SessionResult::fromError(
                                          makeError(kind, msg<MsgId::LinkAutoDetectFailed>(
                                                              station, result.errorMessage())),
                                          {}, held->raw));
            }
        };
        shared->send(std::move(probe));
    };
    (*probeIn)(Protocol::Facon);
}

} // namespace Fatek
