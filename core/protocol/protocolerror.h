#pragma once

#include "message.h"

#include <string>
#include <string_view>

namespace Fatek {

// What went wrong, in categories a caller can act on (retry, mark stale, report).
enum class ErrorKind {
    InvalidAddress,    // user text or element number not acceptable
    LimitExceeded,     // request larger than the protocol allows
    InvalidRequest,    // request inconsistent (wrong element kind for the command, bad value)
    Unsupported,       // command or element not available in this protocol
    BadFrame,          // framing broken: bad header, ID, terminator, length, characters
    BadChecksum,       // LRC / CRC mismatch
    FrameTooLong,      // no end of frame within the largest legal frame
    MalformedResponse, // frame is fine but its content does not fit the query
    StationMismatch,   // answer from another station than asked
    CommandMismatch,   // answer to another command than asked
    PlcError,          // the PLC answered with a non-zero error code
    Timeout,           // no (complete) answer in time
    LinkError,         // transport failed: port gone, connection refused or lost
    ReadOnly,          // refused by operator (read-only) mode before reaching the wire
    Cancelled,         // request dropped because the session stopped
    Expired,           // not sent: it waited past its deadline (RequestOptions::deadline)
};

struct ProtocolError
{
    ErrorKind kind = ErrorKind::BadFrame;
    // Complete sentence for technicians, e.g. "PLC error A: illegal address R70000".
    Message message;
    // PLC error code for PlcError; for a slave decoding a query: the code to answer.
    int plcCode = 0;

    // The sentence in English (logs, the CLI).
    std::string text() const { return english(message); }

    bool operator==(const ProtocolError &) const = default;
};

// What a PLC error code of either protocol means ("illegal address" for 0xA).
Message plcCodeMessage(int code);
// The same in English.
std::string_view plcErrorText(int code);
// The code as the PLC writes it: one hex digit ("A"), larger codes in decimal.
std::string plcCodeDigits(int code);

// "PLC error A: illegal address" followed by " context" when context is given.
ProtocolError makePlcError(int code, std::string_view context = {});

std::string_view errorKindName(ErrorKind kind);

} // namespace Fatek
