#include "watchlist.h"
#include "watchmessages.h"

// The watch list file: versioned JSON, read and written.

#include "jsonkeys.h"
#include "safefile.h"
#include "watchlisterrors.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <functional>

#include <cmath>

namespace Fatek::WatchList {

using namespace Errors;

namespace {

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

// The line of a key of an item's alarm N, for the alarms' errors.
using AlarmKeyLine = std::function<int(qsizetype, const QString &)>;
// The line of a key of the item's history setting.
using HistoryKeyLine = std::function<int(const QString &)>;

Result<WatchItemSpec> entryFromJson(const QJsonValue &value, const AlarmKeyLine &alarmKeyLine,
                                    const HistoryKeyLine &historyKeyLine)
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
    const auto nonFinite = boolMember(object, QStringLiteral("allowNonFinite"), false);
    if (!nonFinite)
        return nonFinite.error();
    entry.allowNonFinite = *nonFinite;

    const auto name = textMember(object, QStringLiteral("name"), QString());
    if (!name)
        return name.error();
    entry.name = *name;
    const auto comment = textMember(object, QStringLiteral("comment"), QString());
    if (!comment)
        return comment.error();
    entry.comment = *comment;

    auto alarms = Alarms::fromJson(object.value(QStringLiteral("alarms")), alarmKeyLine);
    if (!alarms)
        return alarms.error();
    entry.alarms = std::move(alarms).value();
    auto history
        = HistorySettings::fromJson(object.value(QStringLiteral("history")), historyKeyLine);
    if (!history)
        return history.error();
    entry.history = *history;

    if (Status s = validateEntry(entry); !s)
        return s.error();
    return entry;
}

Result<WatchTableSpec> tableFromJson(const QJsonValue &value, qsizetype index,
                                     const QByteArray &json)
{
    const Message place = tablePlace(index);
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
        const auto alarmKeyLine = [&](qsizetype alarm, const QString &key) {
            return JsonKeys::keyLine(json,
                                     {QStringLiteral("tables"), index, QStringLiteral("items"), i,
                                      QStringLiteral("alarms"), alarm},
                                     key);
        };
        const auto historyKeyLine = [&](const QString &key) {
            return JsonKeys::keyLine(json,
                                     {QStringLiteral("tables"), index, QStringLiteral("items"), i,
                                      QStringLiteral("history")},
                                     key);
        };
        auto entry = entryFromJson(array.at(i), alarmKeyLine, historyKeyLine);
        if (!entry)
            return atPlace(itemPlace(index, i), entry.error());
        table.items.append(std::move(entry).value());
    }
    return table;
}

Result<std::pair<Address, Symbol>> symbolFromJson(const QJsonValue &value)
{
    if (!value.isObject())
        return fileError(QStringLiteral("a symbol must be a JSON object"));
    const QJsonObject object = value.toObject();
    const QJsonValue address = object.value(QStringLiteral("address"));
    if (!address.isString())
        return fileError(QStringLiteral("\"address\" must be text such as \"R100\""));
    const auto parsed = Address::parse(address.toString().toStdString());
    if (!parsed)
        return parsed.error();
    const auto name = textMember(object, QStringLiteral("name"), QString());
    if (!name)
        return name.error();
    const auto comment = textMember(object, QStringLiteral("comment"), QString());
    if (!comment)
        return comment.error();
    return std::pair{*parsed, Symbol{*name, *comment}};
}

Result<SymbolTable> symbolsFromJson(const QJsonValue &value)
{
    SymbolTable symbols;
    if (value.isUndefined())
        return symbols;
    if (!value.isArray())
        return fileError(QStringLiteral("\"symbols\" must be a list"));
    const QJsonArray array = value.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const auto symbol = symbolFromJson(array.at(i));
        if (!symbol)
            return atPlace(msg<MsgId::PlaceSymbol>(i + 1), symbol.error());
        symbols.insert(symbol->first, symbol->second);
    }
    return symbols;
}

} // namespace

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
    if (const std::optional<Message> twice = JsonKeys::firstDuplicate(json))
        return makeError(ErrorKind::InvalidRequest, *twice);
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
    if (versionNumber > ItemSettingsVersion) {
        return fileError(
            QStringLiteral(
                "The watch list is version %1, written by a newer FATEK Studio; this one "
                "reads version %2.")
                .arg(versionNumber)
                .arg(ItemSettingsVersion));
    }

    const QJsonValue tables = root.value(QStringLiteral("tables"));
    if (!tables.isArray())
        return fileError(QStringLiteral("The watch list has no \"tables\" list."));
    WatchListFile file;
    const QJsonArray array = tables.toArray();
    for (qsizetype t = 0; t < array.size(); ++t) {
        auto table = tableFromJson(array.at(t), t, json);
        if (!table)
            return table.error();
        file.tables.append(std::move(table).value());
    }
    auto symbols = symbolsFromJson(root.value(QStringLiteral("symbols")));
    if (!symbols)
        return symbols.error();
    file.symbols = std::move(symbols).value();
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
    bool hasItemSettings = false; // alarms or history: version 2
    for (const WatchTableSpec &table : file.tables) {
        QJsonArray items;
        for (const WatchItemSpec &entry : table.items) {
            QJsonObject item{
                {QStringLiteral("address"), QString::fromStdString(entry.address.toString())},
                {QStringLiteral("station"), entry.station},
                {QStringLiteral("format"), ValueFormat::name(entry.format)},
                {QStringLiteral("swapWords"), entry.swapWords},
                {QStringLiteral("name"), entry.name},
                {QStringLiteral("comment"), entry.comment},
            };
            // Only when on: the files of every other item stay as they were.
            if (entry.allowNonFinite)
                item.insert(QStringLiteral("allowNonFinite"), true);
            if (!entry.alarms.isEmpty()) {
                item.insert(QStringLiteral("alarms"), Alarms::toJson(entry.alarms));
                hasItemSettings = true;
            }
            if (entry.history) {
                item.insert(QStringLiteral("history"), HistorySettings::toJson(*entry.history));
                hasItemSettings = true;
            }
            items.append(item);
        }
        tables.append(QJsonObject{
            {QStringLiteral("name"), table.name},
            {QStringLiteral("intervalMs"), table.intervalMs},
            {QStringLiteral("confirmWrites"), table.confirmWrites},
            {QStringLiteral("items"), items},
        });
    }
    QJsonObject root{
        {QStringLiteral("format"), QLatin1String(FormatMarker)},
        // Version 2 only with alarms or history settings: a version 1 reader would drop them
        // unseen on its next save, so it is told the file is newer instead; every other file
        // stays version 1.
        {QStringLiteral("version"), hasItemSettings ? ItemSettingsVersion : CurrentVersion},
        {QStringLiteral("tables"), tables},
    };
    if (!file.symbols.isEmpty()) {
        QJsonArray symbols;
        for (const auto &[address, symbol] : file.symbols.entries()) {
            symbols.append(QJsonObject{
                {QStringLiteral("address"), QString::fromStdString(address.toString())},
                {QStringLiteral("name"), symbol.name},
                {QStringLiteral("comment"), symbol.comment},
            });
        }
        root.insert(QStringLiteral("symbols"), symbols);
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

Status saveToFile(const WatchListFile &file, const QString &path)
{
    // A file that could not be loaded again is not written at all.
    if (Status s = validate(file); !s)
        return atPlace(msg<MsgId::PlaceNotSaved>(), s.error());
    const QByteArray data = save(file);
    if (const QString reason = SafeFile::write(path, data); !reason.isEmpty())
        return fileError(QStringLiteral("Cannot write %1: %2").arg(path, reason));
    return Ok{};
}

} // namespace Fatek::WatchList
