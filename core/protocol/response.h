#pragma once

#include "request.h"

#include <cstdint>
#include <vector>

namespace Fatek {

// A typed answer. A decoder only returns a Response for errorCode 0 (a PLC error becomes a
// ProtocolError); the simulator fills errorCode to encode error answers.
struct Response
{
    std::uint8_t station = 1;
    Command command = Command::BriefStatus;
    std::uint8_t errorCode = 0;
    std::vector<std::uint32_t> values; // 43 44 (0/1), 46 48 (element values), 4F (64 words)
    Bytes data;                        // 40 and 53: the status bytes; 4E: the echoed data

    bool operator==(const Response &) const = default;
};

} // namespace Fatek
