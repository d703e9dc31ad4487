#include "watchinput.h"

#include "ui/common/uitext.h"

#include <QRegularExpression>

namespace Fatek::WatchInput {

Result<QList<Address>> parseAddresses(const QString &text)
{
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    const QStringList tokens = text.split(separators, Qt::SkipEmptyParts);
    if (tokens.isEmpty())
        return makeError(
            ErrorKind::InvalidAddress,
            QCoreApplication::translate("Fatek::WatchInput",
                                        "Type an address such as R100, or a range such as "
                                        "R100..R163.")
                .toStdString());
    QList<Address> all;
    for (const QString &token : tokens) {
        const auto addresses = WatchList::expandRange(token);
        if (!addresses) {
            return makeError(ErrorKind::InvalidAddress,
                             QCoreApplication::translate("Fatek::WatchInput", "\"%1\": %2")
                                 .arg(token, translated(addresses.error().message))
                                 .toStdString());
        }
        all += *addresses;
        if (all.size() > WatchList::MaxRangeItems)
            return makeError(ErrorKind::LimitExceeded,
                             QCoreApplication::translate("Fatek::WatchInput",
                                                         "Too many items at once: at most %1.")
                                 .arg(WatchList::MaxRangeItems)
                                 .toStdString());
    }
    return all;
}

Result<QList<WatchItemSpec>> parsePasted(const QString &text, quint8 station)
{
    // "R100,Tank level" or "R100;1;float" is CSV; "R100, R101" is a list of addresses. A line
    // counts as CSV when its second field is not an address itself.
    static const QRegularExpression csvSeparator(QStringLiteral("[,;\\t]"));
    bool csv = false;
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString &line : lines) {
        const QStringList fields = line.split(csvSeparator);
        if (fields.size() >= 2 && !fields.at(1).trimmed().isEmpty()
            && !WatchList::expandRange(fields.at(1).trimmed()).ok()) {
            csv = true;
            break;
        }
    }
    QList<WatchItemSpec> items;
    if (csv) {
        QString normalised = text;
        normalised.replace(QLatin1Char('\t'), QLatin1Char(';'));
        const QString &firstLine = lines.constFirst();
        const bool hasHeader = firstLine.contains(QLatin1String("address"), Qt::CaseInsensitive);
        bool hasStation
            = hasHeader && firstLine.contains(QLatin1String("station"), Qt::CaseInsensitive);
        if (!hasHeader) {
            // Spreadsheet rows usually read "address, name[, comment]"; a number second is the
            // station (the file column order), a format name second is "address, format, name".
            const QString second = firstLine.split(csvSeparator).value(1).trimmed();
            bool isNumber = false;
            second.toInt(&isNumber);
            hasStation = isNumber;
            const char sep = normalised.contains(QLatin1Char(';')) ? ';' : ',';
            QString header;
            if (!isNumber) {
                header = ValueFormat::fromName(second)
                             ? QStringLiteral("address%1format%1name%1comment\n")
                             : QStringLiteral("address%1name%1comment\n");
                normalised.prepend(header.arg(QLatin1Char(sep)));
            }
        }
        auto rows = WatchList::importCsv(normalised.toUtf8());
        if (!rows)
            return rows.error();
        items = *rows;
        if (!hasStation) {
            // Without a station column the table's station is meant.
            for (WatchItemSpec &item : items)
                item.station = station;
        }
        return items;
    }
    const auto addresses = parseAddresses(text);
    if (!addresses)
        return addresses.error();
    for (const Address &address : *addresses) {
        WatchItemSpec item;
        item.address = address;
        item.station = station;
        item.format = ValueFormat::defaultFormat(address);
        items.append(item);
    }
    return items;
}

} // namespace Fatek::WatchInput
