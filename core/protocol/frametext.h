#pragma once

#include "request.h"
#include "result.h"

#include <span>
#include <string>
#include <string_view>

namespace Fatek {

// Text forms of raw frames for the console and fatek-cli: hex and ASCII views, and parsing what a
// user types. Errors are core messages (Message: english() for the CLI, translated() in the GUI).
class FrameText
{
public:
    // How toAscii() writes control characters: by name (<STX>) or as hex (<02>).
    enum class Controls { Names, Hex };
    // What parse() reads the text as; Guess: hex when it is blank-separated pairs of hex digits
    // ("01 40") or starts with 0x or hex:, otherwise ASCII ("0140" is four characters).
    enum class Typed { Hex, Ascii, Guess };

    // "02 30 31 34 30 43 37 03"
    static std::string toHex(std::span<const std::uint8_t> bytes);
    // "<STX>0140C7<ETX>" (or "<02>0140C7<03>"): printable ASCII as is, others in brackets; bytes
    // above 7E always as hex (<FF>), and form feed too (<0C>: its name FF would read as hex).
    static std::string toAscii(std::span<const std::uint8_t> bytes,
                               Controls controls = Controls::Names);

    // "01 46 03 52 00 0C", "0146035200 0C", "0x01,0x46": pairs of hex digits, separators ignored.
    static Result<Bytes> parseHex(std::string_view text);
    // UTF-8 text of printable ASCII plus <STX>/<ETX>/<CR>... and <1F>-style escapes (two hex
    // digits win over a name: <FF> is FF), as toAscii() writes them in either style.
    static Result<Bytes> parseAscii(std::string_view text);
    // One of the two, as `typed` says; `wasHex` tells which one a guess took.
    static Result<Bytes> parse(std::string_view text, Typed typed, bool *wasHex = nullptr);
};

} // namespace Fatek
