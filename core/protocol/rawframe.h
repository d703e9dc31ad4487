#pragma once

#include "request.h"

#include <optional>
#include <span>
#include <string>

namespace Fatek {

class Codec;

// A frame as the raw console types or receives it: of either protocol, not necessarily valid.
// The one place such frames are framed and looked into; the session sends exactly frame().
class RawFrame
{
public:
    struct Peek
    {
        Protocol protocol = Protocol::Facon;
        std::uint8_t station = 0;
        std::uint8_t command = 0;
    };

    // What goes on the wire: `typed` as is, or wrapped in `framing`'s framing and checksum
    // (FACON: typed is the ASCII between STX and the LRC; binary: the payload bytes).
    static Bytes frame(std::span<const std::uint8_t> typed, std::optional<Protocol> framing);

    // The protocol a frame's first byte announces (STX: FACON, 51/52: binary).
    static std::optional<Protocol> protocolOf(std::span<const std::uint8_t> frame);
    // Protocol, station and command where the frame's layout has them; checksum and length are
    // not checked, so broken frames show what they were meant for. Empty for garbage.
    static std::optional<Peek> peek(std::span<const std::uint8_t> frame);
    // One-line meaning of a frame (the codec's summary); not FACON is read as binary.
    static Message summary(std::span<const std::uint8_t> frame);
    static std::string summarize(std::span<const std::uint8_t> frame);

    static const Codec &codec(Protocol protocol);
};

} // namespace Fatek
