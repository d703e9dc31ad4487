// fatek-cli alarms: a watch list's alarms raised through a link (one line per event), or an
// alarm journal read back.
#include "clialarms.h"

#include "app/common/linkarguments.h"
#include "app/common/quitsignal.h"
#include "clioptions.h"
#include "clioutput.h"
#include "core/alarm/alarmengine.h"
#include "core/alarm/alarmjournal.h"
#include "core/alarm/alarmjournalwriter.h"
#include "core/alarm/alarmmessages.h"
#include "core/plant/plantconnection.h"
#include "core/qtbridge/qtmessage.h"
#include "core/watch/watchlist.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTextStream>

#include <limits>
#include <memory>

namespace Fatek {

namespace {

struct AlarmsOptions
{
    QString watchList;
    QString journal;
    QString connection;
    QString since, until;
    bool json = false;
    bool csv = false;
    LinkArguments link;
};

// The options in any order, before or after the word "alarms"; an option's value is the next
// argument or follows '=' (--since=-2h).
QString parse(const QStringList &arguments, AlarmsOptions *o)
{
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (!arg.startsWith(QLatin1String("--"))) {
            if (!o->watchList.isEmpty())
                return QStringLiteral("alarms takes one watch list (%1 and %2 given).")
                    .arg(o->watchList, arg);
            o->watchList = arg;
            continue;
        }
        QString name = arg.mid(2);
        std::optional<QString> value;
        if (const qsizetype eq = name.indexOf(QLatin1Char('=')); eq >= 0) {
            value = name.mid(eq + 1);
            name.truncate(eq);
        }
        if (name == QLatin1String("json") || name == QLatin1String("csv")) {
            if (value)
                return QStringLiteral("--%1 takes no value.").arg(name);
            (name == QLatin1String("json") ? o->json : o->csv) = true;
            continue;
        }
        const bool own = name == QLatin1String("journal") || name == QLatin1String("since")
                         || name == QLatin1String("until") || name == QLatin1String("connection");
        if (!own && !LinkArguments::names().contains(name))
            return QStringLiteral("Unknown option --%1 for alarms.").arg(name);
        if (!value) {
            if (i + 1 >= arguments.size())
                return QStringLiteral("--%1 needs a value.").arg(name);
            value = arguments.at(++i);
        }
        if (name == QLatin1String("journal"))
            o->journal = *value;
        else if (name == QLatin1String("since"))
            o->since = *value;
        else if (name == QLatin1String("until"))
            o->until = *value;
        else if (name == QLatin1String("connection"))
            o->connection = *value;
        else
            o->link.set(name, *value);
    }
    if (o->json && o->csv)
        return QStringLiteral("--json and --csv cannot be combined.");
    if (o->watchList.isEmpty() && o->journal.isEmpty())
        return QStringLiteral("alarms needs a watch list to watch, or --journal DB to read.");
    if (!o->watchList.isEmpty()) {
        if (!o->since.isEmpty() || !o->until.isEmpty() || o->csv)
            return QStringLiteral("--since, --until and --csv apply to reading a journal "
                                  "(alarms --journal DB without a watch list).");
    } else if (o->link.any()) {
        return QStringLiteral("Reading a journal needs no link option (%1 given).")
            .arg(QStringLiteral("--") + o->link.media.value(0, QStringLiteral("station")));
    }
    return {};
}

QJsonObject eventJson(const AlarmEvent &e)
{
    QJsonObject o;
    o.insert(QStringLiteral("time"), AlarmJournal::localTime(e.timeMs, e.utcOffsetS));
    o.insert(QStringLiteral("timeMs"), e.timeMs);
    o.insert(QStringLiteral("connection"), e.connection);
    o.insert(QStringLiteral("alarm"), e.alarmId);
    o.insert(QStringLiteral("kind"), Alarms::kindName(e.kind));
    o.insert(QStringLiteral("event"), Alarms::eventName(e.type));
    o.insert(QStringLiteral("state"), Alarms::stateName(e.state));
    o.insert(QStringLiteral("priority"), Alarms::priorityName(e.priority));
    o.insert(QStringLiteral("group"), e.group);
    o.insert(QStringLiteral("message"), e.message);
    o.insert(QStringLiteral("value"), e.value);
    o.insert(QStringLiteral("user"), e.user);
    o.insert(QStringLiteral("comment"), e.comment);
    if (e.shelvedUntilMs)
        o.insert(QStringLiteral("shelvedUntil"),
                 AlarmJournal::localTime(e.shelvedUntilMs, e.utcOffsetS));
    return o;
}

// "2026-12-07T17:23:31.253+08:00  raised  1-DR10-high  activeUnacked  high  Ramp high  value 812"
QString eventLine(const AlarmEvent &e, bool json)
{
    if (json)
        return QString::fromUtf8(QJsonDocument(eventJson(e)).toJson(QJsonDocument::Compact));
    QStringList cells{AlarmJournal::localTime(e.timeMs, e.utcOffsetS),
                      Alarms::eventName(e.type),
                      e.alarmId,
                      Alarms::stateName(e.state),
                      Alarms::priorityName(e.priority),
                      e.message};
    if (!e.value.isEmpty())
        cells << QStringLiteral("value %1").arg(e.value);
    if (!e.user.isEmpty())
        cells << QStringLiteral("by %1").arg(e.user);
    if (!e.comment.isEmpty())
        cells << QStringLiteral("\"%1\"").arg(e.comment);
    return cells.join(QLatin1String("  "));
}

int readJournal(const AlarmsOptions &o)
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    qint64 from = 0;
    qint64 to = std::numeric_limits<qint64>::max();
    for (const auto &[text, name, out] :
         {std::tuple{o.since, "since", &from}, std::tuple{o.until, "until", &to}}) {
        if (text.isEmpty())
            continue;
        const std::optional<qint64> ms = CliAlarms::parseTime(text, now);
        if (!ms)
            return CliAlarms::badTime(name, text, o.json);
        *out = *ms;
    }
    Result<std::unique_ptr<AlarmJournal>> journal = AlarmJournal::openReadOnly(o.journal);
    if (!journal) {
        const bool missing = journal.error().message.id == MessageId(MsgId::JournalMissing);
        return CliOutput::failure(journal.error().message,
                                  missing ? ExitCode::Usage : ExitCode::Internal, o.json);
    }
    Result<QList<AlarmEvent>> events = (*journal)->events(from, to, o.connection);
    if (!events)
        return CliOutput::failure(events.error().message, ExitCode::Internal, o.json);
    QByteArray out;
    if (o.csv) {
        out = AlarmJournal::toCsv(*events);
    } else {
        for (const AlarmEvent &e : *events)
            out += eventLine(e, o.json).toUtf8() + '\n';
    }
    bool closedPipe = false;
    if (const QString error = CliOutput::writeStdout(out, &closedPipe); !error.isEmpty())
        return closedPipe ? ExitCode::ClosedPipe : ExitCode::Internal;
    return ExitCode::Ok;
}

int watch(const AlarmsOptions &o)
{
    Result<WatchListFile> file = WatchList::loadFromFile(o.watchList);
    if (!file)
        return CliOutput::failure(file.error().message, ExitCode::Usage, o.json);
    QList<WatchedItem> items;
    for (const WatchTableSpec &table : std::as_const(file->tables)) {
        for (const WatchItemSpec &item : table.items) {
            if (!item.alarms.isEmpty())
                items.append(WatchedItem{WatchedItem::newKey(), item, table.intervalMs});
        }
    }
    if (items.isEmpty())
        return CliOutput::usageError(
            QStringLiteral("%1 defines no alarm (an item's \"alarms\").").arg(o.watchList), o.json);
    LinkArgumentRules rules;
    rules.minStation = 1;
    rules.environment = true;
    const LinkArgumentsResult link = resolveLinkArguments(o.link, rules);
    if (!link.error.isEmpty())
        return CliOutput::usageError(link.error, o.json);

    const QString connection
        = o.connection.isEmpty() ? QFileInfo(o.watchList).completeBaseName() : o.connection;
    int code = ExitCode::Ok;
    AlarmEngine engine(connection);
    engine.setItems(items);
    // Declared after the engine: destroyed first, it writes what is pending while the engine's
    // events still reach it.
    std::unique_ptr<AlarmJournalWriter> writer;
    if (!o.journal.isEmpty()) {
        writer = std::make_unique<AlarmJournalWriter>(o.journal);
        // The watch goes on without its journal; the exit code says the file was not written.
        QObject::connect(writer.get(), &AlarmJournalWriter::failed, &engine,
                         [&code](const Message &reason) {
                             code = ExitCode::Internal;
                             CliOutput::failure(reason, ExitCode::Internal, false);
                         });
        writer->attach(&engine);
    }
    QObject::connect(&engine, &AlarmEngine::alarmEvent, &engine,
                     [&o, &code](const AlarmEvent &event, const AlarmRecord &) {
                         bool closedPipe = false;
                         CliOutput::writeStdout(eventLine(event, o.json).toUtf8() + '\n',
                                                &closedPipe);
                         if (closedPipe) {
                             code = ExitCode::ClosedPipe;
                             QCoreApplication::exit(code);
                         }
                     });
    PlantConnection::DirectOptions direct;
    direct.readOnly = true; // alarms only read
    direct.trafficLog = false;
    std::unique_ptr<PlantConnection> plant(PlantConnection::direct(link.link, direct));
    // The link's losses and returns on stderr: a watch that prints nothing may be a link down.
    QObject::connect(plant.get(), &PlantConnection::linkStateChanged, &engine,
                     [](LinkState state, const Message &reason) {
                         if (state != LinkState::Lost && state != LinkState::Connected)
                             return;
                         QTextStream err(stderr);
                         err << "fatek-cli: link " << linkStateName(state);
                         if (!reason.empty())
                             err << ": " << englishText(reason);
                         err << '\n';
                     });
    engine.attach(plant.get());
    plant->open();
    QTextStream(stderr) << "Watching " << engine.alarmCount() << " alarms of " << o.watchList
                        << " (Ctrl-C ends).\n";
    // Ctrl-C ends the watch: the journal written, the link closed.
    onQuitSignal(&engine, [] { QCoreApplication::exit(0); });
    const int ended = QCoreApplication::exec();
    engine.attach(nullptr);
    writer.reset();
    plant->close();
    return code != ExitCode::Ok ? code : ended;
}

} // namespace

namespace CliAlarms {

int badTime(const char *name, const QString &text, bool json)
{
    return CliOutput::usageError(QStringLiteral("--%1: \"%2\" is not a time (ISO 8601 such as "
                                                "2026-12-07 or 2026-12-07T08:00[:00][+08:00], "
                                                "now, or before now: -90s, -30m, -2h, -7d).")
                                     .arg(QLatin1String(name), text),
                                 json);
}

std::optional<qint64> parseTime(const QString &text, qint64 nowMs)
{
    const QString t = text.trimmed();
    if (t == QLatin1String("now"))
        return nowMs;
    static const QRegularExpression relative(QStringLiteral("^-(\\d{1,9})([smhd])$"));
    if (const QRegularExpressionMatch m = relative.match(t); m.hasMatch()) {
        const qint64 n = m.captured(1).toLongLong();
        const QChar unit = m.captured(2).at(0);
        const qint64 scale = unit == QLatin1Char('s')   ? 1000
                             : unit == QLatin1Char('m') ? 60000
                             : unit == QLatin1Char('h') ? 3600000
                                                        : 86400000;
        return nowMs - n * scale;
    }
    // A date alone is its local midnight.
    if (const QDate date = QDate::fromString(t, Qt::ISODate); date.isValid() && t.size() == 10)
        return date.startOfDay().toMSecsSinceEpoch();
    static const QRegularExpression iso(
        QStringLiteral("^\\d{4}-\\d{2}-\\d{2}[T ]\\d{2}:\\d{2}(:\\d{2}(\\.\\d{1,3})?)?"
                       "(Z|[+-]\\d{2}:?\\d{2})?$"));
    if (!iso.match(t).hasMatch())
        return std::nullopt;
    QString normal = t;
    normal.replace(10, 1, QLatin1Char('T'));
    const QDateTime at = QDateTime::fromString(normal, Qt::ISODateWithMs);
    if (!at.isValid())
        return std::nullopt;
    return at.toMSecsSinceEpoch();
}

} // namespace CliAlarms

int runAlarms(const QStringList &arguments)
{
    AlarmsOptions o;
    if (const QString error = parse(arguments, &o); !error.isEmpty())
        return CliOutput::usageError(error, arguments.contains(QLatin1String("--json")));
    return o.watchList.isEmpty() ? readJournal(o) : watch(o);
}

} // namespace Fatek
