#pragma once

// The slave (simulator) side of BinaryCodec: decodeRequest(), encodeResponse() and
// encodeErrorResponse() are defined in binaryslave.cpp next to the query reader declared here.

#include "request.h"
#include "result.h"

#include <cstdint>
#include <span>

namespace Fatek::BinarySlave {

// A query payload (station, command, data; at least two bytes) as a Request, not yet validated;
// on failure, error().plcCode is the code to answer with. BinaryCodec::summarize() uses it too, to
// describe a query frame.
Result<Request> parseQueryPayload(std::span<const std::uint8_t> p);

} // namespace Fatek::BinarySlave
