#include "datalogger.h"

#include "csvfield.h"
#include "csvfile.h"
#include "safefile.h"

#include <QDir>
#include <QFileInfo>
#include <QStringConverter>

#include <algorithm>

namespace Fatek {

namespace {

ProtocolError fileError(const QString &text)
{
    return makeError(ErrorKind::InvalidRequest, text.toStdString());
}

// Where the file's last whole row ends: its size when it ends with a line end, else just after
// the last line end (0 without one).
qint64 lastRowEnd(QFile &file)
{
    constexpr qint64 chunk = 64 * 1024;
    qint64 end = file.size();
    while (end > 0) {
        const qint64 from = std::max<qint64>(0, end - chunk);
        if (!file.seek(from))
            return file.size();
        const QByteArray bytes = file.read(end - from);
        if (bytes.size() != end - from)
            return file.size();
        const qsizetype newline = bytes.lastIndexOf('\n');
        if (newline >= 0)
            return from + newline + 1;
        end = from;
    }
    return 0;
}

// The first line of an existing file, without its line end (and without a UTF-8 BOM), and the
// line end it has (the rows appended to it keep it).
QString firstLine(QFile &file, CsvFile::LineEnd *lineEnd)
{
    QByteArray line = file.readLine(64 * 1024);
    *lineEnd = CsvFile::lineEndOf(line);
    if (line.startsWith(CsvFile::Bom))
        line.remove(0, 3);
    while (line.endsWith('\n') || line.endsWith('\r'))
        line.chop(1);
    return QString::fromUtf8(line);
}

} // namespace

DataLogger::~DataLogger()
{
    close();
}

QString DataLogger::timestampText(const QDateTime &time)
{
    const QDateTime local = time.toLocalTime();
    const int offset = local.offsetFromUtc();
    const int minutes = (offset < 0 ? -offset : offset) / 60;
    return local.toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss.zzz"))
           + (offset < 0 ? QLatin1Char('-') : QLatin1Char('+'))
           + QStringLiteral("%1:%2")
                 .arg(minutes / 60, 2, 10, QLatin1Char('0'))
                 .arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

QString DataLogger::valueText(const WatchItemSpec &item, std::uint64_t raw)
{
    const int width = ValueFormat::valueWidth(item.address, item.format);
    if (width == 1)
        return (raw & 1u) ? QStringLiteral("1") : QStringLiteral("0");
    return ValueFormat::format(raw, width, item.format, item.swapWords);
}

QString DataLogger::columnName(const WatchItemSpec &item)
{
    QString address = QString::fromStdString(item.address.toString());
    if (item.station != 1)
        address += QStringLiteral("@%1").arg(item.station);
    const QString name = item.name.trimmed();
    return name.isEmpty() ? address : QStringLiteral("%1 (%2)").arg(name, address);
}

QStringList DataLogger::columnNames(const QList<WatchItemSpec> &items)
{
    QStringList names;
    for (const WatchItemSpec &item : items)
        names << columnName(item);
    // The same column twice (one address in two formats): each of them says its format.
    QStringList unique = names;
    for (qsizetype i = 0; i < names.size(); ++i) {
        if (names.count(names.at(i)) > 1)
            unique[i]
                = QStringLiteral("%1 [%2]").arg(names.at(i), ValueFormat::name(items.at(i).format));
    }
    // Still twice (the same item in the same format): the later ones are numbered.
    for (qsizetype i = 0; i < unique.size(); ++i) {
        int n = 1;
        for (qsizetype j = 0; j < i; ++j) {
            if (unique.at(j) == unique.at(i)
                || unique.at(j).startsWith(unique.at(i) + QStringLiteral(" #")))
                ++n;
        }
        if (n > 1)
            unique[i] += QStringLiteral(" #%1").arg(n);
    }
    return unique;
}

QString DataLogger::csvCell(const QString &text)
{
    return CsvField::quoted(text);
}

QString DataLogger::qualityName(Quality quality)
{
    switch (quality) {
    case Quality::Good: return QStringLiteral("ok");
    case Quality::Late: return QStringLiteral("late");
    case Quality::Stale: return QStringLiteral("stale");
    case Quality::Error: return QStringLiteral("error");
    case Quality::Missing: return QStringLiteral("missing");
    }
    return QStringLiteral("missing");
}

DataLogger::Quality DataLogger::qualityOf(ValueQuality quality)
{
    switch (quality) {
    case ValueQuality::Good: return Quality::Good;
    case ValueQuality::Late: return Quality::Late;
    case ValueQuality::Stale: return Quality::Stale;
    case ValueQuality::Error: return Quality::Error;
    }
    return Quality::Error;
}

QString DataLogger::headerLine(const QList<WatchItemSpec> &items)
{
    QStringList cells{QStringLiteral("timestamp")};
    for (const QString &name : columnNames(items))
        cells << csvCell(name);
    cells << QStringLiteral("status");
    return cells.join(QLatin1Char(','));
}

QString DataLogger::rowLine(const QDateTime &time, const QList<WatchItemSpec> &items,
                            const QList<Cell> &cells)
{
    QStringList out{timestampText(time)};
    // Items that are not fresh for the same cause share one note: "stale R1, R2 (timeout)";
    // when no item is fresh for one cause (the link is down), "error all items (reason)".
    struct Problem
    {
        Quality quality;
        QString reason;
        QStringList columns;
    };
    QList<Problem> problems;
    const QStringList names = columnNames(items);
    for (qsizetype i = 0; i < items.size(); ++i) {
        const Cell cell = i < cells.size() ? cells.at(i) : Cell{};
        if (cell.quality == Quality::Good) {
            out << csvCell(valueText(items.at(i), cell.raw));
            continue;
        }
        out << QString(); // never a stale value as if it were fresh
        auto same = std::find_if(problems.begin(), problems.end(), [&cell](const Problem &p) {
            return p.quality == cell.quality && p.reason == cell.reason;
        });
        if (same == problems.end())
            problems.append({cell.quality, cell.reason, {names.at(i)}});
        else
            same->columns << names.at(i);
    }
    QStringList notes;
    for (const Problem &p : problems) {
        const QString which = p.columns.size() > 1 && p.columns.size() == items.size()
                                  ? QStringLiteral("all items")
                                  : p.columns.join(QLatin1String(", "));
        QString note = QStringLiteral("%1 %2").arg(qualityName(p.quality), which);
        if (!p.reason.isEmpty())
            note += QStringLiteral(" (%1)").arg(p.reason);
        notes << note;
    }
    out << csvCell(notes.isEmpty() ? QStringLiteral("ok") : notes.join(QLatin1String("; ")));
    return out.join(QLatin1Char(','));
}

Status DataLogger::open(const QString &path, const QList<WatchItemSpec> &items,
                        CsvFile::LineEnd lineEnd)
{
    close();
    m_failure.reset();
    m_fileProblem = false;
    m_rows = 0;
    if (path.trimmed().isEmpty())
        return fileError(QStringLiteral("No log file given."));
    if (items.isEmpty())
        return fileError(QStringLiteral("Nothing to log: the table has no items."));
    for (const WatchItemSpec &item : items) {
        if (ValueFormat::valueWidth(item.address, item.format) == 0)
            return fileError(QStringLiteral("%1 cannot be shown as %2.")
                                 .arg(columnName(item), ValueFormat::name(item.format)));
    }
    const QStringList columns = QStringList{QStringLiteral("timestamp")} + columnNames(items)
                                + QStringList{QStringLiteral("status")};
    const QString header = headerLine(items);

    const QString native = QDir::toNativeSeparators(path);
    const QFileInfo info(path);
    // From here on a refusal is the file system's (the place, the medium), not the items'.
    m_fileProblem = true;
    if (info.isDir())
        return fileError(QStringLiteral("%1 is a folder, not a file.").arg(native));
    if (!info.absoluteDir().exists())
        return fileError(
            QStringLiteral("Cannot log to %1: the folder %2 does not exist.")
                .arg(native, QDir::toNativeSeparators(info.absoluteDir().absolutePath())));

    m_file.setFileName(path);
    // Read+append: an existing log's header is checked before anything is added to it. A device
    // or a named pipe (QFileInfo follows links) cannot be read back nor sought: it is written
    // only, each row flushed and checked like a file's.
    const bool regular = !info.exists() || info.isFile();
    const bool existed = info.exists();
    // Unbuffered: each row reaches the system at once and its write's result is the real one
    // (a buffered row that fails later, at a flush, loses the system's reason).
    if (!m_file.open(regular ? QIODevice::ReadWrite | QIODevice::Append | QIODevice::Unbuffered
                             : QIODevice::WriteOnly | QIODevice::Unbuffered))
        return fileError(
            QStringLiteral("Cannot open %1 for writing: %2").arg(native, m_file.errorString()));
    const bool isNew = !regular || m_file.size() == 0;
    if (!isNew) {
        m_file.seek(0);
        const QString existing = firstLine(m_file, &lineEnd);
        if (existing != header) {
            m_file.close();
            m_fileProblem = false; // what the file holds: another log
            return fileError(QStringLiteral("%1 already holds a log with other columns (\"%2\"); "
                                            "choose a new file.")
                                 .arg(native, existing.left(120)));
        }
        // Appending: a last row cut short (an earlier run on a full disk, a power cut) is
        // dropped, so that the new rows do not follow half a row.
        if (const qint64 end = lastRowEnd(m_file); end < m_file.size() && !m_file.resize(end))
            return fail(QStringLiteral("Cannot write to %1").arg(native), m_file.errorString());
        m_file.seek(m_file.size());
    }
    m_path = path;
    m_items = items;
    m_columns = columns;
    m_lineEnd = lineEnd;
    // The header reaches the disk at once: an unwritable medium shows up at start, not later.
    if (isNew) {
        // A new file starts with the byte order mark (Excel reads it as UTF-8 then); a device
        // or a pipe is no file a spreadsheet opens.
        const QString line = header + QLatin1Char('\n');
        if (const QString reason = SafeFile::writeAll(
                m_file, regular ? CsvFile::bytes(line, lineEnd) : CsvFile::lines(line, lineEnd));
            !reason.isEmpty()) {
            // No log is left behind that holds nothing, or half a header.
            if (regular) {
                if (existed)
                    m_file.resize(0);
                else
                    m_file.remove();
            }
            return fail(QStringLiteral("Cannot write to %1").arg(native), reason);
        }
    }
    m_fileProblem = false;
    m_sinceFlush.start();
    return Ok{};
}

Status DataLogger::writeRow(const QDateTime &time, const QList<Cell> &cells)
{
    if (m_failure)
        return *m_failure;
    if (!m_file.isOpen())
        return fileError(QStringLiteral("The data log is not open."));
    const QByteArray line
        = CsvFile::lines(rowLine(time, m_items, cells) + QLatin1Char('\n'), m_lineEnd);
    // A row is written whole or not at all: what part of it fitted is taken back.
    const qint64 before = m_file.isSequential() ? -1 : m_file.size();
    if (const QString reason = SafeFile::writeAll(m_file, line); !reason.isEmpty()) {
        if (before >= 0)
            m_file.resize(before);
        return fail(QStringLiteral("Cannot write to %1").arg(QDir::toNativeSeparators(m_path)),
                    reason);
    }
    ++m_rows;
    if (m_flushIntervalMs <= 0 || m_sinceFlush.elapsed() >= m_flushIntervalMs)
        return flush();
    return Ok{};
}

Status DataLogger::flush()
{
    if (m_failure)
        return *m_failure;
    if (!m_file.isOpen())
        return Ok{};
    m_sinceFlush.restart();
    if (!m_file.flush())
        return fail(QStringLiteral("Cannot write to %1").arg(QDir::toNativeSeparators(m_path)),
                    m_file.errorString());
    return Ok{};
}

Status DataLogger::close()
{
    if (!m_file.isOpen())
        return m_failure ? Status(*m_failure) : Status(Ok{});
    const Status s = flush();
    m_file.close();
    return s;
}

Status DataLogger::fail(const QString &what, const QString &reason)
{
    // The OS reason (e.g. "No space left on device").
    m_failure = fileError(QStringLiteral("%1: %2. Logging stopped.").arg(what, reason));
    // Whatever the buffer still holds cannot be written either; drop it rather than retry.
    m_file.close();
    return *m_failure;
}

} // namespace Fatek
