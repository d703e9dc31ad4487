#include "programheader.h"

#include "request.h"

namespace Fatek {

namespace {

template<typename Word>
std::optional<ProgramHeader> decodeWords(std::span<const Word> page)
{
    if (page.size() != Limits::programPageWords)
        return std::nullopt;
    auto byteAt = [&page](std::size_t i) {
        const auto word = static_cast<std::uint32_t>(page[i / 2]);
        return static_cast<std::uint8_t>(i % 2 == 0 ? (word >> 8) & 0xFFu : word & 0xFFu);
    };
    auto isDigit = [](std::uint8_t b) {
        return b >= '0' && b <= '9';
    };
    for (const Word w : page) {
        if (static_cast<std::uint32_t>(w) > 0xFFFFu)
            return std::nullopt;
    }
    if (byteAt(0) != 'F' || (byteAt(1) != 'B' && byteAt(1) != 'M') || !isDigit(byteAt(2))
        || !isDigit(byteAt(3)))
        return std::nullopt;
    ProgramHeader h;
    h.family = static_cast<char>(byteAt(1));
    h.digits[0] = static_cast<char>(byteAt(2));
    h.digits[1] = static_cast<char>(byteAt(3));
    h.ladderSize = static_cast<std::uint16_t>((byteAt(4) << 8) | byteAt(5));
    if (h.ladderSize == 0)
        return std::nullopt;
    return h;
}

} // namespace

std::optional<ProgramHeader> ProgramHeader::decode(std::span<const std::uint32_t> page)
{
    return decodeWords(page);
}

std::optional<ProgramHeader> ProgramHeader::decode(std::span<const std::uint16_t> page)
{
    return decodeWords(page);
}

std::vector<std::uint16_t> ProgramHeader::encode() const
{
    std::vector<std::uint16_t> page(Limits::programPageWords, 0xFFFF);
    page[0] = static_cast<std::uint16_t>(('F' << 8) | static_cast<std::uint8_t>(family));
    page[1] = static_cast<std::uint16_t>((static_cast<std::uint8_t>(digits[0]) << 8)
                                         | static_cast<std::uint8_t>(digits[1]));
    page[2] = ladderSize;
    return page;
}

std::uint16_t ProgramHeader::pageCount() const
{
    return static_cast<std::uint16_t>(
        1 + (ladderSize + Limits::programPageWords - 1) / Limits::programPageWords);
}

std::string ProgramHeader::familyName() const
{
    return family == 'B' ? "FBs" : std::string(1, family);
}

Message ProgramHeader::model() const
{
    return msg<MsgId::ProgramModel>(familyName(), ladderSize);
}

std::string pageListText(const std::vector<std::uint16_t> &pages, std::size_t limit)
{
    std::string out;
    std::size_t items = 0;
    for (std::size_t i = 0; i < pages.size();) {
        std::size_t j = i;
        while (j + 1 < pages.size() && pages[j + 1] == pages[j] + 1)
            ++j;
        if (items == limit) {
            out += ", ...";
            break;
        }
        if (!out.empty())
            out += ", ";
        out += std::to_string(pages[i]);
        if (j > i)
            out += "-" + std::to_string(pages[j]);
        ++items;
        i = j + 1;
    }
    return out;
}

} // namespace Fatek
