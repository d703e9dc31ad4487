#pragma once

#include "core/protocol/addressrange.h"
#include "core/protocol/plcstatus.h"
#include "core/protocol/result.h"

#include <QDateTime>
#include <QString>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace Fatek {

// One element's raw value: 0/1 for a discrete, the register's 16 or 32 bits.
struct SnapshotValue
{
    Address address;
    std::uint32_t value = 0;

    bool operator==(const SnapshotValue &) const = default;
};

// Where and when a snapshot was read.
struct SnapshotInfo
{
    QDateTime taken; // UTC
    QString link;    // "tcp 192.0.2.10:500" (LinkSettings::toString)
    int station = 1;
    QString protocol; // "FACON", "binary"
    QString model;    // PlcModel::modelText(), empty when the PLC did not say

    bool operator==(const SnapshotInfo &) const = default;
};

// A memory snapshot: metadata and the values of chosen element ranges, sorted by address, each
// address once.
struct MemorySnapshot
{
    SnapshotInfo info;
    std::vector<SnapshotValue> values;

    bool operator==(const MemorySnapshot &) const = default;

    std::optional<std::uint32_t> value(const Address &address) const;
    // Sorts by address; the later of two values of one address wins.
    void normalize();
    // The values whose address lies in one of `ranges` (all of them when `ranges` is empty).
    std::vector<SnapshotValue> select(std::span<const AddressRange> ranges) const;
    // What a restore of values writes: the values in `ranges`, or with no ranges every value but
    // the inputs X (the PLC overwrites them from its terminals every scan).
    std::vector<SnapshotValue> toRestore(std::span<const AddressRange> ranges) const;
};

namespace Snapshot {

// At most this many values in one snapshot (more than every element of the largest model a
// default snapshot reads): a bound on what a damaged file or a typing slip makes us hold.
inline constexpr std::size_t MaxValues = 400000;

// Every element the PLC reports in its 53 detail status: X Y M S T C (discreteCount), RT and RC
// (timers, counters), R and D. Nothing when the answer does not give the sizes.
std::vector<AddressRange> defaultRanges(const DetailStatus &status);
// "R0..R99, X0..X255 D0-9": AddressRange::parseList (commas, semicolons or blanks). Blank text
// gives no ranges: the default set (a snapshot reads every element the PLC reports, a restore
// writes every value but the inputs X).
Result<std::vector<AddressRange>> parseRanges(const QString &text);
// Consecutive addresses as ranges (sorted input): R0 R1 R2 R7 -> R0..R2, R7.
std::vector<AddressRange> rangesOf(std::span<const Address> sortedAddresses);
// The same as text, "R0-2, R7, Y0-15"; at most `limit` ranges (0: all), then ", ...".
std::string rangesText(std::span<const Address> sortedAddresses, std::size_t limit = 0);
// Bits of the raw value of an element: 1, 16 or 32.
int valueBits(const Address &address);

} // namespace Snapshot

} // namespace Fatek
