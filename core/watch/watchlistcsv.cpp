#include "watchlist.h"

// Watch rows imported from CSV (spreadsheet exports).

#include "csvreader.h"
#include "watchlisterrors.h"

#include <QStringDecoder>
#include <QStringList>

namespace Fatek::WatchList {

using namespace Errors;

namespace {

struct CsvRecord
{
    int line = 0;
    QStringList fields;
};

QString decodeText(const QByteArray &bytes)
{
    QByteArray data = bytes;
    if (data.startsWith("\xEF\xBB\xBF"))
        data.remove(0, 3);
    QStringDecoder decoder(QStringDecoder::Utf8);
    QString text = decoder.decode(data);
    if (decoder.hasError())
        return QString::fromLatin1(data);
    return text;
}

// Splits the text into records of fields. The first ',' or ';' outside quotes fixes the separator
// for the whole file; a quoted field may hold line ends.
Result<QList<CsvRecord>> splitCsv(const QString &text)
{
    QList<CsvRecord> records;
    CsvReader reader(text, u",;", CsvReader::LineEnds::MayBeQuoted);
    while (reader.nextRecord()) {
        CsvReader::Problem problem;
        CsvRecord record{reader.line(), reader.fields(&problem)};
        if (record.fields.isEmpty()) {
            const QString why
                = problem.kind == CsvReader::Problem::Kind::QuoteNotClosed
                      ? QStringLiteral("a quoted field is not closed (missing \")")
                      : QStringLiteral("unexpected text after the quoted field \"%1\"")
                            .arg(problem.field);
            return atPlace(linePlace(problem.line), fileError(why));
        }
        records.append(record);
    }
    return records;
}

enum class Column { Address, Station, Format, Name, Comment, Ignored };

Result<QList<Column>> headerColumns(const CsvRecord &record)
{
    QList<Column> columns;
    QList<Column> seen;
    for (const QString &cell : record.fields) {
        const QString key = cell.trimmed().toLower();
        Column column = Column::Ignored;
        if (key == QLatin1String("address"))
            column = Column::Address;
        else if (key == QLatin1String("station"))
            column = Column::Station;
        else if (key == QLatin1String("format"))
            column = Column::Format;
        else if (key == QLatin1String("name"))
            column = Column::Name;
        else if (key == QLatin1String("comment"))
            column = Column::Comment;
        // Columns of rows copied from a watch table: what was read, not what to watch.
        else if (key == QLatin1String("value") || key == QLatin1String("quality"))
            column = Column::Ignored;
        else if (!key.isEmpty()) {
            return atPlace(
                linePlace(record.line),
                fileError(
                    QStringLiteral("unknown column \"%1\" (known: address, station, format, name, "
                                   "comment)")
                        .arg(cell)));
        }
        if (column != Column::Ignored) {
            if (seen.contains(column)) {
                return atPlace(linePlace(record.line),
                               fileError(QStringLiteral("column \"%1\" appears twice").arg(cell)));
            }
            seen.append(column);
        }
        columns.append(column);
    }
    return columns;
}

} // namespace

Result<QList<WatchItemSpec>> importCsv(const QByteArray &csv)
{
    const auto records = splitCsv(decodeText(csv));
    if (!records)
        return records.error();

    QList<Column> columns{Column::Address, Column::Station, Column::Format, Column::Name,
                          Column::Comment};
    bool header = false;
    // A data row always holds an address, and "address" is not one; so a first row with an
    // "address" cell and no address in its first cell names the columns.
    const auto looksLikeHeader = [](const CsvRecord &record) {
        if (expandRange(record.fields.first()).ok())
            return false;
        for (const QString &cell : record.fields) {
            if (cell.trimmed().compare(QLatin1String("address"), Qt::CaseInsensitive) == 0)
                return true;
        }
        return false;
    };
    if (!records->isEmpty() && looksLikeHeader(records->first())) {
        const auto headerResult = headerColumns(records->first());
        if (!headerResult)
            return headerResult.error();
        columns = *headerResult;
        header = true;
    }

    QList<WatchItemSpec> entries;
    for (qsizetype r = header ? 1 : 0; r < records->size(); ++r) {
        const CsvRecord &record = records->at(r);
        const Message place = linePlace(record.line);
        QString cells[5];
        for (qsizetype c = 0; c < record.fields.size(); ++c) {
            const QString &field = record.fields.at(c);
            if (c >= columns.size()) {
                // Spreadsheets pad rows with empty cells; only real extra data is an error.
                if (field.isEmpty())
                    continue;
                return atPlace(
                    place,
                    fileError(header
                                  ? QStringLiteral("more fields than the header has columns")
                                  : QStringLiteral("too many fields: at most 5 (address, station, "
                                                   "format, name, comment)")));
            }
            if (columns.at(c) != Column::Ignored)
                cells[static_cast<int>(columns.at(c))] = field;
        }
        const QString &addressText = cells[static_cast<int>(Column::Address)];
        const QString &stationText = cells[static_cast<int>(Column::Station)];
        const QString &formatText = cells[static_cast<int>(Column::Format)];
        const QString &name = cells[static_cast<int>(Column::Name)];
        const QString &comment = cells[static_cast<int>(Column::Comment)];

        if (addressText.trimmed().isEmpty()) {
            if (CsvReader::allEmpty(record.fields))
                continue; // a row of empty cells (";;;;") is a blank line too
            return atPlace(place, fileError(QStringLiteral("the address is missing")));
        }
        const auto addresses = expandRange(addressText);
        if (!addresses)
            return atPlace(place, addresses.error());
        if (entries.size() + addresses->size() > MaxTableItems)
            return atPlace(place, tooManyItems(entries.size() + addresses->size()));

        quint8 station = 1;
        if (!stationText.trimmed().isEmpty()) {
            bool ok = false;
            const int value = stationText.trimmed().toInt(&ok);
            if (!ok || value < 1 || value > 254) {
                return atPlace(
                    place, fileError(QStringLiteral(
                                         "station \"%1\" is not valid: use a number from 1 to 254")
                                         .arg(stationText)));
            }
            station = static_cast<quint8>(value);
        }

        std::optional<DisplayFormat> format;
        if (!formatText.trimmed().isEmpty()) {
            format = ValueFormat::fromName(formatText);
            if (!format) {
                return atPlace(place, fileError(QStringLiteral("unknown format \"%1\" (known: %2)")
                                                    .arg(formatText, knownFormats())));
            }
        }

        for (qsizetype i = 0; i < addresses->size(); ++i) {
            WatchItemSpec entry;
            entry.address = addresses->at(i);
            entry.station = station;
            entry.format = format ? *format : ValueFormat::defaultFormat(entry.address);
            entry.name = addresses->size() > 1 && !name.isEmpty()
                             ? QStringLiteral("%1[%2]").arg(name).arg(i)
                             : name;
            entry.comment = comment;
            if (Status s = validateEntry(entry); !s)
                return atPlace(place, s.error());
            entries.append(entry);
        }
    }
    if (entries.isEmpty())
        return fileError(QStringLiteral("The CSV text holds no addresses to watch."));
    return entries;
}

} // namespace Fatek::WatchList
