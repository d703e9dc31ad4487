// fatek-cli history: a history store's series, or samples of some of them over a range.
#include "clihistory.h"

#include "clialarms.h"
#include "clioptions.h"
#include "clioutput.h"
#include "core/history/historycsv.h"
#include "core/history/historymessages.h"
#include "core/history/historystore.h"
#include "core/qtbridge/qtmessage.h"

#include <QDateTime>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>

#include <memory>

namespace Fatek {

namespace {

struct HistoryOptions
{
    QString store;
    QStringList items;
    QString from = QStringLiteral("-1h");
    QString to = QStringLiteral("now");
    qint64 limit = 0;
    bool json = false;
    bool csv = false;
};

QString parse(const QStringList &arguments, HistoryOptions *o)
{
    for (qsizetype i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        if (!arg.startsWith(QLatin1String("--"))) {
            (o->store.isEmpty() ? o->store : o->items.emplaceBack()) = arg;
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
        if (name != QLatin1String("from") && name != QLatin1String("to")
            && name != QLatin1String("limit"))
            return QStringLiteral("Unknown option --%1 for history.").arg(name);
        if (!value) {
            if (i + 1 >= arguments.size())
                return QStringLiteral("--%1 needs a value.").arg(name);
            value = arguments.at(++i);
        }
        if (name == QLatin1String("from")) {
            o->from = *value;
        } else if (name == QLatin1String("to")) {
            o->to = *value;
        } else {
            bool ok = false;
            o->limit = value->toLongLong(&ok);
            if (!ok || o->limit < 1)
                return QStringLiteral("--limit: \"%1\" is not a count of 1 or more.").arg(*value);
        }
    }
    if (o->json && o->csv)
        return QStringLiteral("--json and --csv cannot be combined.");
    if (o->store.isEmpty())
        return QStringLiteral("history needs a store: an SQLite file or a postgresql:// URL.");
    return {};
}

// ITEM is a series' key ("line1/1-R100"), its item ("1-R100"), its address ("R100", station 1)
// or its label; it must name one series.
QString find(const QList<HistorySeries> &all, const QString &item, HistorySeries *out)
{
    QList<HistorySeries> found;
    for (const HistorySeries &s : all) {
        if (s.key() == item) {
            *out = s;
            return {};
        }
        if (s.item.compare(item, Qt::CaseInsensitive) == 0
            || s.item.compare(QStringLiteral("1-") + item, Qt::CaseInsensitive) == 0
            || (!s.label.isEmpty() && s.label == item))
            found.append(s);
    }
    if (found.size() == 1) {
        *out = found.first();
        return {};
    }
    if (found.isEmpty())
        return QStringLiteral("%1 is no series of the store (fatek-cli history DB lists them).")
            .arg(item);
    QStringList keys;
    for (const HistorySeries &s : std::as_const(found))
        keys << s.key();
    return QStringLiteral("%1 names several series: %2; give one of these.")
        .arg(item, keys.join(QStringLiteral(", ")));
}

QByteArray seriesLines(const QList<HistorySeries> &all, bool json)
{
    QByteArray out;
    for (const HistorySeries &s : all) {
        if (json) {
            const QJsonObject o{
                {QStringLiteral("series"), s.key()},  {QStringLiteral("source"), s.source},
                {QStringLiteral("item"), s.item},     {QStringLiteral("label"), s.label},
                {QStringLiteral("format"), s.format}, {QStringLiteral("heartbeatS"), s.heartbeatS}};
            out += QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n';
        } else {
            out += QStringList{s.key(), s.label.isEmpty() ? QStringLiteral("-") : s.label, s.format,
                               QStringLiteral("heartbeat %1 s").arg(s.heartbeatS)}
                       .join(QLatin1String("  "))
                       .toUtf8()
                   + '\n';
        }
    }
    return out;
}

QByteArray sampleLines(const HistorySeries &series, const std::vector<HistorySample> &samples,
                       bool json)
{
    QByteArray out;
    for (const HistorySample &s : samples) {
        const QString value = History::hasValue(s.quality)
                                  ? HistoryCsv::valueText(s.value, series.format)
                                  : QString();
        if (json) {
            QJsonObject o{{QStringLiteral("time"), HistoryCsv::localTime(s.timeMs)},
                          {QStringLiteral("timeMs"), s.timeMs},
                          {QStringLiteral("series"), series.key()},
                          {QStringLiteral("raw"), HistoryCsv::rawText(s.raw)},
                          {QStringLiteral("quality"), History::qualityName(s.quality)}};
            // A number that reads back exactly; none without a value.
            o.insert(QStringLiteral("value"), value.isEmpty() ? QJsonValue() : QJsonValue(s.value));
            out += QJsonDocument(o).toJson(QJsonDocument::Compact) + '\n';
        } else {
            out += QStringList{HistoryCsv::localTime(s.timeMs), series.key(),
                               value.isEmpty() ? QStringLiteral("-") : value,
                               History::qualityName(s.quality)}
                       .join(QLatin1String("  "))
                       .toUtf8()
                   + '\n';
        }
    }
    return out;
}

int run(const HistoryOptions &o)
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    qint64 from = 0;
    qint64 to = 0;
    for (const auto &[text, name, out] :
         {std::tuple{o.from, "from", &from}, std::tuple{o.to, "to", &to}}) {
        const std::optional<qint64> ms = CliAlarms::parseTime(text, now);
        if (!ms)
            return CliAlarms::badTime(name, text, o.json);
        *out = *ms;
    }
    if (to <= from)
        return CliOutput::usageError(
            QStringLiteral("--to (%1) must come after --from (%2).")
                .arg(HistoryCsv::localTime(to), HistoryCsv::localTime(from)),
            o.json);
    Result<std::unique_ptr<HistoryStore>> store
        = HistoryStore::open(o.store, HistoryStore::Mode::ReadOnly);
    if (!store) {
        const bool missing = store.error().message.id == MessageId(MsgId::HistoryMissing);
        return CliOutput::failure(store.error().message,
                                  missing ? ExitCode::Usage : ExitCode::Internal, o.json);
    }
    const Result<QList<HistorySeries>> all = (*store)->series();
    if (!all)
        return CliOutput::failure(all.error().message, ExitCode::Internal, o.json);
    QByteArray out;
    if (o.items.isEmpty()) {
        out = seriesLines(*all, o.json);
    } else {
        QList<HistorySeries> chosen;
        for (const QString &item : o.items) {
            HistorySeries s;
            if (const QString error = find(*all, item, &s); !error.isEmpty())
                return CliOutput::usageError(error, o.json);
            chosen.append(s);
        }
        if (o.csv)
            out = HistoryCsv::header();
        for (const HistorySeries &s : std::as_const(chosen)) {
            const Result<std::vector<HistorySample>> samples
                = (*store)->samples(s.id, from, to, o.limit);
            if (!samples)
                return CliOutput::failure(samples.error().message, ExitCode::Internal, o.json);
            // The sample before the range is what the line enters it with: not asked for here.
            std::vector<HistorySample> inRange;
            for (const HistorySample &sample : *samples) {
                if (sample.timeMs >= from)
                    inRange.push_back(sample);
            }
            out += o.csv ? HistoryCsv::rows(s, inRange) : sampleLines(s, inRange, o.json);
        }
    }
    bool closedPipe = false;
    if (const QString error = CliOutput::writeStdout(out, &closedPipe); !error.isEmpty())
        return closedPipe ? ExitCode::ClosedPipe : ExitCode::Internal;
    return ExitCode::Ok;
}

} // namespace

int runHistory(const QStringList &arguments)
{
    HistoryOptions o;
    if (const QString error = parse(arguments, &o); !error.isEmpty())
        return CliOutput::usageError(error, arguments.contains(QLatin1String("--json")));
    return run(o);
}

} // namespace Fatek
