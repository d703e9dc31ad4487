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

#include <cmath>
#include <utility>

namespace Fatek::WatchList {

using namespace Errors;

namespace {

// One object of the file. Every key it does not know is refused (a misspelt "staton" would
// otherwise poll station 1 on a multi-drop line), and an error about a key names its line.
class Members
{
public:
    Members(const QJsonObject &object, const QByteArray &json, JsonKeys::Path path)
        : m_object(object)
        , m_json(json)
        , m_path(std::move(path))
    {}

    const QJsonObject &object() const { return m_object; }
    const JsonKeys::Path &path() const { return m_path; }

    ProtocolError error(const QString &key, const QString &text) const
    {
        const int line = JsonKeys::keyLine(m_json, m_path, key);
        return fileError(line > 0 ? QStringLiteral("line %1: %2").arg(line).arg(text) : text);
    }

    // The first unknown key in the file's order (QJsonObject sorts its keys).
    Status rejectUnknown(const QStringList &known) const
    {
        QString first;
        int firstLine = 0;
        for (auto it = m_object.begin(); it != m_object.end(); ++it) {
            if (known.contains(it.key()))
                continue;
            const int line = JsonKeys::keyLine(m_json, m_path, it.key());
            if (first.isNull() || (line > 0 && (firstLine == 0 || line < firstLine))) {
                first = it.key();
                firstLine = line;
            }
        }
        if (first.isNull())
            return Ok{};
        return error(first, unknownKey(first, known));
    }

    Result<QString> text(const QString &key, const QString &fallback) const
    {
        const QJsonValue value = m_object.value(key);
        if (value.isUndefined())
            return fallback;
        if (!value.isString())
            return error(key, QStringLiteral("\"%1\" must be text").arg(key));
        return value.toString();
    }

    Result<bool> boolean(const QString &key, bool fallback) const
    {
        const QJsonValue value = m_object.value(key);
        if (value.isUndefined())
            return fallback;
        if (!value.isBool())
            return error(key, QStringLiteral("\"%1\" must be true or false").arg(key));
        return value.toBool();
    }

    Result<int> integer(const QString &key, int fallback, int min, int max) const
    {
        const QJsonValue value = m_object.value(key);
        if (value.isUndefined())
            return fallback;
        const double number = value.toDouble();
        if (!value.isDouble() || std::floor(number) != number || number < min || number > max) {
            return error(key, QStringLiteral("\"%1\" must be a whole number from %2 to %3")
                                  .arg(key)
                                  .arg(min)
                                  .arg(max));
        }
        return static_cast<int>(number);
    }

    // A required address ("R100").
    Result<Address> address() const
    {
        const QString key = QStringLiteral("address");
        const QJsonValue value = m_object.value(key);
        if (value.isUndefined())
            return fileError(QStringLiteral("the \"address\" is missing"));
        if (!value.isString())
            return error(key, QStringLiteral("\"address\" must be text such as \"R100\""));
        auto parsed = Address::parse(value.toString().toStdString());
        if (!parsed) {
            const int line = JsonKeys::keyLine(m_json, m_path, key);
            return line > 0 ? atPlace(linePlace(line), parsed.error()) : parsed.error();
        }
        return *parsed;
    }

private:
    QJsonObject m_object;
    const QByteArray &m_json;
    JsonKeys::Path m_path;
};

// Every key each object of the file has: what save() writes.
const QStringList &rootKeys()
{
    static const QStringList keys{QStringLiteral("format"), QStringLiteral("version"),
                                  QStringLiteral("tables"), QStringLiteral("symbols")};
    return keys;
}

const QStringList &tableKeys()
{
    static const QStringList keys{QStringLiteral("name"), QStringLiteral("intervalMs"),
                                  QStringLiteral("confirmWrites"), QStringLiteral("items")};
    return keys;
}

const QStringList &itemKeys()
{
    static const QStringList keys{
        QStringLiteral("address"),   QStringLiteral("station"),        QStringLiteral("format"),
        QStringLiteral("swapWords"), QStringLiteral("allowNonFinite"), QStringLiteral("name"),
        QStringLiteral("comment"),   QStringLiteral("alarms"),         QStringLiteral("history"),
    };
    return keys;
}

const QStringList &symbolKeys()
{
    static const QStringList keys{QStringLiteral("address"), QStringLiteral("name"),
                                  QStringLiteral("comment")};
    return keys;
}

Result<WatchItemSpec> entryFromJson(const QJsonValue &value, const QByteArray &json,
                                    const JsonKeys::Path &path)
{
    if (!value.isObject())
        return fileError(QStringLiteral("an item must be a JSON object"));
    const Members m(value.toObject(), json, path);
    if (Status s = m.rejectUnknown(itemKeys()); !s)
        return s.error();

    WatchItemSpec entry;
    const auto address = m.address();
    if (!address)
        return address.error();
    entry.address = *address;

    const auto station = m.integer(QStringLiteral("station"), 1, 1, 254);
    if (!station)
        return station.error();
    entry.station = static_cast<quint8>(*station);

    const auto formatName = m.text(QStringLiteral("format"), QString());
    if (!formatName)
        return formatName.error();
    if (formatName->isEmpty()) {
        entry.format = ValueFormat::defaultFormat(entry.address);
    } else if (const auto format = ValueFormat::fromName(*formatName)) {
        entry.format = *format;
    } else {
        return m.error(
            QStringLiteral("format"),
            QStringLiteral("unknown format \"%1\" (known: %2)").arg(*formatName, knownFormats()));
    }

    const auto swap = m.boolean(QStringLiteral("swapWords"), false);
    if (!swap)
        return swap.error();
    entry.swapWords = *swap;
    const auto nonFinite = m.boolean(QStringLiteral("allowNonFinite"), false);
    if (!nonFinite)
        return nonFinite.error();
    entry.allowNonFinite = *nonFinite;

    const auto name = m.text(QStringLiteral("name"), QString());
    if (!name)
        return name.error();
    entry.name = *name;
    const auto comment = m.text(QStringLiteral("comment"), QString());
    if (!comment)
        return comment.error();
    entry.comment = *comment;

    const auto alarmKeyLine = [&](qsizetype alarm, const QString &key) {
        JsonKeys::Path at = path;
        at << QStringLiteral("alarms") << alarm;
        return JsonKeys::keyLine(json, at, key);
    };
    const auto historyKeyLine = [&](const QString &key) {
        JsonKeys::Path at = path;
        at << QStringLiteral("history");
        return JsonKeys::keyLine(json, at, key);
    };
    auto alarms = Alarms::fromJson(m.object().value(QStringLiteral("alarms")), alarmKeyLine);
    if (!alarms)
        return alarms.error();
    entry.alarms = std::move(alarms).value();
    auto history
        = HistorySettings::fromJson(m.object().value(QStringLiteral("history")), historyKeyLine);
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
    const Members m(value.toObject(), json, {QStringLiteral("tables"), index});
    if (Status s = m.rejectUnknown(tableKeys()); !s)
        return atPlace(place, s.error());

    WatchTableSpec table;
    const auto name = m.text(QStringLiteral("name"), QStringLiteral("Table %1").arg(index + 1));
    if (!name)
        return atPlace(place, name.error());
    table.name = *name;
    const auto interval
        = m.integer(QStringLiteral("intervalMs"), 500, MinIntervalMs, MaxIntervalMs);
    if (!interval)
        return atPlace(place, interval.error());
    table.intervalMs = *interval;
    const auto confirm = m.boolean(QStringLiteral("confirmWrites"), true);
    if (!confirm)
        return atPlace(place, confirm.error());
    table.confirmWrites = *confirm;

    const QString itemsKey = QStringLiteral("items");
    const QJsonValue items = m.object().value(itemsKey);
    if (items.isUndefined())
        return table;
    if (!items.isArray())
        return atPlace(place, m.error(itemsKey, QStringLiteral("\"items\" must be a list")));
    const QJsonArray array = items.toArray();
    if (array.size() > MaxTableItems)
        return atPlace(place, tooManyItems(array.size()));
    for (qsizetype i = 0; i < array.size(); ++i) {
        auto entry
            = entryFromJson(array.at(i), json, {QStringLiteral("tables"), index, itemsKey, i});
        if (!entry)
            return atPlace(itemPlace(index, i), entry.error());
        table.items.append(std::move(entry).value());
    }
    return table;
}

Result<std::pair<Address, Symbol>> symbolFromJson(const QJsonValue &value, qsizetype index,
                                                  const QByteArray &json)
{
    if (!value.isObject())
        return fileError(QStringLiteral("a symbol must be a JSON object"));
    const Members m(value.toObject(), json, {QStringLiteral("symbols"), index});
    if (Status s = m.rejectUnknown(symbolKeys()); !s)
        return s.error();
    const auto address = m.address();
    if (!address)
        return address.error();
    const auto name = m.text(QStringLiteral("name"), QString());
    if (!name)
        return name.error();
    const auto comment = m.text(QStringLiteral("comment"), QString());
    if (!comment)
        return comment.error();
    return std::pair{*address, Symbol{*name, *comment}};
}

Result<SymbolTable> symbolsFromJson(const QJsonValue &value, const QByteArray &json)
{
    SymbolTable symbols;
    if (value.isUndefined())
        return symbols;
    if (!value.isArray())
        return fileError(QStringLiteral("\"symbols\" must be a list"));
    const QJsonArray array = value.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const auto symbol = symbolFromJson(array.at(i), i, json);
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

    // After the version: a newer file's new keys are "written by a newer FATEK Studio".
    if (Status s = Members(root, json, {}).rejectUnknown(rootKeys()); !s)
        return s.error();
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
    auto symbols = symbolsFromJson(root.value(QStringLiteral("symbols")), json);
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
