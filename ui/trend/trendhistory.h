#pragma once

#include "core/history/historytypes.h"
#include "core/protocol/result.h"
#include "core/watch/csvfile.h"
#include "trendvalueaxes.h"

#include <QList>
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>
#include <vector>

class QChart;
class QDateTimeAxis;
class QLineSeries;
class QWidget;

namespace Fatek {

class HistoryCenter;
struct TrendLine;

// The recorded past of the trend's lines (issue 51): where the visible range reaches before what
// a line's live buffer holds, its older part is asked of the history store (HistoryWriter::
// queryPoints, one bucket per pixel column: min/max per column, so a week of 1 s values draws at
// once), debounced while the user scrolls, and drawn in the line's colour up to the live buffer's
// first sample, where it joins the live line. Gaps (no value, nothing recorded) stay gaps. Answers
// for a range no longer wanted are dropped (a generation per request); the UI never waits for the
// store. A line the store does not record shows nothing there, without a message. Also exports
// the recorded samples of a range to CSV.
class TrendHistory : public QObject
{
    Q_OBJECT

public:
    // How long the user may keep scrolling before the store is asked.
    static constexpr int DebounceMs = 150;

    TrendHistory(QChart *chart, QDateTimeAxis *timeAxis, QObject *parent = nullptr);
    ~TrendHistory() override;

    // Where the series are read (nullptr: nowhere; the trend shows its live buffers only).
    void setCenter(HistoryCenter *center);
    HistoryCenter *center() const;
    // The series a line is recorded as ("Line 1/1-R1"); empty without a center or connection.
    QString seriesKey(const TrendLine &line) const;

    // Draws the recorded part of `line` in [fromMs, toMs] (`pixels` columns wide) as `name` and
    // widens `span` by its values inside the range; asks the store for what it lacks.
    void draw(TrendLine &line, const QString &name, qint64 fromMs, qint64 toMs, int pixels,
              TrendValueAxes::Span &span);
    // The line leaves the trend: its pieces leave the chart.
    void remove(const TrendLine *line);
    // The recorded pieces drawn for a line (one per stretch without a gap).
    QList<QLineSeries *> series(const TrendLine *line) const;
    // The drawn recorded value of a line at a time (NaN in a gap): false when the recorded part
    // does not reach that time (the live buffer has it, or nothing does).
    bool valueAt(const TrendLine *line, qint64 timeMs, double *value) const;
    // Whether no request is waiting or under way (tests wait for it).
    bool isIdle() const;

    // Writes the samples of `series` (by key; the format says how a value is written) with
    // fromMs <= time < toMs to `path` in time order (HistoryCsv: time in local ISO 8601 with its
    // offset, series, value, raw in hex, quality), atomically; exportFinished says how it went.
    // Series the store does not have are left out.
    // The file starts with the byte order mark, its lines end as `lineEnd` (CsvFile).
    void exportRange(const QList<HistorySeries> &series, qint64 fromMs, qint64 toMs,
                     const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    // The same for the series of `lines` (those with a connection), each once.
    void exportRange(const std::vector<std::unique_ptr<TrendLine>> &lines, qint64 fromMs,
                     qint64 toMs, const QString &path,
                     CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    // Asks where to export (a file dialog); empty when cancelled. `lineEnd` gets the line ends of
    // the file type chosen (CSV, or CSV with Windows line ends).
    static QString askExportPath(QWidget *parent, CsvFile::LineEnd *lineEnd);

Q_SIGNALS:
    // Points arrived from the store: draw again.
    void pointsArrived();
    // `error` empty: `rows` samples written to `path`.
    void exportFinished(const QString &path, int rows, const QString &error);
    void statusMessage(const QString &text);

private:
    struct Range
    {
        qint64 fromMs = 0;
        qint64 toMs = 0;
        int buckets = 0;
        double msPerBucket() const { return double(toMs - fromMs) / std::max(buckets, 1); }
    };
    struct State
    {
        QString key;
        std::optional<Range> held; // what `points` cover
        std::optional<Range> wanted;
        std::optional<Range> asked;
        quint64 generation = 0; // of the request under way
        std::vector<HistoryPoint> points;
        quint64 version = 0; // of `points`
        std::vector<QLineSeries *> series;
        // What the pieces show now: redrawn only when it changes.
        quint64 drawnVersion = 0;
        qint64 drawnEndMs = -1;
        QPointF drawnJoin;
    };

    void send();
    void answered(const TrendLine *line, quint64 generation,
                  const Result<std::vector<HistoryPoint>> &points);
    void clearPieces(State &state);
    void drawPieces(State &state, const TrendLine &line, const QString &name, qint64 endMs,
                    std::optional<QPointF> join);

    QChart *m_chart;
    QDateTimeAxis *m_timeAxis;
    QPointer<HistoryCenter> m_center;
    std::map<const TrendLine *, State> m_states;
    QTimer m_debounce;
    quint64 m_generation = 0;
    QString m_lastError; // said once, not per scroll
};

} // namespace Fatek
