// WatchTableModel, the polled side: batches of values from the session are queued and applied in
// time slices (at most one round per frame), and only the cells that really change are reported.
#include "watchtablemodel.h"

#include <algorithm>
#include <utility>

namespace Fatek {

QList<WatchEntry> WatchTableModel::pollEntries(int intervalMs) const
{
    QList<WatchEntry> entries;
    for (const Row &row : m_rows)
        entries += row.values.pollEntries(intervalMs);
    return entries;
}

void WatchTableModel::applyValues(const QList<WatchValue> &values)
{
    queueValues(values);
    flushValues();
}

void WatchTableModel::queueValues(const QList<WatchValue> &values)
{
    if (values.isEmpty())
        return;
    m_queue.push_back({values, ++m_batchSequence, 0});
    scheduleSlice();
}

void WatchTableModel::scheduleSlice()
{
    if (m_queue.empty() || m_sliceTimer.isActive())
        return;
    if (m_inRound) {
        m_sliceTimer.start(0); // the round goes on once the event loop has had its turn
        return;
    }
    // A new round starts at most once per frame: batches that come faster wait and coalesce.
    const qint64 sinceRound = m_roundStart.isValid() ? m_roundStart.elapsed() : frameMs;
    m_sliceTimer.start(static_cast<int>(std::clamp<qint64>(frameMs - sinceRound, 0, frameMs)));
}

void WatchTableModel::flushValues()
{
    m_sliceTimer.stop();
    applySlice(-1);
    m_inRound = false;
}

void WatchTableModel::applySlice(qint64 budgetNs)
{
    QElapsedTimer clock;
    clock.start();
    ++m_slice;
    int sinceCheck = 0;
    bool outOfTime = false;
    // Newest batch first: an element it sets is skipped in the older ones, so that a burst of
    // batches costs one apply per element, and an element only older batches carry still gets
    // its newest value.
    while (!m_queue.empty() && !outOfTime) {
        Batch &batch = m_queue.back();
        const WatchValue *values = std::as_const(batch.values).constData();
        const qsizetype count = batch.values.size();
        while (batch.next < count) {
            applyOne(values[batch.next++], batch.sequence);
            if (budgetNs >= 0 && ++sinceCheck == 64) {
                sinceCheck = 0;
                if (clock.nsecsElapsed() >= budgetNs) {
                    outOfTime = true;
                    break;
                }
            }
        }
        if (batch.next >= count)
            m_queue.pop_back();
    }
    finishSlice();
}

void WatchTableModel::applyOne(const WatchValue &v, quint64 batch)
{
    const auto it = m_index.constFind(v.itemId);
    if (it == m_index.cend())
        return;
    const int r = it->first;
    Row &row = m_rows[r];
    Part &part = row.parts[static_cast<std::size_t>(it->second)];
    // The quality comes from the newest batch that has the element, the value and its time from
    // the newest one that read it (a newer "stale" keeps an older good value, as in order).
    const bool good = v.quality == ValueQuality::Good;
    const bool newerQuality = batch >= part.qualityBatch;
    const bool newerValue = good && batch >= part.valueBatch;
    if (!newerQuality && !newerValue)
        return; // newer batches have set it
    if (row.slice != m_slice) {
        row.slice = m_slice;
        row.hadValue = row.complete;
        row.before = row.complete ? combine(row) : 0;
        m_touchedRows.push_back(r);
    }
    // Only the cells that really change are reported: an open editor (name, format, a value being
    // typed) must not be disturbed, and unchanged cells need no repaint.
    const bool qualityChanged
        = newerQuality && (part.quality != v.quality || part.error != v.error);
    const bool valueChanged = newerValue && (!part.received || part.value != v.value);
    const bool updatedChanged = newerValue && part.timestamp != v.timestamp;
    if (qualityChanged || (newerValue && !part.received))
        m_qualityRows.push_back(r); // "waiting" becomes a quality with the first value
    if (qualityChanged || valueChanged)
        m_valueRows.push_back(r); // the value's font, colour and tooltip follow the quality
    if (updatedChanged)
        m_updatedRows.push_back(r);
    if (newerQuality) {
        part.qualityBatch = batch;
        if (qualityChanged) {
            part.quality = v.quality;
            part.error = v.error;
        }
    }
    if (newerValue) {
        part.valueBatch = batch;
        part.value = v.value;
        part.timestamp = v.timestamp;
        if (!part.received) {
            part.received = true;
            row.complete = std::all_of(row.parts.cbegin(), row.parts.cend(),
                                       [](const Part &p) { return p.received; });
        }
    }
}

void WatchTableModel::finishSlice()
{
    const qint64 now = m_clock.elapsed();
    bool flashed = false;
    for (int r : m_touchedRows) {
        Row &row = m_rows[r];
        if (row.complete && (!row.hadValue || combine(row) != row.before)) {
            row.flashUntil = now + flashMs;
            flashed = true;
        }
    }
    m_touchedRows.clear();
    if (flashed && !m_flashTimer.isActive())
        m_flashTimer.start();
    emitRowsChanged(std::exchange(m_valueRows, {}), ValueColumn, ValueColumn);
    emitRowsChanged(std::exchange(m_qualityRows, {}), QualityColumn, QualityColumn);
    emitRowsChanged(std::exchange(m_updatedRows, {}), UpdatedColumn, UpdatedColumn);
}

void WatchTableModel::markAllStale(const Message &reason)
{
    // What was delivered before goes in first: it must not turn a row good again afterwards.
    flushValues();
    std::vector<int> touched;
    for (int r = 0; r < m_rows.size(); ++r) {
        bool changed = false;
        for (Part &p : m_rows[r].parts) {
            changed = changed || p.quality != ValueQuality::Stale || p.error != reason;
            p.quality = ValueQuality::Stale;
            p.error = reason;
        }
        if (changed)
            touched.push_back(r);
    }
    emitRowsChanged(touched, ValueColumn, ValueColumn);
    emitRowsChanged(std::move(touched), QualityColumn, QualityColumn);
}

} // namespace Fatek
