#include "snapshotfile.h"

#include "commissionmessages.h"
#include "core/watch/safefile.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

#include <cmath>

namespace Fatek::SnapshotFile {

namespace {

using Kind = Error::Kind;

std::uint64_t maxValue(const Address &a)
{
    return (std::uint64_t{1} << Snapshot::valueBits(a)) - 1;
}

QString hexText(const SnapshotValue &v)
{
    const int bits = Snapshot::valueBits(v.address);
    if (bits == 1)
        return {};
    return QStringLiteral("0x%1")
        .arg(v.value, bits / 4, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString takenText(const QDateTime &taken)
{
    return taken.isValid() ? taken.toUTC().toString(Qt::ISODate) : QString();
}

Loaded failed(Kind kind, Message message, int line = 0, int valueIndex = 0)
{
    Loaded l;
    l.error = Error{kind, line, valueIndex, std::move(message)};
    return l;
}

Loaded failedAtLine(Kind kind, int line, Message what)
{
    return failed(kind, msg<MsgId::AtPlace>(msg<MsgId::PlaceLine>(line), std::move(what)), line);
}

Loaded failedAtValue(int index, Message what)
{
    return failed(Kind::Content,
                  msg<MsgId::AtPlace>(msg<MsgId::SnapshotPlaceValue>(index), std::move(what)), 0,
                  index);
}

// The address and value of one row or entry checked: the message when they are not acceptable.
std::optional<Message> checkValue(const QString &addressText, std::optional<std::uint64_t> value,
                                  const QString &valueText, SnapshotValue *out)
{
    const auto address = Address::parse(addressText.toStdString());
    if (!address)
        return address.error().message;
    if (!value)
        return msg<MsgId::SnapshotNotNumber>(valueText.toStdString());
    const std::uint64_t max = maxValue(*address);
    if (*value > max)
        return msg<MsgId::SnapshotOutOfRange>(std::to_string(*value), address->toString(),
                                              std::to_string(max));
    out->address = *address;
    out->value = static_cast<std::uint32_t>(*value);
    return std::nullopt;
}

std::optional<std::uint64_t> parseUnsigned(const QString &text, int base)
{
    bool ok = false;
    const qulonglong v = text.trimmed().toULongLong(&ok, base);
    if (!ok)
        return std::nullopt;
    return v;
}

// Sorted, each address once: the place of the second of two equal addresses otherwise.
std::optional<std::size_t> firstDuplicate(std::vector<std::pair<SnapshotValue, int>> &values)
{
    std::stable_sort(values.begin(), values.end(), [](const auto &a, const auto &b) {
        return a.first.address < b.first.address;
    });
    for (std::size_t i = 1; i < values.size(); ++i) {
        if (values[i].first.address == values[i - 1].first.address)
            return std::max(values[i].second, values[i - 1].second);
    }
    return std::nullopt;
}

QByteArray saveJson(const MemorySnapshot &s)
{
    QJsonObject root;
    root.insert(QStringLiteral("format"), QLatin1String(FormatMarker));
    root.insert(QStringLiteral("version"), CurrentVersion);
    root.insert(QStringLiteral("taken"), takenText(s.info.taken));
    root.insert(QStringLiteral("link"), s.info.link);
    root.insert(QStringLiteral("station"), s.info.station);
    root.insert(QStringLiteral("protocol"), s.info.protocol);
    root.insert(QStringLiteral("model"), s.info.model);
    // One value per line (readable, and a version control diff shows the changed elements).
    QByteArray text = QJsonDocument(root).toJson(QJsonDocument::Indented);
    text.chop(3); // "\n}\n"
    text += ",\n    \"values\": [";
    for (std::size_t i = 0; i < s.values.size(); ++i) {
        const SnapshotValue &v = s.values[i];
        text += (i == 0 ? "\n" : ",\n");
        text += "        {\"address\": \"" + QByteArray::fromStdString(v.address.toString())
                + "\", \"value\": " + QByteArray::number(v.value) + '}';
    }
    text += s.values.empty() ? "]\n}\n" : "\n    ]\n}\n";
    return text;
}

QByteArray saveCsv(const MemorySnapshot &s, CsvFile::LineEnd lineEnd)
{
    QString out;
    auto meta = [&out](const char *key, const QString &value) {
        QString clean = value;
        clean.replace(QLatin1Char('\n'), QLatin1Char(' '))
            .replace(QLatin1Char('\r'), QLatin1Char(' '));
        out += QStringLiteral("# %1: %2\n").arg(QLatin1String(key), clean);
    };
    out += QStringLiteral("# %1 %2\n").arg(QLatin1String(FormatMarker)).arg(CurrentVersion);
    meta("taken", takenText(s.info.taken));
    meta("link", s.info.link);
    meta("station", QString::number(s.info.station));
    meta("protocol", s.info.protocol);
    meta("model", s.info.model);
    out += QStringLiteral("address,value,hex\n");
    for (const SnapshotValue &v : s.values) {
        out += QString::fromStdString(v.address.toString()) + QLatin1Char(',')
               + QString::number(v.value) + QLatin1Char(',') + hexText(v) + QLatin1Char('\n');
    }
    return CsvFile::bytes(out, lineEnd);
}

// Line and column (1-based) of a byte offset.
std::pair<int, int> lineColumn(const QByteArray &data, qsizetype offset)
{
    int line = 1;
    int column = 1;
    for (qsizetype i = 0; i < offset && i < data.size(); ++i) {
        if (data.at(i) == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

Loaded loadJson(const QByteArray &data)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const auto [line, column] = lineColumn(data, parseError.offset);
        return failed(Kind::Syntax,
                      msg<MsgId::AtPlace>(
                          msg<MsgId::SnapshotPlaceLineColumn>(line, column),
                          msg<MsgId::SnapshotJsonSyntax>(parseError.errorString().toStdString())),
                      line);
    }
    const QJsonObject root = doc.object();
    if (!doc.isObject()
        || root.value(QStringLiteral("format")).toString() != QLatin1String(FormatMarker))
        return failed(Kind::NotSnapshot, msg<MsgId::SnapshotNotSnapshot>(FormatMarker));
    const QJsonValue version = root.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() != CurrentVersion)
        return failed(Kind::Version, msg<MsgId::SnapshotVersion>(
                                         version.isUndefined() ? std::string("?")
                                                               : QJsonDocument(QJsonArray{version})
                                                                     .toJson(QJsonDocument::Compact)
                                                                     .mid(1)
                                                                     .chopped(1)
                                                                     .toStdString(),
                                         CurrentVersion));
    if (!root.value(QStringLiteral("values")).isArray())
        return failed(Kind::Content, msg<MsgId::SnapshotMissing>("values"));

    MemorySnapshot s;
    s.info.taken
        = QDateTime::fromString(root.value(QStringLiteral("taken")).toString(), Qt::ISODate);
    s.info.link = root.value(QStringLiteral("link")).toString();
    s.info.station = root.value(QStringLiteral("station")).toInt(1);
    s.info.protocol = root.value(QStringLiteral("protocol")).toString();
    s.info.model = root.value(QStringLiteral("model")).toString();

    const QJsonArray values = root.value(QStringLiteral("values")).toArray();
    if (static_cast<std::size_t>(values.size()) > Snapshot::MaxValues)
        return failed(Kind::Content,
                      msg<MsgId::SnapshotTooMany>(values.size(), Snapshot::MaxValues));
    std::vector<std::pair<SnapshotValue, int>> read;
    read.reserve(static_cast<std::size_t>(values.size()));
    for (qsizetype i = 0; i < values.size(); ++i) {
        const int index = static_cast<int>(i + 1);
        const QJsonObject entry = values.at(i).toObject();
        if (!entry.contains(QStringLiteral("address")))
            return failedAtValue(index, msg<MsgId::SnapshotMissing>("address"));
        if (!entry.contains(QStringLiteral("value")))
            return failedAtValue(index, msg<MsgId::SnapshotMissing>("value"));
        const QJsonValue v = entry.value(QStringLiteral("value"));
        std::optional<std::uint64_t> number;
        const double d = v.toDouble(-1);
        if (v.isDouble() && d >= 0 && d <= 4294967295.0 && std::floor(d) == d)
            number = static_cast<std::uint64_t>(d);
        const QString valueText = v.isString()
                                      ? v.toString()
                                      : QString::fromUtf8(QJsonDocument(QJsonArray{v})
                                                              .toJson(QJsonDocument::Compact)
                                                              .mid(1)
                                                              .chopped(1));
        SnapshotValue sv;
        if (auto problem
            = checkValue(entry.value(QStringLiteral("address")).toString(), number, valueText, &sv))
            return failedAtValue(index, std::move(*problem));
        read.emplace_back(sv, index);
    }
    if (const auto dup = firstDuplicate(read)) {
        std::string address;
        for (const auto &[v, index] : read) {
            if (index == static_cast<int>(*dup))
                address = v.address.toString();
        }
        return failedAtValue(static_cast<int>(*dup), msg<MsgId::SnapshotDuplicate>(address));
    }
    for (const auto &entry : read)
        s.values.push_back(entry.first);
    return Loaded{std::move(s), {}};
}

Loaded loadCsv(const QByteArray &data)
{
    QString text = QString::fromUtf8(data);
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    MemorySnapshot s;
    bool header = false;
    bool hexColumn = false;
    std::vector<std::pair<SnapshotValue, int>> read;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNo = static_cast<int>(i + 1);
        QString line = lines.at(i);
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (line.trimmed().isEmpty())
            continue;
        if (line.startsWith(QLatin1Char('#'))) {
            const QString body = line.mid(1).trimmed();
            if (body.startsWith(QLatin1String(FormatMarker))) {
                const QString version = body.mid(qsizetype(qstrlen(FormatMarker))).trimmed();
                if (!version.isEmpty() && version != QString::number(CurrentVersion))
                    return failedAtLine(
                        Kind::Version, lineNo,
                        msg<MsgId::SnapshotVersion>(version.toStdString(), CurrentVersion));
                continue;
            }
            const qsizetype colon = body.indexOf(QLatin1Char(':'));
            if (colon <= 0) {
                if (header)
                    continue; // a comment among the rows
                return failedAtLine(Kind::Syntax, lineNo, msg<MsgId::SnapshotCsvBadMeta>());
            }
            const QString key = body.left(colon).trimmed().toLower();
            const QString value = body.mid(colon + 1).trimmed();
            if (key == QLatin1String("taken"))
                s.info.taken = QDateTime::fromString(value, Qt::ISODate);
            else if (key == QLatin1String("link"))
                s.info.link = value;
            else if (key == QLatin1String("station"))
                s.info.station = value.toInt();
            else if (key == QLatin1String("protocol"))
                s.info.protocol = value;
            else if (key == QLatin1String("model"))
                s.info.model = value;
            continue;
        }
        const QStringList cells = line.split(QLatin1Char(','));
        if (!header) {
            const QString joined = cells.join(QLatin1Char(',')).remove(QLatin1Char(' ')).toLower();
            if (joined == QLatin1String("address,value")
                || joined == QLatin1String("address,value,hex")) {
                header = true;
                hexColumn = cells.size() == 3;
                continue;
            }
            return failedAtLine(Kind::Syntax, lineNo, msg<MsgId::SnapshotCsvColumns>());
        }
        if (cells.size() < 2 || cells.size() > (hexColumn ? 3 : 2))
            return failedAtLine(Kind::Syntax, lineNo, msg<MsgId::SnapshotCsvColumns>());
        if (read.size() >= Snapshot::MaxValues)
            return failedAtLine(Kind::Content, lineNo,
                                msg<MsgId::SnapshotTooMany>(read.size() + 1, Snapshot::MaxValues));
        SnapshotValue sv;
        if (auto problem = checkValue(cells.at(0).trimmed(), parseUnsigned(cells.at(1), 10),
                                      cells.at(1).trimmed(), &sv))
            return failedAtLine(Kind::Content, lineNo, std::move(*problem));
        if (cells.size() == 3 && !cells.at(2).trimmed().isEmpty()) {
            QString hex = cells.at(2).trimmed();
            if (hex.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
                hex = hex.mid(2);
            const auto h = parseUnsigned(hex, 16);
            if (!h || *h != sv.value)
                return failedAtLine(
                    Kind::Content, lineNo,
                    msg<MsgId::SnapshotHexMismatch>(cells.at(2).trimmed().toStdString(),
                                                    std::to_string(sv.value)));
        }
        read.emplace_back(sv, lineNo);
    }
    if (!header)
        return failed(Kind::Syntax, msg<MsgId::SnapshotCsvColumns>());
    if (const auto dup = firstDuplicate(read)) {
        std::string address;
        for (const auto &[v, line] : read) {
            if (line == static_cast<int>(*dup))
                address = v.address.toString();
        }
        return failedAtLine(Kind::Content, static_cast<int>(*dup),
                            msg<MsgId::SnapshotDuplicate>(address));
    }
    for (const auto &entry : read)
        s.values.push_back(entry.first);
    return Loaded{std::move(s), {}};
}

} // namespace

std::optional<Format> formatFor(const QString &path)
{
    if (path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive))
        return Format::Json;
    if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive))
        return Format::Csv;
    // A device or a pipe (/dev/stdout) has no extension to go by: JSON.
    if (const QFileInfo info(path); info.exists() && !info.isFile() && !info.isDir())
        return Format::Json;
    return std::nullopt;
}

QByteArray save(const MemorySnapshot &snapshot, Format format, CsvFile::LineEnd lineEnd)
{
    return format == Format::Json ? saveJson(snapshot) : saveCsv(snapshot, lineEnd);
}

Loaded load(const QByteArray &data, Format format)
{
    return format == Format::Json ? loadJson(data) : loadCsv(data);
}

std::optional<Error> saveToFile(const MemorySnapshot &snapshot, const QString &path,
                                CsvFile::LineEnd lineEnd)
{
    const auto format = formatFor(path);
    if (!format)
        return Error{Kind::Io, 0, 0, msg<MsgId::SnapshotFileUnknownType>(path.toStdString())};
    const QByteArray data = save(snapshot, *format, lineEnd);
    if (const QString reason = SafeFile::write(path, data); !reason.isEmpty())
        return Error{Kind::Io, 0, 0,
                     msg<MsgId::SnapshotFileCannotWrite>(path.toStdString(),
                                                         Message::text(reason.toStdString()))};
    return std::nullopt;
}

Loaded loadFromFile(const QString &path)
{
    const auto format = formatFor(path);
    if (!format)
        return failed(Kind::Io, msg<MsgId::SnapshotFileUnknownType>(path.toStdString()));
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return failed(Kind::Io,
                      msg<MsgId::SnapshotFileCannotRead>(
                          path.toStdString(), Message::text(in.errorString().toStdString())));
    Loaded loaded = load(in.readAll(), *format);
    if (!loaded.ok())
        loaded.error.message = msg<MsgId::AtPlace>(path.toStdString(), loaded.error.message);
    return loaded;
}

} // namespace Fatek::SnapshotFile
