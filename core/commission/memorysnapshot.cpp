#include "memorysnapshot.h"

#include <algorithm>

namespace Fatek {

std::optional<std::uint32_t> MemorySnapshot::value(const Address &address) const
{
    const auto it
        = std::lower_bound(values.begin(), values.end(), address,
                           [](const SnapshotValue &v, const Address &a) { return v.address < a; });
    if (it == values.end() || it->address != address)
        return std::nullopt;
    return it->value;
}

void MemorySnapshot::normalize()
{
    std::stable_sort(
        values.begin(), values.end(),
        [](const SnapshotValue &a, const SnapshotValue &b) { return a.address < b.address; });
    // Keep the last of equal addresses.
    std::vector<SnapshotValue> out;
    out.reserve(values.size());
    for (const SnapshotValue &v : values) {
        if (!out.empty() && out.back().address == v.address)
            out.back() = v;
        else
            out.push_back(v);
    }
    values = std::move(out);
}

std::vector<SnapshotValue> MemorySnapshot::toRestore(std::span<const AddressRange> ranges) const
{
    std::vector<SnapshotValue> out = select(ranges);
    if (ranges.empty())
        std::erase_if(out, [](const SnapshotValue &v) { return v.address.type == ElementType::X; });
    return out;
}

std::vector<SnapshotValue> MemorySnapshot::select(std::span<const AddressRange> ranges) const
{
    if (ranges.empty())
        return values;
    std::vector<SnapshotValue> out;
    for (const SnapshotValue &v : values) {
        for (const AddressRange &r : ranges) {
            const Address last = r.last();
            if (v.address.type == r.start.type && v.address.number >= r.start.number
                && v.address.number <= last.number
                && (v.address.number - r.start.number) % v.address.info().step == 0) {
                out.push_back(v);
                break;
            }
        }
    }
    return out;
}

namespace Snapshot {

std::vector<AddressRange> defaultRanges(const DetailStatus &status)
{
    std::vector<AddressRange> out;
    auto add = [&out](ElementType type, const std::optional<std::uint16_t> &count) {
        if (count && *count > 0)
            out.push_back(AddressRange{Address{type, 0}, *count});
    };
    for (ElementType t : {ElementType::X, ElementType::Y, ElementType::M, ElementType::S,
                          ElementType::T, ElementType::C})
        add(t, status.discreteCount(t));
    add(ElementType::RT, status.timers);
    add(ElementType::RC, status.counters);
    add(ElementType::R, status.rRegisters);
    add(ElementType::D, status.dRegisters);
    return out;
}

Result<std::vector<AddressRange>> parseRanges(const QString &text)
{
    // Nothing typed is no mistake: it asks for the default set (the one rule for the CLI's
    // missing RANGES and the dialogs' empty fields).
    if (text.trimmed().isEmpty())
        return std::vector<AddressRange>{};
    return AddressRange::parseList(text.toStdString());
}

std::vector<AddressRange> rangesOf(std::span<const Address> sortedAddresses)
{
    std::vector<AddressRange> out;
    for (const Address &a : sortedAddresses) {
        if (!out.empty()) {
            AddressRange &r = out.back();
            if (r.start.type == a.type && r.last().advanced(1) == a) {
                ++r.count;
                continue;
            }
        }
        out.push_back(AddressRange{a, 1});
    }
    return out;
}

std::string rangesText(std::span<const Address> sortedAddresses, std::size_t limit)
{
    std::string text;
    std::size_t n = 0;
    for (const AddressRange &r : rangesOf(sortedAddresses)) {
        if (!text.empty())
            text += ", ";
        if (limit != 0 && n++ == limit)
            return text + "...";
        text += r.toString();
    }
    return text;
}

int valueBits(const Address &address)
{
    switch (address.width()) {
    case ElementWidth::Bit: return 1;
    case ElementWidth::Word: return 16;
    case ElementWidth::DoubleWord: return 32;
    }
    return 16;
}

} // namespace Snapshot

} // namespace Fatek
