#include "discreterange.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>

namespace Fatek {

QString DiscreteRange::toString() const
{
    const QString first = QString::fromStdString(start.toString());
    if (count <= 1)
        return first;
    return QStringLiteral("%1-%2").arg(first).arg(last().number);
}

Result<DiscreteRange> DiscreteRange::parse(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral(
        R"(^\s*([A-Za-z]+)\s*(\d+)\s*(?:(?:-|\.\.)\s*(?:([A-Za-z]+)\s*)?(\d+))?\s*$)"));
    const QRegularExpressionMatch m = pattern.match(text);
    if (!m.hasMatch()) {
        return makeError(ErrorKind::InvalidAddress,
                         QCoreApplication::translate("Fatek::DiscreteRange",
                                                     "\u201c%1\u201d is not a range of discretes; "
                                                     "write it like Y0-255 or M100.")
                             .arg(text.trimmed())
                             .toStdString());
    }
    const auto type = elementTypeFromSymbol(m.captured(1).toStdString());
    if (!type || !isDiscrete(*type)) {
        return makeError(
            ErrorKind::InvalidAddress,
            QCoreApplication::translate("Fatek::DiscreteRange",
                                        "\u201c%1\u201d is not a discrete type; use X, Y, M, "
                                        "S, T or C.")
                .arg(m.captured(1))
                .toStdString());
    }
    if (m.hasCaptured(3) && !m.captured(3).isEmpty()
        && elementTypeFromSymbol(m.captured(3).toStdString()) != type) {
        return makeError(ErrorKind::InvalidAddress,
                         QCoreApplication::translate("Fatek::DiscreteRange",
                                                     "A range must stay within one type: %1")
                             .arg(text.trimmed())
                             .toStdString());
    }
    bool ok = false;
    const quint32 first = m.captured(2).toUInt(&ok);
    if (!ok)
        return makeError(
            ErrorKind::InvalidAddress,
            QCoreApplication::translate("Fatek::DiscreteRange", "Point number too large in %1")
                .arg(text.trimmed())
                .toStdString());
    quint32 lastNumber = first;
    if (m.hasCaptured(4) && !m.captured(4).isEmpty()) {
        lastNumber = m.captured(4).toUInt(&ok);
        if (!ok)
            return makeError(
                ErrorKind::InvalidAddress,
                QCoreApplication::translate("Fatek::DiscreteRange", "Point number too large in %1")
                    .arg(text.trimmed())
                    .toStdString());
    }
    if (lastNumber < first) {
        return makeError(ErrorKind::InvalidAddress,
                         QCoreApplication::translate("Fatek::DiscreteRange",
                                                     "The range %1 ends before it starts.")
                             .arg(text.trimmed())
                             .toStdString());
    }
    DiscreteRange range;
    range.start = Address{*type, first};
    range.count = lastNumber - first + 1;
    if (const Status s = validateSpan(range.start, range.count); !s)
        return s.error();
    return range;
}

Result<QList<DiscreteRange>> DiscreteRange::parseList(const QString &text)
{
    // Split on separators, but keep "Y0 - 255" together by normalizing spaces around dashes first.
    QString normalized = text;
    normalized.replace(QRegularExpression(QStringLiteral(R"(\s*(-|\.\.)\s*)")),
                       QStringLiteral("\\1"));
    normalized.replace(QRegularExpression(QStringLiteral(R"(([A-Za-z])\s+(\d))")),
                       QStringLiteral("\\1\\2"));
    const QStringList parts
        = normalized.split(QRegularExpression(QStringLiteral(R"([\s,;]+)")), Qt::SkipEmptyParts);
    if (parts.isEmpty())
        return makeError(
            ErrorKind::InvalidAddress,
            QCoreApplication::translate("Fatek::DiscreteRange",
                                        "No range given; write for example X0-255, Y0-255.")
                .toStdString());
    QList<DiscreteRange> ranges;
    for (const QString &part : parts) {
        const Result<DiscreteRange> r = parse(part);
        if (!r)
            return r.error();
        ranges << *r;
    }
    return ranges;
}

QString DiscreteRange::listText(const QList<DiscreteRange> &ranges)
{
    QStringList parts;
    for (const DiscreteRange &r : ranges)
        parts << r.toString();
    return parts.join(QStringLiteral(", "));
}

QList<DiscreteRange> DiscreteRange::defaults()
{
    return {{{ElementType::X, 0}, 256}, {{ElementType::Y, 0}, 256}, {{ElementType::M, 0}, 1024},
            {{ElementType::S, 0}, 256}, {{ElementType::T, 0}, 256}, {{ElementType::C, 0}, 256}};
}

QList<DiscreteRange> DiscreteRange::wholePlc(const DetailStatus &status,
                                             QList<ElementType> *unreported)
{
    QList<DiscreteRange> ranges;
    for (const DiscreteRange &fallback : defaults()) {
        const ElementType type = fallback.start.type;
        const std::optional<std::uint16_t> count = status.discreteCount(type);
        if (!count) {
            if (unreported)
                *unreported << type;
            ranges << fallback;
        } else if (*count > 0) {
            // Never beyond what the protocol can address, whatever a PLC reports.
            const quint32 max = elementInfo(type).maxNumber + 1;
            ranges << DiscreteRange{{type, 0}, std::min<quint32>(*count, max)};
        }
    }
    return ranges;
}

} // namespace Fatek
