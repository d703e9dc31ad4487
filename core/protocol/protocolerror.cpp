#include "protocolerror.h"

#include <string>

namespace Fatek {

std::string_view plcErrorText(int code)
{
    switch (code) {
    case 0x0: return "no error";
    case 0x2: return "illegal value";
    case 0x3: return "write prohibited (ROM pack)";
    case 0x4: return "illegal format, or command cannot execute";
    case 0x5: return "cannot RUN: ladder checksum error";
    case 0x6: return "cannot RUN: PLC ID differs from ladder ID";
    case 0x7: return "cannot RUN: syntax check error";
    case 0x9: return "cannot RUN: function not supported";
    case 0xA: return "illegal address";
    default: return "unknown error code";
    }
}

ProtocolError makePlcError(int code, std::string_view context)
{
    static const char digits[] = "0123456789ABCDEF";
    std::string codeText;
    if (code >= 0 && code < 16)
        codeText = digits[code];
    else
        codeText = std::to_string(code);
    std::string message = "PLC error " + codeText + ": " + std::string(plcErrorText(code));
    if (!context.empty()) {
        message += ' ';
        message += context;
    }
    return ProtocolError{ErrorKind::PlcError, std::move(message), code};
}

std::string_view errorKindName(ErrorKind kind)
{
    switch (kind) {
    case ErrorKind::InvalidAddress: return "invalid address";
    case ErrorKind::LimitExceeded: return "limit exceeded";
    case ErrorKind::InvalidRequest: return "invalid request";
    case ErrorKind::Unsupported: return "not supported";
    case ErrorKind::BadFrame: return "bad frame";
    case ErrorKind::BadChecksum: return "checksum error";
    case ErrorKind::FrameTooLong: return "frame too long";
    case ErrorKind::MalformedResponse: return "malformed response";
    case ErrorKind::StationMismatch: return "wrong station";
    case ErrorKind::CommandMismatch: return "wrong command";
    case ErrorKind::PlcError: return "PLC error";
    case ErrorKind::Timeout: return "timeout";
    case ErrorKind::LinkError: return "link error";
    case ErrorKind::ReadOnly: return "read-only mode";
    case ErrorKind::Cancelled: return "cancelled";
    }
    return "error";
}

} // namespace Fatek
