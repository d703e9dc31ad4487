#include "modelprofile.h"

#include <algorithm>
#include <cctype>

namespace Fatek {

namespace {

void putWord(Bytes &b, std::size_t statusNumber, std::uint32_t value)
{
    // STATUSn is b[n - 1]; counts are high byte first and saturate (R 0..65535 does not fit).
    const auto v = static_cast<std::uint16_t>(std::min<std::uint32_t>(value, 0xFFFF));
    b[statusNumber - 1] = static_cast<std::uint8_t>(v >> 8);
    b[statusNumber] = static_cast<std::uint8_t>(v & 0xFF);
}

} // namespace

std::uint16_t ModelProfile::programPages() const
{
    return static_cast<std::uint16_t>(
        1 + (programWords + Limits::programPageWords - 1) / Limits::programPageWords);
}

ProgramHeader ModelProfile::programHeader() const
{
    ProgramHeader h;
    h.family = programFamily;
    const unsigned kilo = ((programWords + 512u) / 1024u) % 100u; // 13184 -> "13"
    h.digits[0] = static_cast<char>('0' + kilo / 10);
    h.digits[1] = static_cast<char>('0' + kilo % 10);
    h.ladderSize = programWords;
    return h;
}

std::vector<std::uint16_t> ModelProfile::powerOnProgram() const
{
    std::vector<std::uint16_t> words(std::size_t{programPages()} * Limits::programPageWords, 0);
    const std::vector<std::uint16_t> header = programHeader().encode();
    std::copy(header.begin(), header.end(), words.begin());
    // Page 1: a title in ASCII (two characters a word), then 40 instruction-like words.
    const std::string title = "FATEK-SIM DEMO LADDER " + name;
    std::size_t at = Limits::programPageWords;
    for (std::size_t i = 0; i < title.size(); i += 2) {
        const auto hi = static_cast<std::uint8_t>(title[i]);
        const auto lo = i + 1 < title.size() ? static_cast<std::uint8_t>(title[i + 1]) : 0;
        words[at++] = static_cast<std::uint16_t>((hi << 8) | lo);
    }
    for (std::uint16_t i = 0; i < 40 && at < words.size(); ++i)
        words[at++] = static_cast<std::uint16_t>(0x1000u + i * 0x0101u);
    return words;
}

Bytes ModelProfile::detailStatus(std::uint8_t status1) const
{
    Bytes b(64, 0);
    b[0] = status1;
    b[1] = mainUnitType;
    b[2] = ioPointsCode;
    b[3] = osVersion;
    putWord(b, 5, programWords);
    putWord(b, 7, discretes[0]);
    putWord(b, 9, discretes[1]);
    putWord(b, 11, analogInputs);
    putWord(b, 13, analogOutputs);
    putWord(b, 15, discretes[2]);
    putWord(b, 17, discretes[3]);
    putWord(b, 19, 0); // L relays: not simulated
    putWord(b, 21, registers[2]);
    putWord(b, 23, registers[3]);
    putWord(b, 25, discretes[4]);
    putWord(b, 27, discretes[5]);
    return b;
}

ModelProfile ModelProfile::fbs()
{
    ModelProfile p;
    static_cast<PlcModel &>(p) = PlcModel::fbs();
    p.name = "fbs";
    p.description = "FBs-28MC, OS V3.1, 13K program";
    p.status2 = 0x54; // 13K step program (FACON 40 table)
    p.status3 = 0x00;
    p.mainUnitType = 0x01;
    p.ioPointsCode = 0x02;
    p.osVersion = 0x31;
    p.programWords = 13184;
    p.analogInputs = 100;
    p.analogOutputs = 100;
    return p;
}

ModelProfile ModelProfile::mSeries()
{
    ModelProfile p;
    static_cast<PlcModel &>(p) = PlcModel::mSeries();
    p.name = "m";
    p.description = "M-series, largest ranges of the reference";
    p.status2 = 0x00;
    p.status3 = 0x00;
    // 53's main unit type and I/O points are documented for the FB series only (00 MA/MU,
    // 01 MC; other values reserved) and the binary (M series) document lists no 53 answer: an M
    // PLC must not read as an FBs model, so both bytes hold a reserved value and the M series
    // shows through the program header's family instead.
    p.mainUnitType = 0xFF;
    p.ioPointsCode = 0xFF;
    p.osVersion = 0x31;
    p.programWords = 16384;
    p.programFamily = 'M';
    p.analogInputs = 100;
    p.analogOutputs = 100;
    return p;
}

std::optional<ModelProfile> ModelProfile::byName(const std::string &name)
{
    std::string lower;
    for (char c : name)
        lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "fbs")
        return fbs();
    if (lower == "m")
        return mSeries();
    return std::nullopt;
}

std::vector<std::string> ModelProfile::names()
{
    return {"fbs", "m"};
}

} // namespace Fatek
