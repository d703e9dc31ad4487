#include "protocolerror.h"

#include <string>

namespace Fatek {

Message plcCodeMessage(int code)
{
    switch (code) {
    case 0x0: return msg<MsgId::PlcCodeNoError>();
    case 0x2: return msg<MsgId::PlcCodeIllegalValue>();
    case 0x3: return msg<MsgId::PlcCodeWriteProhibited>();
    case 0x4: return msg<MsgId::PlcCodeIllegalFormat>();
    case 0x5: return msg<MsgId::PlcCodeLadderChecksum>();
    case 0x6: return msg<MsgId::PlcCodeIdMismatch>();
    case 0x7: return msg<MsgId::PlcCodeSyntaxError>();
    case 0x9: return msg<MsgId::PlcCodeNotSupported>();
    case 0xA: return msg<MsgId::PlcCodeIllegalAddress>();
    default: return msg<MsgId::PlcCodeUnknown>();
    }
}

std::string_view plcErrorText(int code)
{
    // The code texts take no arguments: their template is the English text.
    return messageTemplate(plcCodeMessage(code).id);
}

std::string plcCodeDigits(int code)
{
    static const char digits[] = "0123456789ABCDEF";
    if (code >= 0 && code < 16)
        return std::string(1, digits[code]);
    return std::to_string(code);
}

ProtocolError makePlcError(int code, std::string_view context)
{
    Message message
        = context.empty()
              ? msg<MsgId::PlcError>(plcCodeDigits(code), plcCodeMessage(code))
              : msg<MsgId::PlcErrorAbout>(plcCodeDigits(code), plcCodeMessage(code), context);
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
    case ErrorKind::Expired: return "expired";
    }
    return "error";
}

} // namespace Fatek
