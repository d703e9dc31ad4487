#include "historytypes.h"

// The words of a sample's quality, as the CLI, the CSV and the JSON write them.

#include <array>
#include <utility>

namespace Fatek::History {

namespace {

constexpr std::array<std::pair<HistoryQuality, const char *>, 5> qualityNames{{
    {HistoryQuality::Good, "good"},
    {HistoryQuality::Late, "late"},
    {HistoryQuality::Stale, "stale"},
    {HistoryQuality::Error, "error"},
    {HistoryQuality::Off, "off"},
}};

} // namespace

QString qualityName(HistoryQuality quality)
{
    for (const auto &[q, name] : qualityNames) {
        if (q == quality)
            return QLatin1String(name);
    }
    return {};
}

std::optional<HistoryQuality> qualityFromName(const QString &name)
{
    for (const auto &[q, text] : qualityNames) {
        if (name == QLatin1String(text))
            return q;
    }
    return std::nullopt;
}

} // namespace Fatek::History
