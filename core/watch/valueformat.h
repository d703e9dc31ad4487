#pragma once

#include "core/protocol/address.h"
#include "core/protocol/result.h"

#include <QList>
#include <QString>
#include <QStringView>

#include <cstdint>
#include <optional>

namespace Fatek {

// How a watch value is shown and typed.
enum class DisplayFormat {
    Bit,      // ON / OFF (1-bit values only)
    Unsigned, // 0..65535
    Signed,   // -32768..32767 (two's complement)
    Hex,      // 0x001A, fixed number of digits
    Binary,   // 0000 0000 0001 1010, grouped in nibbles
    Bcd,      // 0x1234 shown as 1234
    Float32,  // IEEE-754 single over 32 bits, 7 significant digits
    Ascii,    // two characters per 16-bit word, high byte first
    Double64, // IEEE-754 double over 64 bits (four registers), shortest exact text
};

// A raw watch value is a std::uint64_t plus its width in bits: 1 (discrete), 16 (register),
// 32 (register pair: high word = R(n+1), low word = R(n)) or 64 (four registers, word 0 = R(n)
// lowest). swapWords reverses the order of the 16-bit words before interpreting (PLCs or HMIs that
// store the low word of a float high); it has no effect on 1- and 16-bit values. Bits above `width`
// are ignored.
namespace ValueFormat {

// Names used in watch list files and on the command line: "bit", "unsigned", "signed", "hex",
// "binary", "bcd", "float", "ascii", "double".
QString name(DisplayFormat format);
// Case-insensitive; also accepts "float32" and "double64".
std::optional<DisplayFormat> fromName(QStringView name);
QList<DisplayFormat> allFormats();

// Whether `format` means something for a value of `width` bits: Bit needs 1 bit, Signed/Bcd/Ascii
// 16 bits or more, Float32 exactly 32, Double64 exactly 64; Unsigned/Hex/Binary fit every width.
bool isAvailable(DisplayFormat format, int width);

// Bits a watch item of `address` shown as `format` covers, or 0 if the format does not apply:
// a discrete is 1 bit; a 16-bit register shown as float covers R(n), R(n+1) (32 bits) and as double
// R(n)..R(n+3) (64 bits); a 32-bit register shown as double covers DR(n), DR(n+2).
int valueWidth(const Address &address, DisplayFormat format);
// Consecutive elements (address.advanced(0..count-1)) that valueWidth covers; 0 if the format does
// not apply.
int elementCount(const Address &address, DisplayFormat format);
// Format given to new items: Bit for discretes, Signed for registers.
DisplayFormat defaultFormat(const Address &address);

// Text for a raw value. A width/format pair that isAvailable() rejects gives a bracketed note, e.g.
// "(float needs 32 bits)", never a made-up number.
QString format(std::uint64_t raw, int width, DisplayFormat format, bool swapWords = false);

// The number a value stands for, for trends and sorting: signed, unsigned, BCD, float and double
// as their value; hex and binary (ways of writing the bits) as signed; bits as 0/1. Nothing for
// ASCII (text has no height), a format that does not fit `width`, BCD with a digit above 9, or a
// float that is not finite.
std::optional<double> number(std::uint64_t raw, int width, DisplayFormat format,
                             bool swapWords = false);

// Parses what a technician typed into the raw value to write (swapWords applied, so that
// format(parse(text)) shows text again). Integer formats accept decimal, 0x1A, 1Ah and 0b1010, each
// only in the range the format shows again: Signed -2^(w-1)..2^(w-1)-1 (negative values as two's
// complement, "-0x10" too), Unsigned/Hex/Binary 0..2^w-1, and digits with a prefix or suffix
// without a sign (the bits themselves) 0..2^w-1 in every format; in Hex format bare digits are hex,
// in Binary format bare digits are binary (spaces allowed), in Bcd format bare digits are the BCD
// digits. Float32/Double64 take decimal or exponent text, NaN, Inf, -Inf, or raw bits as 0x.., ..h
// or 0b... Ascii takes the literal characters (shorter text is padded with NUL). 1-bit values take
// ON/OFF, TRUE/FALSE, 1/0 in any format. Errors are sentences for technicians.
Result<std::uint64_t> parse(const QString &text, int width, DisplayFormat format,
                            bool swapWords = false);

// False only for a Float32/Double64 value that is NaN or an infinity (what a PLC program's
// arithmetic rarely expects: writes refuse it unless the item allows it, ItemValues).
bool isFinite(std::uint64_t raw, int width, DisplayFormat format, bool swapWords = false);

// Reverses the 16-bit words of a 32- or 64-bit value; identity for other widths. Its own inverse.
std::uint64_t swapWords(std::uint64_t raw, int width);

} // namespace ValueFormat

} // namespace Fatek
