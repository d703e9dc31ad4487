#include "trendhistory.h"

#include "trendtimeticks.h"

#include "core/history/historycsv.h"
#include "core/history/historymessages.h"
#include "core/history/historyreducer.h"
#include "core/history/historywriter.h"
#include "core/watch/safefile.h"
#include "core/watch/valueformat.h"
#include "trendline.h"
#include "ui/common/csvfilefilter.h"
#include "ui/common/lastdirectory.h"
#include "ui/common/uitext.h"
#include "ui/history/historycenter.h"
#include "ui/watch/watchtablemodel.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QPen>
#include <QtCharts/QChart>
#include <QtCharts/QDateTimeAxis>
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <limits>
#include <memory>

namespace Fatek {

namespace {

// More columns than a screen has are not worth the store's time.
constexpr int maxBuckets = 8000;

bool unknownSeries(const ProtocolError &error)
{
    return error.message.id == MsgId::HistoryUnknownSeries;
}

} // namespace

TrendHistory::TrendHistory(QChart *chart, QDateTimeAxis *timeAxis, QObject *parent)
    : QObject(parent)
    , m_chart(chart)
    , m_timeAxis(timeAxis)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(DebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &TrendHistory::send);
    connect(this, &TrendHistory::exportFinished, this,
            [this](const QString &path, int rows, const QString &error) {
                Q_EMIT statusMessage(error.isEmpty()
                                         ? tr("%n value(s) exported to %1.", nullptr, rows)
                                               .arg(QDir::toNativeSeparators(path))
                                         : error);
            });
}

TrendHistory::~TrendHistory() = default;

void TrendHistory::setCenter(HistoryCenter *center)
{
    m_center = center;
    for (auto &[line, state] : m_states) {
        clearPieces(state);
        state = State{};
    }
}

HistoryCenter *TrendHistory::center() const
{
    return m_center.data();
}

QString TrendHistory::seriesKey(const TrendLine &line) const
{
    return m_center && line.model ? m_center->seriesKey(line.model, line.spec) : QString();
}

bool TrendHistory::isIdle() const
{
    if (m_debounce.isActive())
        return false;
    return std::none_of(m_states.cbegin(), m_states.cend(), [](const auto &entry) {
        return entry.second.wanted || entry.second.asked;
    });
}

void TrendHistory::draw(TrendLine &line, const QString &name, qint64 fromMs, qint64 toMs,
                        int pixels, TrendValueAxes::Span &span)
{
    State &state = m_states[&line];
    const TrendBuffer &live = line.buffer;
    // The recorded part ends where the live buffer begins: the live line is the newer one.
    const qint64 endMs = live.isEmpty() ? toMs : std::min(toMs, live.at(0).timeMs);
    const QString key = endMs > fromMs ? seriesKey(line) : QString();
    if (key.isEmpty()) {
        clearPieces(state);
        return;
    }
    if (key != state.key) {
        clearPieces(state);
        std::vector<QLineSeries *> pieces = std::move(state.series);
        state = State{};
        state.series = std::move(pieces);
        state.key = key;
    }
    const double pixelMs = double(toMs - fromMs) / std::max(pixels, 1);
    const auto covers = [&](const std::optional<Range> &r) {
        return r && r->fromMs <= fromMs && double(r->toMs) + pixelMs >= double(endMs)
               && r->msPerBucket() <= 2 * pixelMs;
    };
    if (!covers(state.held) && !covers(state.asked) && !covers(state.wanted)) {
        // Half a range more to the left: scrolling back a little needs no new request.
        Range want;
        want.fromMs = fromMs - (toMs - fromMs) / 2;
        want.toMs = endMs;
        want.buckets = static_cast<int>(
            std::clamp<double>(double(want.toMs - want.fromMs) / pixelMs, 1, maxBuckets));
        state.wanted = want;
        m_debounce.start(); // again: the user is still scrolling
    }

    std::optional<QPointF> join;
    if (!live.isEmpty() && !live.at(0).gap && endMs == live.at(0).timeMs && !state.points.empty()) {
        const HistoryPoint &last = state.points.back();
        const int heartbeatS
            = line.spec.history ? line.spec.history->heartbeatS : History::DefaultHeartbeatS;
        // A silence longer than the heartbeat allows is a gap (the studio was not running).
        if (!last.gap && last.timeMs < endMs
            && endMs - last.timeMs <= History::maxSilenceMs(heartbeatS))
            join = QPointF(double(endMs), live.at(0).value);
    }
    drawPieces(state, line, name, endMs, join);
    for (const HistoryPoint &p : state.points) {
        if (p.gap || p.timeMs < fromMs || p.timeMs > endMs)
            continue;
        span.min = std::min(span.min, p.value);
        span.max = std::max(span.max, p.value);
    }
}

void TrendHistory::drawPieces(State &state, const TrendLine &line, const QString &name,
                              qint64 endMs, std::optional<QPointF> join)
{
    const QPointF joinPoint = join.value_or(QPointF(-1, 0));
    const bool same = state.drawnVersion == state.version && state.drawnEndMs == endMs
                      && state.drawnJoin == joinPoint;
    if (same) {
        // The axes may have been made anew (rebuildAxes): the pieces follow the line's.
        for (QLineSeries *s : state.series) {
            if (!s->attachedAxes().contains(line.axis))
                s->attachAxis(line.axis);
        }
        return;
    }
    state.drawnVersion = state.version;
    state.drawnEndMs = endMs;
    state.drawnJoin = joinPoint;
    QList<QList<QPointF>> pieces;
    QList<QPointF> piece;
    for (const HistoryPoint &p : state.points) {
        if (p.timeMs >= endMs)
            break;
        if (p.gap) {
            if (!piece.isEmpty())
                pieces.append(piece);
            piece.clear();
            continue;
        }
        piece.append(QPointF(double(p.timeMs), p.value));
    }
    if (join && !piece.isEmpty())
        piece.append(*join);
    if (!piece.isEmpty())
        pieces.append(piece);

    while (state.series.size() < static_cast<std::size_t>(pieces.size())) {
        auto *s = new QLineSeries;
        QPen pen(line.color);
        pen.setWidthF(1.8);
        s->setPen(pen);
        m_chart->addSeries(s);
        s->attachAxis(m_timeAxis);
        TrendTimeTicks::attach(m_chart, s);
        // The live line's legend entry names the item.
        for (QLegendMarker *m : m_chart->legend()->markers(s))
            m->setVisible(false);
        state.series.push_back(s);
    }
    for (std::size_t i = 0; i < state.series.size(); ++i) {
        QLineSeries *s = state.series[i];
        s->setName(name);
        if (!s->attachedAxes().contains(line.axis))
            s->attachAxis(line.axis);
        if (i < static_cast<std::size_t>(pieces.size()))
            s->replace(pieces.at(static_cast<qsizetype>(i)));
        else if (s->count() > 0)
            s->clear();
    }
}

void TrendHistory::clearPieces(State &state)
{
    for (QLineSeries *s : state.series) {
        if (s->count() > 0)
            s->clear();
    }
    state.drawnVersion = ~quint64(0);
    state.drawnEndMs = -1;
}

void TrendHistory::remove(const TrendLine *line)
{
    const auto it = m_states.find(line);
    if (it == m_states.end())
        return;
    for (QLineSeries *s : it->second.series) {
        m_chart->removeSeries(s);
        delete s;
    }
    m_states.erase(it);
}

QList<QLineSeries *> TrendHistory::series(const TrendLine *line) const
{
    QList<QLineSeries *> list;
    const auto it = m_states.find(line);
    if (it == m_states.end())
        return list;
    for (QLineSeries *s : it->second.series) {
        if (s->count() > 0)
            list.append(s);
    }
    return list;
}

bool TrendHistory::valueAt(const TrendLine *line, qint64 timeMs, double *value) const
{
    const auto it = m_states.find(line);
    if (it == m_states.end())
        return false;
    const std::vector<HistoryPoint> &points = it->second.points;
    if (points.empty() || timeMs < points.front().timeMs || timeMs >= it->second.drawnEndMs)
        return false;
    // The last point at or before the time, as the live read-out takes the last sample.
    const auto after
        = std::upper_bound(points.cbegin(), points.cend(), timeMs,
                           [](qint64 t, const HistoryPoint &p) { return t < p.timeMs; });
    const HistoryPoint &p = *(after - 1);
    *value = p.gap ? std::numeric_limits<double>::quiet_NaN() : p.value;
    return true;
}

void TrendHistory::send()
{
    HistoryWriter *writer = m_center ? m_center->readableWriter() : nullptr;
    for (auto &[line, state] : m_states) {
        if (!state.wanted)
            continue;
        const Range range = *state.wanted;
        state.wanted.reset();
        if (!writer) {
            // Nothing was ever recorded: nothing to show, and nothing to ask again.
            state.held = range;
            state.points.clear();
            ++state.version;
            continue;
        }
        state.asked = range;
        state.generation = ++m_generation;
        writer->queryPoints(state.key, range.fromMs, range.toMs, range.buckets, this,
                            [this, line = line, generation = state.generation](
                                const Result<std::vector<HistoryPoint>> &points) {
                                answered(line, generation, points);
                            });
    }
}

void TrendHistory::answered(const TrendLine *line, quint64 generation,
                            const Result<std::vector<HistoryPoint>> &points)
{
    const auto it = m_states.find(line);
    // A late answer for a range no longer wanted, or for a line that left.
    if (it == m_states.end() || it->second.generation != generation || !it->second.asked)
        return;
    State &state = it->second;
    state.held = state.asked;
    state.asked.reset();
    state.points.clear();
    if (points) {
        state.points = *points;
    } else if (!unknownSeries(points.error())) {
        // A store that cannot be read is said once, not at every scroll.
        const QString text = tr("History: %1").arg(translated(points.error().message));
        if (text != m_lastError)
            Q_EMIT statusMessage(text);
        m_lastError = text;
    }
    ++state.version;
    Q_EMIT pointsArrived();
}

void TrendHistory::exportRange(const std::vector<std::unique_ptr<TrendLine>> &lines, qint64 fromMs,
                               qint64 toMs, const QString &path, CsvFile::LineEnd lineEnd)
{
    QList<HistorySeries> series;
    QStringList keys;
    for (const auto &line : lines) {
        const QString key = seriesKey(*line);
        if (key.isEmpty() || keys.contains(key))
            continue;
        keys.append(key);
        HistorySeries s;
        s.source = key.section(QLatin1Char('/'), 0, -2);
        s.item = key.section(QLatin1Char('/'), -1);
        s.format = ValueFormat::name(line->spec.format);
        series.append(s);
    }
    exportRange(series, fromMs, toMs, path, lineEnd);
}

QString TrendHistory::askExportPath(QWidget *parent, CsvFile::LineEnd *lineEnd)
{
    QString filter;
    QString path = QFileDialog::getSaveFileName(parent, tr("Export Range to CSV"), lastDirectory(),
                                                CsvFileFilter::both(), &filter);
    *lineEnd = CsvFileFilter::lineEnd(filter);
    if (path.isEmpty())
        return path;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".csv");
    setLastDirectory(path);
    return path;
}

void TrendHistory::exportRange(const QList<HistorySeries> &series, qint64 fromMs, qint64 toMs,
                               const QString &path, CsvFile::LineEnd lineEnd)
{
    HistoryWriter *writer = m_center ? m_center->readableWriter() : nullptr;
    if (series.isEmpty() || !writer) {
        Q_EMIT exportFinished(path, 0, tr("None of the trend's items is recorded in the history."));
        return;
    }
    struct Job
    {
        QList<HistorySeries> series;
        std::vector<std::vector<HistorySample>> samples;
        std::vector<bool> found;
        qsizetype waiting = 0;
        QString error;
    };
    auto job = std::make_shared<Job>();
    job->series = series;
    job->samples.resize(static_cast<std::size_t>(series.size()));
    job->found.resize(static_cast<std::size_t>(series.size()), false);
    job->waiting = series.size();
    const auto finish = [this, job, path, fromMs, toMs, lineEnd] {
        if (job->error.isEmpty()
            && std::none_of(job->found.cbegin(), job->found.cend(), [](bool f) { return f; }))
            job->error = tr("None of the trend's items is recorded in the history.");
        if (!job->error.isEmpty()) {
            Q_EMIT exportFinished(path, 0, job->error);
            return;
        }
        // One series after the other would be HistoryCsv::rows; the trend's items side by side
        // read better in time order.
        struct Row
        {
            qint64 timeMs;
            std::size_t series;
            const HistorySample *sample;
        };
        std::vector<Row> rows;
        for (std::size_t i = 0; i < job->samples.size(); ++i) {
            for (const HistorySample &s : job->samples[i]) {
                // The store adds the sample before the range (the value the line enters with).
                if (s.timeMs >= fromMs && s.timeMs < toMs)
                    rows.push_back({s.timeMs, i, &s});
            }
        }
        std::stable_sort(rows.begin(), rows.end(),
                         [](const Row &a, const Row &b) { return a.timeMs < b.timeMs; });
        QByteArray text = HistoryCsv::header();
        for (const Row &row : rows) {
            text += HistoryCsv::rows(job->series.at(static_cast<qsizetype>(row.series)),
                                     {*row.sample});
        }
        const QString error
            = SafeFile::write(path, CsvFile::bytes(QString::fromUtf8(text), lineEnd));
        Q_EMIT exportFinished(
            path, error.isEmpty() ? static_cast<int>(rows.size()) : 0,
            error.isEmpty() ? QString()
                            : tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), error));
    };
    for (qsizetype i = 0; i < series.size(); ++i) {
        writer->querySamples(series.at(i).key(), fromMs, toMs, this,
                             [job, i, finish](const Result<std::vector<HistorySample>> &samples) {
                                 const auto n = static_cast<std::size_t>(i);
                                 if (samples) {
                                     job->samples[n] = *samples;
                                     job->found[n] = true;
                                 } else if (!unknownSeries(samples.error())
                                            && job->error.isEmpty()) {
                                     job->error = translated(samples.error().message);
                                 }
                                 if (--job->waiting == 0)
                                     finish();
                             });
    }
}

} // namespace Fatek
