#pragma once

// Building blocks of the FACON wire format shared by FaconCodec's master side (faconcodec.cpp) and
// slave side (faconslave.cpp): hex fields, values on the wire, framing.

#include "request.h"
#include "result.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace Fatek::FaconWire {

inline constexpr char kHexDigits[] = "0123456789ABCDEF";

std::optional<std::uint32_t> hexValue(char c);
// Fixed-width hex field (1..8 chars); nullopt on any non-hex character.
std::optional<std::uint32_t> parseHex(std::string_view text);
void appendHex(std::string &out, std::uint32_t value, int digits);
std::string hex2(std::uint32_t value);

// Characters of one value on the wire: discrete 1, 16-bit 4, 32-bit 8.
std::size_t valueChars(ElementType type);
void appendValue(std::string &out, ElementType type, std::uint32_t value);

// At most maxChars of `text` for a message, bytes outside printable ASCII as <hex>.
std::string printable(std::string_view text, std::size_t maxChars);

// STX, body, LRC, ETX.
Bytes frameOf(std::string_view body);
std::string headerText(std::uint8_t station, std::uint8_t command);

struct ParsedFrame
{
    std::uint8_t station = 0;
    std::uint8_t command = 0;
    std::string_view data; // between the command and the LRC
};

// Framing, hex header and LRC. The view points into `frame`.
Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame);

} // namespace Fatek::FaconWire
