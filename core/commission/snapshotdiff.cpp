#include "snapshotdiff.h"

#include "commissionmessages.h"
#include "core/watch/valueformat.h"

namespace Fatek::SnapshotDiff {

std::vector<SnapshotDifference> compare(const MemorySnapshot &before, const MemorySnapshot &after,
                                        std::size_t *compared)
{
    std::vector<SnapshotDifference> out;
    std::size_t count = 0;
    auto a = before.values.begin();
    auto b = after.values.begin();
    while (a != before.values.end() || b != after.values.end()) {
        ++count;
        if (b == after.values.end() || (a != before.values.end() && a->address < b->address)) {
            out.push_back({a->address, a->value, std::nullopt});
            ++a;
        } else if (a == before.values.end() || b->address < a->address) {
            out.push_back({b->address, std::nullopt, b->value});
            ++b;
        } else {
            if (a->value != b->value)
                out.push_back({a->address, a->value, b->value});
            ++a;
            ++b;
        }
    }
    if (compared)
        *compared = count;
    return out;
}

QString valueText(const Address &address, const std::optional<std::uint32_t> &value)
{
    if (!value)
        return QString::fromStdString(english(msg<MsgId::DiffAbsent>()));
    return ValueFormat::format(*value, Snapshot::valueBits(address),
                               ValueFormat::defaultFormat(address));
}

QString hexText(const Address &address, const std::optional<std::uint32_t> &value)
{
    if (!value || isDiscrete(address.type))
        return {};
    return ValueFormat::format(*value, Snapshot::valueBits(address), DisplayFormat::Hex);
}

Message line(const SnapshotDifference &d)
{
    auto side = [&d](const std::optional<std::uint32_t> &v) -> MessageArg {
        if (!v)
            return msg<MsgId::DiffAbsent>();
        return valueText(d.address, v).toStdString();
    };
    return msg<MsgId::DiffLine>(d.address.toString(), side(d.before), side(d.after));
}

Message summary(std::size_t differences, std::size_t compared)
{
    if (differences == 0)
        return msg<MsgId::DiffNone>();
    return msg<MsgId::DiffCount>(differences, compared);
}

} // namespace Fatek::SnapshotDiff
