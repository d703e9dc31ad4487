#include "discretescan.h"

#include <algorithm>

namespace Fatek {

Result<QList<AddressRange>> DiscreteScan::parse(const QString &text)
{
    const Result<std::vector<AddressRange>> ranges = AddressRange::parseList(text.toStdString());
    if (!ranges)
        return ranges.error();
    QList<AddressRange> out;
    for (const AddressRange &range : *ranges) {
        // Forcing acts on single points: registers have no enable flags to scan.
        if (!isDiscrete(range.start.type)) {
            const std::string_view symbol = range.start.info().symbol;
            return makeError(
                ErrorKind::InvalidAddress,
                tr("\u201c%1\u201d is not a discrete type; use X, Y, M, S, T or C.")
                    .arg(QString::fromLatin1(symbol.data(), static_cast<qsizetype>(symbol.size())))
                    .toStdString());
        }
        out << range;
    }
    return out;
}

QString DiscreteScan::listText(const QList<AddressRange> &ranges)
{
    QStringList parts;
    for (const AddressRange &r : ranges)
        parts << QString::fromStdString(r.toString());
    return parts.join(QStringLiteral(", "));
}

QList<AddressRange> DiscreteScan::defaults()
{
    return {{{ElementType::X, 0}, 256}, {{ElementType::Y, 0}, 256}, {{ElementType::M, 0}, 1024},
            {{ElementType::S, 0}, 256}, {{ElementType::T, 0}, 256}, {{ElementType::C, 0}, 256}};
}

QList<AddressRange> DiscreteScan::wholePlc(const DetailStatus &status,
                                           QList<ElementType> *unreported)
{
    QList<AddressRange> ranges;
    for (const AddressRange &fallback : defaults()) {
        const ElementType type = fallback.start.type;
        const std::optional<std::uint16_t> count = status.discreteCount(type);
        if (!count) {
            if (unreported)
                *unreported << type;
            ranges << fallback;
        } else if (*count > 0) {
            // Never beyond what the protocol can address, whatever a PLC reports.
            const quint32 max = elementInfo(type).maxNumber + 1;
            ranges << AddressRange{{type, 0}, std::min<quint32>(*count, max)};
        }
    }
    return ranges;
}

} // namespace Fatek
