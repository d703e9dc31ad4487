#pragma once

// Building blocks of the FATEK binary wire format shared by BinaryCodec's master side
// (binarycodec.cpp) and slave side (binaryslave.cpp): values, numbers, framing, message text.

#include "request.h"
#include "result.h"

#include <cstdint>
#include <span>
#include <string>

namespace Fatek::BinaryWire {

std::string hex2(std::uint32_t value);
// "01 46 03 ..." cut after maxBytes.
std::string hexBytes(std::span<const std::uint8_t> bytes, std::size_t maxBytes);
// "46 read consecutive registers", or "A0 unknown command".
std::string commandText(std::uint8_t code);

// Bytes one value takes on the wire.
std::size_t valueSize(ElementType type);
void appendValue(Bytes &out, ElementType type, std::uint32_t value);
// Big-endian number of `size` bytes at `pos`; the caller checks the bounds.
std::uint32_t readNumber(std::span<const std::uint8_t> bytes, std::size_t pos, std::size_t size);

struct ParsedFrame
{
    std::uint8_t header = 0;
    std::span<const std::uint8_t> payload;
};

// Header, ID, length, terminator and CRC. The payload view points into `frame`.
Result<ParsedFrame> parseFrame(std::span<const std::uint8_t> frame);
Bytes frameOf(std::uint8_t header, std::span<const std::uint8_t> payload);

} // namespace Fatek::BinaryWire
