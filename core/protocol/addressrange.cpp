#include "addressrange.h"

#include "textscan.h"

#include <cctype>

namespace Fatek {

namespace {

using TextScan::isBlank;
using TextScan::trimmed;

bool isLetter(char c)
{
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}

bool isDigit(char c)
{
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

bool isSeparatorChar(char c)
{
    return c == '-' || c == '.';
}

// Drops blanks between an element type and its number ("Y 0" is Y0); other blanks stay, so
// Address::parse still reports "R1 2" as it was typed.
std::string joinTypeAndNumber(std::string_view text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (isBlank(text[i]) && !out.empty() && isLetter(out.back())) {
            std::size_t next = i;
            while (next < text.size() && isBlank(text[next]))
                ++next;
            if (next < text.size() && isDigit(text[next])) {
                i = next - 1;
                continue;
            }
        }
        out += text[i];
    }
    return out;
}

std::size_t dashAfterNumber(std::string_view text)
{
    for (std::size_t dash = text.find('-'); dash != std::string_view::npos;
         dash = text.find('-', dash + 1)) {
        std::size_t before = dash;
        while (before > 0 && isBlank(text[before - 1]))
            --before;
        if (before > 0 && isDigit(text[before - 1]))
            return dash;
    }
    return std::string_view::npos;
}

ProtocolError rangeError(Message message)
{
    return makeError(ErrorKind::InvalidAddress, std::move(message));
}

} // namespace

std::vector<Address> AddressRange::addresses() const
{
    std::vector<Address> out;
    out.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i)
        out.push_back(start.advanced(i));
    return out;
}

std::string AddressRange::toString() const
{
    if (count <= 1)
        return start.toString();
    return start.toString() + "-" + std::to_string(last().number);
}

Result<AddressRange> AddressRange::parse(std::string_view text)
{
    const std::string shown(trimmed(text));
    // Addresses hold neither '.' nor '-', so the first ".." splits the two ends; else a '-' after
    // a number does ("R-1" stays one address, reported as a bad number).
    std::size_t split = shown.find("..");
    std::string separator = "..";
    if (split == std::string::npos) {
        split = dashAfterNumber(shown);
        separator = "-";
    }
    if (split == std::string::npos) {
        const auto single = Address::parse(joinTypeAndNumber(shown));
        if (!single)
            return single.error();
        return AddressRange{*single, 1};
    }

    const std::string left = joinTypeAndNumber(trimmed(std::string_view(shown).substr(0, split)));
    std::string right
        = joinTypeAndNumber(trimmed(std::string_view(shown).substr(split + separator.size())));
    if (left.empty() || right.empty()) {
        return rangeError(msg<MsgId::RangeIncomplete>(shown));
    }
    const auto start = Address::parse(left);
    if (!start)
        return start.error();
    bool numberOnly = true;
    for (const char c : right)
        numberOnly = numberOnly && isDigit(c);
    const std::string symbol(start->info().symbol);
    if (numberOnly)
        right.insert(0, symbol);
    const auto end = Address::parse(right);
    if (!end)
        return end.error();

    const std::string first = start->toString();
    const std::string last = end->toString();
    if (start->type != end->type) {
        return rangeError(msg<MsgId::RangeMixedTypes>(shown, first, last));
    }
    if (end->number < start->number) {
        return rangeError(msg<MsgId::RangeBackwards>(shown, last + separator + first));
    }
    const std::uint32_t step = start->info().step;
    const std::uint32_t distance = end->number - start->number;
    if (distance % step != 0) {
        return rangeError(
            msg<MsgId::RangeNotWhole>(shown, symbol, step, first, start->advanced(1).toString()));
    }
    return AddressRange{*start, distance / step + 1};
}

Result<std::vector<AddressRange>> AddressRange::parseList(std::string_view text)
{
    // Blanks next to a separator or between type and number belong to one range ("Y 0 - 15");
    // the others, commas and semicolons separate ranges.
    std::vector<std::string> parts(1);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ',' || c == ';') {
            parts.emplace_back();
            continue;
        }
        if (isBlank(c)) {
            std::size_t next = i;
            while (next < text.size() && isBlank(text[next]))
                ++next;
            const std::string &current = parts.back();
            const bool joins = !current.empty() && next < text.size()
                               && (isSeparatorChar(current.back()) || isSeparatorChar(text[next])
                                   || (isLetter(current.back()) && isDigit(text[next])));
            if (!joins)
                parts.emplace_back();
            i = next - 1;
            continue;
        }
        parts.back() += c;
    }
    std::vector<AddressRange> ranges;
    for (const std::string &part : parts) {
        if (part.empty())
            continue;
        const auto range = parse(part);
        if (!range)
            return range.error();
        ranges.push_back(*range);
    }
    if (ranges.empty())
        return rangeError(msg<MsgId::RangeNoneGiven>());
    return ranges;
}

} // namespace Fatek
