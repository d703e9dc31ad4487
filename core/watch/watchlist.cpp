#include "watchlist.h"

#include "addressrange.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QSaveFile>
#include <QStringDecoder>

#include <cmath>

namespace Fatek::WatchList {

namespace {

ProtocolError fileError(const QString &message)
{
    return makeError(ErrorKind::InvalidRequest, message.toStdString());
}

// "Invalid address ..." becomes "invalid address ..." after "table 2, item 5: ". Acronyms ("BCD
// ...") keep their case.
QString lowerFirst(const QString &text)
{
    if (text.size() >= 2 && text[0].isUpper() && text[1].isLower())
        return text[0].toLower() + text.mid(1);
    return text;
}

ProtocolError atPlace(const QString &place, const ProtocolError &error)
{
    ProtocolError e = error;
    e.message = (place + QStringLiteral(": ") + lowerFirst(QString::fromStdString(error.message)))
                    .toStdString();
    return e;
}

QString knownFormats()
{
    QStringList names;
    for (DisplayFormat f : ValueFormat::allFormats())
        names.append(ValueFormat::name(f));
    return names.join(QStringLiteral(", "));
}

QString tablePlace(qsizetype table)
{
    return QStringLiteral("table %1").arg(table + 1);
}

ProtocolError tooManyItems(qsizetype count)
{
    return fileError(QStringLiteral("%1 items are more than one table holds (at most %2)")
                         .arg(count)
                         .arg(MaxTableItems));
}

QString itemPlace(qsizetype table, qsizetype item)
{
    return QStringLiteral("table %1, item %2").arg(table + 1).arg(item + 1);
}

QString linePlace(int line)
{
    return QStringLiteral("line %1").arg(line);
}

Status validateInterval(int intervalMs)
{
    if (intervalMs < MinIntervalMs || intervalMs > MaxIntervalMs) {
        return fileError(QStringLiteral("poll interval %1 ms is out of range (%2..%3 ms)")
                             .arg(intervalMs)
                             .arg(MinIntervalMs)
                             .arg(MaxIntervalMs));
    }
    return Ok{};
}

// ---- JSON members ----

Result<QString> textMember(const QJsonObject &object, const QString &key, const QString &fallback)
{
    const QJsonValue value = object.value(key);
    if (value.isUndefined())
        return fallback;
    if (!value.isString())
        return fileError(QStringLiteral("\"%1\" must be text").arg(key));
    return value.toString();
}

Result<bool> boolMember(const QJsonObject &object, const QString &key, bool fallback)
{
    const QJsonValue value = object.value(key);
    if (value.isUndefined())
        return fallback;
    if (!value.isBool())
        return fileError(QStringLiteral("\"%1\" must be true or false").arg(key));
    return value.toBool();
}

Result<int> intMember(const QJsonObject &object, const QString &key, int fallback, int min, int max)
{
    const QJsonValue value = object.value(key);
    if (value.isUndefined())
        return fallback;
    const double number = value.toDouble();
    if (!value.isDouble() || std::floor(number) != number || number < min || number > max) {
        return fileError(QStringLiteral("\"%1\" must be a whole number from %2 to %3")
                             .arg(key)
                             .arg(min)
                             .arg(max));
    }
    return static_cast<int>(number);
}

Result<WatchItemSpec> entryFromJson(const QJsonValue &value)
{
    if (!value.isObject())
        return fileError(QStringLiteral("an item must be a JSON object"));
    const QJsonObject object = value.toObject();

    WatchItemSpec entry;
    const QJsonValue address = object.value(QStringLiteral("address"));
    if (address.isUndefined())
        return fileError(QStringLiteral("the \"address\" is missing"));
    if (!address.isString())
        return fileError(QStringLiteral("\"address\" must be text such as \"R100\""));
    const auto parsed = Address::parse(address.toString().toStdString());
    if (!parsed)
        return parsed.error();
    entry.address = *parsed;

    const auto station = intMember(object, QStringLiteral("station"), 1, 1, 254);
    if (!station)
        return station.error();
    entry.station = static_cast<quint8>(*station);

    const auto formatName = textMember(object, QStringLiteral("format"), QString());
    if (!formatName)
        return formatName.error();
    if (formatName->isEmpty()) {
        entry.format = ValueFormat::defaultFormat(entry.address);
    } else if (const auto format = ValueFormat::fromName(*formatName)) {
        entry.format = *format;
    } else {
        return fileError(
            QStringLiteral("unknown format \"%1\" (known: %2)").arg(*formatName, knownFormats()));
    }

    const auto swap = boolMember(object, QStringLiteral("swapWords"), false);
    if (!swap)
        return swap.error();
    entry.swapWords = *swap;

    const auto name = textMember(object, QStringLiteral("name"), QString());
    if (!name)
        return name.error();
    entry.name = *name;
    const auto comment = textMember(object, QStringLiteral("comment"), QString());
    if (!comment)
        return comment.error();
    entry.comment = *comment;

    if (Status s = validateEntry(entry); !s)
        return s.error();
    return entry;
}

Result<WatchTableSpec> tableFromJson(const QJsonValue &value, qsizetype index)
{
    const QString place = tablePlace(index);
    if (!value.isObject())
        return atPlace(place, fileError(QStringLiteral("a table must be a JSON object")));
    const QJsonObject object = value.toObject();

    WatchTableSpec table;
    const auto name
        = textMember(object, QStringLiteral("name"), QStringLiteral("Table %1").arg(index + 1));
    if (!name)
        return atPlace(place, name.error());
    table.name = *name;
    const auto interval
        = intMember(object, QStringLiteral("intervalMs"), 500, MinIntervalMs, MaxIntervalMs);
    if (!interval)
        return atPlace(place, interval.error());
    table.intervalMs = *interval;
    const auto confirm = boolMember(object, QStringLiteral("confirmWrites"), true);
    if (!confirm)
        return atPlace(place, confirm.error());
    table.confirmWrites = *confirm;

    const QJsonValue items = object.value(QStringLiteral("items"));
    if (items.isUndefined())
        return table;
    if (!items.isArray())
        return atPlace(place, fileError(QStringLiteral("\"items\" must be a list")));
    const QJsonArray array = items.toArray();
    if (array.size() > MaxTableItems)
        return atPlace(place, tooManyItems(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        auto entry = entryFromJson(array.at(i));
        if (!entry)
            return atPlace(itemPlace(index, i), entry.error());
        table.items.append(std::move(entry).value());
    }
    return table;
}

// ---- CSV ----

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

bool isBlankOrComment(QStringView line)
{
    const QStringView trimmed = line.trimmed();
    return trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#'));
}

// Splits the text into records of fields. The first ',' or ';' outside quotes fixes the separator
// for the whole file; until then both count.
Result<QList<CsvRecord>> splitCsv(const QString &text)
{
    QList<CsvRecord> records;
    QChar separator;
    const auto isSeparator = [&](QChar c) {
        if (separator.isNull() && (c == QLatin1Char(',') || c == QLatin1Char(';'))) {
            separator = c;
            return true;
        }
        return !separator.isNull() && c == separator;
    };
    const auto isBlank = [](QChar c) {
        return c == QLatin1Char(' ') || c == QLatin1Char('\t') || c == QLatin1Char('\r');
    };

    const qsizetype n = text.size();
    qsizetype i = 0;
    int line = 1;
    while (i < n) {
        qsizetype lineEnd = text.indexOf(QLatin1Char('\n'), i);
        if (lineEnd < 0)
            lineEnd = n;
        if (isBlankOrComment(QStringView(text).mid(i, lineEnd - i))) {
            i = lineEnd + 1;
            ++line;
            continue;
        }

        CsvRecord record;
        record.line = line;
        bool endOfRecord = false;
        while (!endOfRecord) {
            while (i < n && isBlank(text[i]))
                ++i;
            QString field;
            if (i < n && text[i] == QLatin1Char('"')) {
                const int quoteLine = line;
                ++i;
                bool closed = false;
                while (i < n) {
                    const QChar c = text[i];
                    if (c == QLatin1Char('"')) {
                        if (i + 1 < n && text[i + 1] == QLatin1Char('"')) {
                            field += QLatin1Char('"');
                            i += 2;
                            continue;
                        }
                        ++i;
                        closed = true;
                        break;
                    }
                    if (c == QLatin1Char('\n'))
                        ++line;
                    field += c;
                    ++i;
                }
                if (!closed) {
                    return atPlace(
                        linePlace(quoteLine),
                        fileError(QStringLiteral("a quoted field is not closed (missing \")")));
                }
                while (i < n && isBlank(text[i]))
                    ++i;
                if (i < n && text[i] != QLatin1Char('\n') && !isSeparator(text[i])) {
                    return atPlace(
                        linePlace(line),
                        fileError(QStringLiteral("unexpected text after the quoted field \"%1\"")
                                      .arg(field)));
                }
            } else {
                const qsizetype start = i;
                while (i < n && text[i] != QLatin1Char('\n') && !isSeparator(text[i]))
                    ++i;
                field = text.mid(start, i - start).trimmed();
            }
            record.fields.append(field);
            // Here i is at a separator (already recognised), a newline or the end.
            if (i >= n) {
                endOfRecord = true;
            } else if (text[i] == QLatin1Char('\n')) {
                ++i;
                ++line;
                endOfRecord = true;
            } else {
                ++i;
            }
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

Status validateEntry(const WatchItemSpec &entry)
{
    if (entry.station == 0)
        return fileError(
            QStringLiteral("station 0 is broadcast (no PLC answers): use a station number 1..254"));
    if (entry.station > 254)
        return fileError(QStringLiteral("station %1 is not valid: use a station number 1..254")
                             .arg(entry.station));
    if (Status s = validateAddress(entry.address); !s)
        return s;
    const int count = ValueFormat::elementCount(entry.address, entry.format);
    const QString address = QString::fromStdString(entry.address.toString());
    if (count == 0) {
        return fileError(
            QStringLiteral("format \"%1\" does not apply to %2 (%3)")
                .arg(ValueFormat::name(entry.format), address,
                     QString::fromUtf8(entry.address.info().name.data(),
                                       static_cast<qsizetype>(entry.address.info().name.size()))));
    }
    if (count > 1) {
        if (Status s = validateSpan(entry.address, static_cast<std::uint32_t>(count)); !s) {
            return fileError(QStringLiteral("format \"%1\" on %2 needs %3 elements: %4")
                                 .arg(ValueFormat::name(entry.format), address)
                                 .arg(count)
                                 .arg(lowerFirst(QString::fromStdString(s.error().message))));
        }
    }
    return Ok{};
}

Status validate(const WatchListFile &file)
{
    for (qsizetype t = 0; t < file.tables.size(); ++t) {
        const WatchTableSpec &table = file.tables.at(t);
        if (Status s = validateInterval(table.intervalMs); !s)
            return atPlace(tablePlace(t), s.error());
        if (table.items.size() > MaxTableItems)
            return atPlace(tablePlace(t), tooManyItems(table.items.size()));
        for (qsizetype i = 0; i < table.items.size(); ++i) {
            if (Status s = validateEntry(table.items.at(i)); !s)
                return atPlace(itemPlace(t, i), s.error());
        }
    }
    return Ok{};
}

Result<WatchListFile> load(const QByteArray &json)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // Offsets are bytes; lines and columns are what an editor shows.
        const QByteArray before = json.left(parseError.offset);
        const qsizetype line = before.count('\n') + 1;
        const qsizetype column = parseError.offset - (before.lastIndexOf('\n') + 1) + 1;
        return fileError(QStringLiteral("The file is not valid JSON: %1 at line %2, column %3.")
                             .arg(parseError.errorString())
                             .arg(line)
                             .arg(column));
    }
    if (!document.isObject())
        return fileError(
            QStringLiteral("The file is not a FATEK Studio watch list: it holds no JSON object."));
    const QJsonObject root = document.object();

    if (root.value(QStringLiteral("format")).toString() != QLatin1String(FormatMarker)) {
        return fileError(
            QStringLiteral("The file is not a FATEK Studio watch list: \"format\" is not \"%1\".")
                .arg(QLatin1String(FormatMarker)));
    }
    const QJsonValue version = root.value(QStringLiteral("version"));
    const double versionNumber = version.toDouble();
    if (!version.isDouble() || std::floor(versionNumber) != versionNumber || versionNumber < 1) {
        return fileError(QStringLiteral("The watch list has no valid \"version\" (expected %1).")
                             .arg(CurrentVersion));
    }
    if (versionNumber > CurrentVersion) {
        return fileError(
            QStringLiteral(
                "The watch list is version %1, written by a newer FATEK Studio; this one "
                "reads version %2.")
                .arg(versionNumber)
                .arg(CurrentVersion));
    }

    const QJsonValue tables = root.value(QStringLiteral("tables"));
    if (!tables.isArray())
        return fileError(QStringLiteral("The watch list has no \"tables\" list."));
    WatchListFile file;
    const QJsonArray array = tables.toArray();
    for (qsizetype t = 0; t < array.size(); ++t) {
        auto table = tableFromJson(array.at(t), t);
        if (!table)
            return table.error();
        file.tables.append(std::move(table).value());
    }
    return file;
}

Result<WatchListFile> loadFromFile(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return fileError(QStringLiteral("Cannot open %1: %2").arg(path, f.errorString()));
    auto file = load(f.readAll());
    if (!file)
        return atPlace(QFileInfo(path).fileName(), file.error());
    return file;
}

QByteArray save(const WatchListFile &file)
{
    QJsonArray tables;
    for (const WatchTableSpec &table : file.tables) {
        QJsonArray items;
        for (const WatchItemSpec &entry : table.items) {
            items.append(QJsonObject{
                {QStringLiteral("address"), QString::fromStdString(entry.address.toString())},
                {QStringLiteral("station"), entry.station},
                {QStringLiteral("format"), ValueFormat::name(entry.format)},
                {QStringLiteral("swapWords"), entry.swapWords},
                {QStringLiteral("name"), entry.name},
                {QStringLiteral("comment"), entry.comment},
            });
        }
        tables.append(QJsonObject{
            {QStringLiteral("name"), table.name},
            {QStringLiteral("intervalMs"), table.intervalMs},
            {QStringLiteral("confirmWrites"), table.confirmWrites},
            {QStringLiteral("items"), items},
        });
    }
    const QJsonObject root{
        {QStringLiteral("format"), QLatin1String(FormatMarker)},
        {QStringLiteral("version"), CurrentVersion},
        {QStringLiteral("tables"), tables},
    };
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Status saveToFile(const WatchListFile &file, const QString &path)
{
    // A file that could not be loaded again is not written at all.
    if (Status s = validate(file); !s)
        return atPlace(QStringLiteral("Not saved"), s.error());
    const QByteArray data = save(file);
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly))
        return fileError(QStringLiteral("Cannot write %1: %2").arg(path, out.errorString()));
    if (out.write(data) != data.size()) {
        const QString reason = out.errorString();
        out.cancelWriting();
        return fileError(QStringLiteral("Cannot write %1: %2").arg(path, reason));
    }
    if (!out.commit())
        return fileError(QStringLiteral("Cannot write %1: %2").arg(path, out.errorString()));
    return Ok{};
}

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
        const QString place = linePlace(record.line);
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
            bool allEmpty = true;
            for (const QString &field : record.fields)
                allEmpty = allEmpty && field.trimmed().isEmpty();
            if (allEmpty)
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

Result<QList<Address>> expandRange(const QString &text)
{
    const auto range = AddressRange::parse(text.toStdString());
    if (!range)
        return range.error();
    // One range becomes that many watch rows: the grammar is AddressRange's, the limit ours.
    if (range->count > static_cast<std::uint32_t>(MaxRangeItems)) {
        return makeError(
            ErrorKind::InvalidAddress,
            QStringLiteral("Range \"%1\" has %2 elements; at most %3 fit in one range.")
                .arg(text.trimmed())
                .arg(range->count)
                .arg(MaxRangeItems)
                .toStdString());
    }
    QList<Address> addresses;
    addresses.reserve(range->count);
    for (std::uint32_t i = 0; i < range->count; ++i)
        addresses.append(range->start.advanced(i));
    return addresses;
}

} // namespace Fatek::WatchList
