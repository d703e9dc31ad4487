// WatchTableModel, the polled side: batches of item values from the link are queued and applied
// in time slices (at most one round per frame), and only the cells that really change are
// reported.
#include "watchtablemodel.h"

#include <algorithm>
#include <utility>

namespace Fatek {

QList<WatchedItem> WatchTableModel::watchItems(int intervalMs) const
{
    QList<WatchedItem> items;
    items.reserve(m_rows.size());
    for (const Row &row : m_rows)
        items.append({row.itemKey, row.spec(), intervalMs});
    return items;
}

void WatchTableModel::applyValues(const QList<WatchItemValue> &values)
{
    queueValues(values);
    flushValues();
}

void WatchTableModel::queueValues(const QList<WatchItemValue> &values)
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
    // Newest batch first: an item it sets is skipped in the older ones, so that a burst of
    // batches costs one apply per item, and an item only older batches carry still gets its
    // newest value.
    while (!m_queue.empty() && !outOfTime) {
        Batch &batch = m_queue.back();
        const WatchItemValue *values = std::as_const(batch.values).constData();
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

void WatchTableModel::applyOne(const WatchItemValue &v, quint64 batch)
{
    const auto it = m_index.constFind(v.key);
    if (it == m_index.cend())
        return;
    const int r = *it;
    Row &row = m_rows[r];
    if (batch < row.batch)
        return; // a newer batch has set it
    if (row.slice != m_slice) {
        row.slice = m_slice;
        row.hadValue = row.received;
        row.before = row.raw;
        m_touchedRows.push_back(r);
    }
    // Only the cells that really change are reported: an open editor (name, format, a value being
    // typed) must not be disturbed, and unchanged cells need no repaint. An item value carries
    // its elements' last read words whatever its quality (a stale one keeps the good value).
    const bool qualityChanged = row.quality != v.quality || row.error != v.error;
    const bool valueChanged = v.hasValue && (!row.received || row.raw != v.raw);
    const bool updatedChanged = v.hasValue && row.updated != v.time;
    if (qualityChanged || (v.hasValue && !row.received))
        m_qualityRows.push_back(r); // "waiting" becomes a quality with the first value
    if (qualityChanged || valueChanged)
        m_valueRows.push_back(r); // the value's font, colour and tooltip follow the quality
    if (updatedChanged)
        m_updatedRows.push_back(r);
    if (row.peerName != v.name) {
        row.peerName = v.name;
        if (row.spec().name.isEmpty())
            m_nameRows.push_back(r);
    }
    row.batch = batch;
    row.quality = v.quality;
    row.error = v.error;
    if (v.hasValue) {
        row.raw = v.raw;
        row.updated = v.time;
        row.received = true;
    }
}

void WatchTableModel::finishSlice()
{
    const qint64 now = m_clock.elapsed();
    bool flashed = false;
    for (int r : m_touchedRows) {
        Row &row = m_rows[r];
        if (row.received && (!row.hadValue || row.raw != row.before)) {
            row.flashUntil = now + flashMs;
            flashed = true;
        }
    }
    m_touchedRows.clear();
    if (flashed && !m_flashTimer.isActive())
        m_flashTimer.start();
    // Values have come: their ages grow from now on.
    if (!m_updatedRows.empty() && !m_ageTimer.isActive())
        m_ageTimer.start();
    emitRowsChanged(std::exchange(m_valueRows, {}), ValueColumn, ValueColumn);
    emitRowsChanged(std::exchange(m_qualityRows, {}), QualityColumn, QualityColumn);
    emitRowsChanged(std::exchange(m_updatedRows, {}), UpdatedColumn, UpdatedColumn);
    emitRowsChanged(std::exchange(m_nameRows, {}), NameColumn, NameColumn);
}

void WatchTableModel::markAllStale(const Message &reason)
{
    // What was delivered before goes in first: it must not turn a row good again afterwards.
    flushValues();
    std::vector<int> touched;
    for (int r = 0; r < m_rows.size(); ++r) {
        Row &row = m_rows[r];
        const bool changed = row.quality != ValueQuality::Stale || row.error != reason;
        row.quality = ValueQuality::Stale;
        row.error = reason;
        if (changed)
            touched.push_back(r);
    }
    emitRowsChanged(touched, ValueColumn, ValueColumn);
    emitRowsChanged(std::move(touched), QualityColumn, QualityColumn);
}

} // namespace Fatek
