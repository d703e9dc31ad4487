#pragma once

#include "request.h"
#include "response.h"
#include "result.h"

#include <optional>
#include <span>

namespace Fatek {

struct FrameHeader
{
    std::uint8_t station = 0;
    std::uint8_t command = 0;
};

// Turns typed requests into frames and frames into typed answers, for one protocol. Pure: no I/O,
// no clock. A frame is one complete frame as a Deframer delivers it (checksum already verified by
// the deframer, but decoders verify it again so they can be used alone).
class Codec
{
public:
    virtual ~Codec() = default;

    virtual Protocol protocol() const = 0;

    // Master side.
    virtual Result<Bytes> encodeRequest(const Request &request) const = 0;
    // Checks station and command against `request`, decodes the values it asked for; a non-zero
    // PLC error code becomes ProtocolError{PlcError} naming what was asked ("... R70000").
    virtual Result<Response> decodeResponse(std::span<const std::uint8_t> frame,
                                            const Request &request) const = 0;

    // Slave side (the simulator). On failure, error().plcCode is the code to answer with
    // (4 malformed, A illegal address, 2 illegal value); 0 means "do not answer" (bad checksum).
    virtual Result<Request> decodeRequest(std::span<const std::uint8_t> frame) const = 0;
    virtual Bytes encodeResponse(const Request &request, const Response &response) const = 0;
    // Error answer when the query could not even be decoded into a Request.
    virtual Bytes encodeErrorResponse(FrameHeader header, std::uint8_t errorCode) const = 0;

    // Station and command of a checksum-valid frame, if it has them.
    virtual std::optional<FrameHeader> frameHeader(std::span<const std::uint8_t> frame) const = 0;
    // Station and command where this protocol's frames carry them, checksum and length not
    // checked (the raw console names broken frames too); empty unless the frame starts like one.
    virtual std::optional<FrameHeader> peekHeader(std::span<const std::uint8_t> frame) const = 0;

    // Raw console: wraps a body in framing and checksum. FACON body: the ASCII between STX and
    // the LRC ("014603R00012"); binary body: the payload bytes (01 46 03 52 00 0C).
    virtual Bytes wrap(std::span<const std::uint8_t> body, bool response = false) const = 0;

    // One-line summary of any frame for the traffic log ("station 1, 46 read consecutive
    // registers: 3 x R00012").
    virtual Message summary(std::span<const std::uint8_t> frame) const = 0;
    // The same in English.
    std::string summarize(std::span<const std::uint8_t> frame) const
    {
        return english(summary(frame));
    }
};

} // namespace Fatek
