// The polled side of a watch table: batches of item values from the link are queued and applied
// in time slices (at most one round per frame), and only the cells that really change are
// reported.
#include "watchvaluestate.h"

#include <algorithm>
#include <utility>

namespace Fatek {

WatchValueState::WatchValueState(SpecOf specOf, QObject *parent)
    : QObject(parent)
    , m_specOf(std::move(specOf))
{
    m_clock.start();
    m_flashTimer.setInterval(100);
    connect(&m_flashTimer, &QTimer::timeout, this, &WatchValueState::expireFlashes);
    // One timer for every row's age: a few repaints a second of the quality column only.
    m_ageTimer.setInterval(ageRefreshMs);
    connect(&m_ageTimer, &QTimer::timeout, this, &WatchValueState::refreshAges);
    m_sliceTimer.setSingleShot(true);
    connect(&m_sliceTimer, &QTimer::timeout, this, [this] {
        if (!m_inRound) {
            m_inRound = true;
            m_roundStart.start();
        }
        applySlice(qint64(sliceBudgetMs) * 1000000);
        if (m_queue.empty())
            m_inRound = false;
        else
            scheduleSlice();
    });
}

void WatchValueState::resetValue(RowValue &row)
{
    row.itemKey = WatchedItem::newKey();
    row.raw = 0;
    row.quality = ValueQuality::Stale;
    row.error = {};
    row.updated = {};
    row.received = false;
    row.batch = 0;
}

void WatchValueState::rebuildIndex()
{
    m_index.clear();
    for (int r = 0; r < m_rows.size(); ++r)
        m_index.insert(m_rows.at(r).itemKey, r);
}

void WatchValueState::insertRows(int row, int count)
{
    m_rows.insert(row, count, RowValue());
    for (int r = row; r < row + count; ++r)
        resetValue(m_rows[r]);
    rebuildIndex();
}

void WatchValueState::removeRows(int row, int count)
{
    m_rows.remove(row, count);
    rebuildIndex();
}

void WatchValueState::reorder(const QList<int> &order)
{
    QList<RowValue> rows;
    rows.reserve(m_rows.size());
    for (int i = 0; i < order.size(); ++i)
        rows.append(std::move(m_rows[order.at(i)]));
    m_rows = std::move(rows);
    rebuildIndex();
}

void WatchValueState::clear()
{
    m_queue.clear();
    m_sliceTimer.stop();
    m_inRound = false;
    m_rows.clear();
    m_index.clear();
}

void WatchValueState::resetRow(int row)
{
    resetValue(m_rows[row]);
    rebuildIndex();
}

qint64 WatchValueState::ageMs(int row) const
{
    const RowValue &r = m_rows.at(row);
    if (!r.received || !r.updated.isValid())
        return -1;
    return std::max<qint64>(0, QDateTime::currentMSecsSinceEpoch() - r.updated.toMSecsSinceEpoch());
}

bool WatchValueState::isFlashing(int row) const
{
    return m_rows.at(row).flashUntil > m_clock.elapsed();
}

void WatchValueState::setAgeRows(std::function<std::vector<int>()> rowsOnScreen)
{
    m_ageRows = std::move(rowsOnScreen);
}

void WatchValueState::refreshAges()
{
    if (m_rows.isEmpty()) {
        m_ageTimer.stop();
        return;
    }
    if (!m_ageRows) {
        std::vector<int> all(static_cast<std::size_t>(m_rows.size()));
        for (std::size_t r = 0; r < all.size(); ++r)
            all[r] = static_cast<int>(r);
        report(std::move(all), Cell::Quality, {Qt::DisplayRole});
        return;
    }
    std::vector<int> rows = m_ageRows();
    std::erase_if(rows, [this](int r) { return r < 0 || r >= m_rows.size(); });
    report(std::move(rows), Cell::Quality);
}

void WatchValueState::applyValues(const QList<WatchItemValue> &values)
{
    queueValues(values);
    flushValues();
}

void WatchValueState::queueValues(const QList<WatchItemValue> &values)
{
    if (values.isEmpty())
        return;
    m_queue.push_back({values, ++m_batchSequence, 0});
    scheduleSlice();
}

void WatchValueState::scheduleSlice()
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

void WatchValueState::flushValues()
{
    m_sliceTimer.stop();
    applySlice(-1);
    m_inRound = false;
}

void WatchValueState::applySlice(qint64 budgetNs)
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

void WatchValueState::applyOne(const WatchItemValue &v, quint64 batch)
{
    const auto it = m_index.constFind(v.key);
    if (it == m_index.cend())
        return;
    const int r = *it;
    RowValue &row = m_rows[r];
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
        if (m_specOf(r).name.isEmpty())
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

void WatchValueState::finishSlice()
{
    const qint64 now = m_clock.elapsed();
    bool flashed = false;
    for (int r : m_touchedRows) {
        RowValue &row = m_rows[r];
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
    report(std::exchange(m_valueRows, {}), Cell::Value);
    report(std::exchange(m_qualityRows, {}), Cell::Quality);
    report(std::exchange(m_updatedRows, {}), Cell::Updated);
    report(std::exchange(m_nameRows, {}), Cell::Name);
}

void WatchValueState::markAllStale(const Message &reason)
{
    // What was delivered before goes in first: it must not turn a row good again afterwards.
    flushValues();
    std::vector<int> touched;
    for (int r = 0; r < m_rows.size(); ++r) {
        RowValue &row = m_rows[r];
        // A refusal (R5000 on a PLC without it) stays true while nothing is read: the row
        // keeps its error and reason rather than turning "waiting".
        if (row.quality == ValueQuality::Error)
            continue;
        const bool changed = row.quality != ValueQuality::Stale || row.error != reason;
        row.quality = ValueQuality::Stale;
        row.error = reason;
        if (changed)
            touched.push_back(r);
    }
    report(touched, Cell::Value);
    report(std::move(touched), Cell::Quality);
}

void WatchValueState::expireFlashes()
{
    const qint64 now = m_clock.elapsed();
    std::vector<int> expired;
    bool pending = false;
    for (int r = 0; r < m_rows.size(); ++r) {
        RowValue &row = m_rows[r];
        if (row.flashUntil == 0)
            continue;
        if (row.flashUntil <= now) {
            row.flashUntil = 0;
            expired.push_back(r);
        } else {
            pending = true;
        }
    }
    if (!pending)
        m_flashTimer.stop();
    report(std::move(expired), Cell::Value);
}

void WatchValueState::setWriteOutcome(int row, const QString &text)
{
    m_rows[row].writeOutcome = text;
    report({row}, Cell::Value, {Qt::ToolTipRole});
}

void WatchValueState::setForcedFlags(quint8 station, const Address &start,
                                     const std::vector<std::uint32_t> &flags)
{
    std::vector<int> changed;
    for (int r = 0; r < m_rows.size(); ++r) {
        const WatchItemSpec &spec = m_specOf(r);
        const Address &a = spec.address;
        if (spec.station != station || a.type != start.type || a.number < start.number
            || a.number - start.number >= flags.size())
            continue;
        const bool forced = flags[a.number - start.number] != 0;
        if (m_rows[r].forced != forced) {
            m_rows[r].forced = forced;
            changed.push_back(r);
        }
    }
    report(std::move(changed), Cell::Value);
}

void WatchValueState::clearForced()
{
    std::vector<int> changed;
    for (int r = 0; r < m_rows.size(); ++r) {
        if (m_rows[r].forced) {
            m_rows[r].forced.reset();
            changed.push_back(r);
        }
    }
    report(std::move(changed), Cell::Value);
}

void WatchValueState::setSilentStations(const QList<quint8> &stations)
{
    if (stations == m_silentStations)
        return;
    // Rows of a station that fell silent or answers again change their quality text.
    std::vector<int> changed;
    for (int r = 0; r < m_rows.size(); ++r) {
        const quint8 s = m_specOf(r).station;
        if (stations.contains(s) != m_silentStations.contains(s))
            changed.push_back(r);
    }
    m_silentStations = stations;
    report(std::move(changed), Cell::Quality);
}

void WatchValueState::report(std::vector<int> rows, Cell cell, const QList<int> &roles)
{
    if (!rows.empty())
        Q_EMIT cellsChanged(rows, cell, roles);
}

} // namespace Fatek
