#pragma once

// The slave (simulator) side of FaconCodec: decodeRequest(), encodeResponse() and
// encodeErrorResponse() are defined in faconslave.cpp next to the query reader declared here.

#include "request.h"
#include "result.h"

#include <cstdint>
#include <string_view>

namespace Fatek::FaconSlave {

// The data of a query (between the command and the LRC) as a Request validated for FACON; on
// failure, error().plcCode is the code to answer with. FaconCodec::summarize() uses it too: a frame
// that parses as a query is shown as one.
Result<Request> parseQuery(std::uint8_t station, Command command, std::string_view data);

} // namespace Fatek::FaconSlave
