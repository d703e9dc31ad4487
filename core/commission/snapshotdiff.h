#pragma once

#include "core/protocol/message.h"
#include "memorysnapshot.h"

#include <QString>

#include <optional>
#include <vector>

namespace Fatek {

// One element whose value differs: `before` (the snapshot, the first file) and `after` (the live
// PLC, the second file); an element only one side holds has the other side empty.
struct SnapshotDifference
{
    Address address;
    std::optional<std::uint32_t> before;
    std::optional<std::uint32_t> after;

    bool operator==(const SnapshotDifference &) const = default;
};

// The differences between two snapshots and how they read. Values are formatted by
// ValueFormat in the element's default format (ON/OFF for discretes, signed for registers).
namespace SnapshotDiff {

// Sorted by address. `compared` (if given) receives how many addresses were compared.
std::vector<SnapshotDifference> compare(const MemorySnapshot &before, const MemorySnapshot &after,
                                        std::size_t *compared = nullptr);

// "12", "ON", "-5"; the absent side as DiffAbsent's text.
QString valueText(const Address &address, const std::optional<std::uint32_t> &value);
// "0x000C" for registers, empty for discretes and the absent side.
QString hexText(const Address &address, const std::optional<std::uint32_t> &value);
// "R0: 12 -> 15" (DiffLine), in English through english(), translated in the UI.
Message line(const SnapshotDifference &difference);
// "No differences." or "3 of 7604 values differ."
Message summary(std::size_t differences, std::size_t compared);

} // namespace SnapshotDiff

} // namespace Fatek
