#pragma once

#include "core/protocol/codec.h"
#include "core/protocol/deframer.h"
#include "sessionjob.h"

#include <QByteArray>

#include <functional>
#include <memory>
#include <optional>

namespace Fatek {

struct SessionShared;

// The link's protocol (chosen, or found by auto-detect), the codecs and deframers of both
// protocols, and the auto-detect probes.
class SessionProtocol
{
public:
    explicit SessionProtocol(std::shared_ptr<SessionShared> shared);
    ~SessionProtocol();

    // Unset while auto-detect has not decided.
    const std::optional<Protocol> &protocol() const { return m_protocol; }
    // True when it differs from what was known.
    bool set(Protocol protocol);
    // The link protocol's codec; null while it is not known.
    const Codec *codec() const;
    const Codec *codecFor(Protocol protocol) const;
    Deframer *deframerFor(Protocol protocol);
    // Empties both deframers; returns the bytes of partial frames they held.
    std::size_t resetDeframers();
    // Noise the deframers skipped since the last call (they count since construction).
    std::size_t takeNoise();
    // Takes the noise as not noise (bytes around a console answer are the answer).
    void skipNoise();
    // A frame for the traffic log, in the link's protocol or, before it is known, as it looks.
    Message summarize(const QByteArray &frame) const;

    // What the auto-detect probes do around them: `send` queues a probe ahead of everything,
    // `detected` lets the waiting request go, `failed` answers it.
    struct ProbeHooks
    {
        std::function<void(SessionJob probe)> send;
        std::function<void(Protocol protocol, SessionJob &waiting)> detected;
        std::function<void(SessionJob &waiting, SessionResult result)> failed;
    };
    // Auto-detect for `waiting`: asks `station` for its status in FACON, then binary.
    static void detect(SessionJob waiting, quint8 station, ProbeHooks hooks);

private:
    std::shared_ptr<SessionShared> m_shared;
    std::unique_ptr<Codec> m_faconCodec;
    std::unique_ptr<Codec> m_binaryCodec;
    std::unique_ptr<Deframer> m_faconDeframer;
    std::unique_ptr<Deframer> m_binaryDeframer;
    std::optional<Protocol> m_protocol;
    std::size_t m_noise = 0; // deframers' discardedBytes() already taken
};

} // namespace Fatek
