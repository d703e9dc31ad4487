#pragma once

#include "protocolerror.h"
#include "request.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace Fatek {

struct DeframedItem
{
    Bytes frame;                        // the complete frame, or the rejected bytes
    std::optional<ProtocolError> error; // set when the frame was rejected (bad LRC/CRC, ID, ...)
};

// Finds frames in a byte stream fed in arbitrary chunks. Skips garbage before a frame, rejects a
// broken frame with a typed reason and resynchronises on the next frame start. Its buffer never
// holds more than the largest legal frame.
class Deframer
{
public:
    virtual ~Deframer() = default;

    // Appends every frame (or rejection) completed by `bytes` to `out`, in stream order.
    virtual void feed(std::span<const std::uint8_t> bytes, std::vector<DeframedItem> &out) = 0;
    // Forget a partial frame (before a new query: stale bytes must not join the next answer).
    virtual void reset() = 0;
    // Bytes held for an incomplete frame.
    virtual std::size_t bufferedBytes() const = 0;
    // Garbage bytes skipped outside frames since construction (rejected frames not included).
    virtual std::size_t discardedBytes() const = 0;
    virtual std::size_t maxFrameSize() const = 0;
};

} // namespace Fatek
