#include "historycsv.h"

#include "core/watch/csvfield.h"

#include <QDateTime>

#include <array>
#include <charconv>
#include <cmath>

namespace Fatek::HistoryCsv {

QByteArray header()
{
    return QByteArrayLiteral("time,series,value,raw,quality\n");
}

QByteArray rows(const HistorySeries &series, const std::vector<HistorySample> &samples)
{
    const QString key = CsvField::quoted(series.key());
    QByteArray out;
    out.reserve(static_cast<qsizetype>(samples.size()) * 80);
    for (const HistorySample &s : samples) {
        const QString line
            = localTime(s.timeMs) + QLatin1Char(',') + key + QLatin1Char(',')
              + (History::hasValue(s.quality) ? valueText(s.value, series.format) : QString())
              + QLatin1Char(',') + rawText(s.raw) + QLatin1Char(',')
              + History::qualityName(s.quality) + QLatin1Char('\n');
        out += line.toUtf8();
    }
    return out;
}

QString localTime(qint64 ms)
{
    const QDateTime local = QDateTime::fromMSecsSinceEpoch(ms);
    return local.toOffsetFromUtc(local.offsetFromUtc()).toString(Qt::ISODateWithMs);
}

QString valueText(double value, const QString &format)
{
    if (std::isnan(value))
        return {};
    std::array<char, 64> buffer{};
    const auto result = format == QLatin1String("float")
                            ? std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                                            static_cast<float>(value))
                            : std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return QString::fromLatin1(buffer.data(), result.ptr - buffer.data());
}

QString rawText(std::uint64_t raw)
{
    return QStringLiteral("0x%1").arg(raw, 16, 16, QLatin1Char('0'));
}

} // namespace Fatek::HistoryCsv
