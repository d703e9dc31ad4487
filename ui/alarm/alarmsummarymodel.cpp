#include "alarmsummarymodel.h"

#include "alarmtext.h"

#include <QGuiApplication>
#include <QPalette>

#include <algorithm>

namespace Fatek {

namespace {

// Dark text on the light priority colours, light text on the dark ones.
QColor textOn(const QColor &background)
{
    return background.lightnessF() > 0.55 ? QColor(Qt::black) : QColor(Qt::white);
}

} // namespace

AlarmSummaryModel::AlarmSummaryModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(0);
    connect(&m_flushTimer, &QTimer::timeout, this, &AlarmSummaryModel::flush);
    m_flashTimer.setInterval(flashMs);
    connect(&m_flashTimer, &QTimer::timeout, this, &AlarmSummaryModel::flash);
}

int AlarmSummaryModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int AlarmSummaryModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString AlarmSummaryModel::keyOf(const QString &connection, const QString &alarmId)
{
    return connection + QChar(0) + alarmId;
}

int AlarmSummaryModel::rowOf(const QString &connection, const QString &alarmId) const
{
    return m_rowOf.value(keyOf(connection, alarmId), -1);
}

QVariant AlarmSummaryModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const AlarmStatus &a = m_rows.at(index.row());
    const bool unacked = Alarms::isUnacked(a.state);
    const qint64 time = a.raisedMs > 0 ? a.raisedMs : a.sinceMs;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case StateColumn: {
            QString text = AlarmText::state(a.state);
            if (a.state == AlarmState::Shelved)
                text = tr("shelved until %1").arg(AlarmText::time(a.shelvedUntilMs));
            return a.chattering ? tr("%1, chattering").arg(text) : text;
        }
        case PriorityColumn: return AlarmText::priority(a.definition.priority);
        case TimeColumn: return AlarmText::time(time);
        case ConnectionColumn: return a.connection;
        case ItemColumn: return a.itemName;
        case MessageColumn: return a.message;
        case ValueColumn: return a.value;
        case GroupColumn: return a.definition.group;
        default: return {};
        }
    case SortRole:
        switch (index.column()) {
        case StateColumn: return static_cast<int>(a.state);
        case PriorityColumn: return static_cast<int>(a.definition.priority);
        case TimeColumn: return time;
        default: return data(index, Qt::DisplayRole);
        }
    case StateRole: return static_cast<int>(a.state);
    case PriorityRole: return static_cast<int>(a.definition.priority);
    case GroupRole: return a.definition.group;
    case FlashRole: return unacked && m_flashOn;
    case ConnectionRole: return a.connection;
    case AlarmIdRole: return a.alarmId;
    case Qt::BackgroundRole: {
        const QColor colour = AlarmText::priorityColor(a.definition.priority);
        if (index.column() == PriorityColumn || (unacked && m_flashOn))
            return colour;
        return {};
    }
    case Qt::ForegroundRole: {
        const QColor colour = AlarmText::priorityColor(a.definition.priority);
        if (index.column() == PriorityColumn || (unacked && m_flashOn))
            return textOn(colour);
        // Out of service and shelved alarms need no action: greyed.
        if (a.state == AlarmState::Shelved || a.state == AlarmState::OutOfService)
            return QGuiApplication::palette().brush(QPalette::PlaceholderText);
        return {};
    }
    case Qt::ToolTipRole: {
        QStringList lines{tr("%1 (%2, station %3)").arg(a.alarmId, a.address).arg(a.station)};
        if (a.chattering)
            lines << tr("Chattering: raised %1 times or more within a minute.")
                         .arg(Alarms::ChatterCount);
        if (!a.lastUser.isEmpty())
            lines << (a.lastComment.isEmpty()
                          ? tr("Last action by %1").arg(a.lastUser)
                          : tr("Last action by %1: %2").arg(a.lastUser, a.lastComment));
        return lines.join(QLatin1Char('\n'));
    }
    default: return {};
    }
}

QVariant AlarmSummaryModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case StateColumn: return tr("State");
    case PriorityColumn: return tr("Priority");
    case TimeColumn: return tr("Time");
    case ConnectionColumn: return tr("Connection");
    case ItemColumn: return tr("Item");
    case MessageColumn: return tr("Message");
    case ValueColumn: return tr("Value");
    case GroupColumn: return tr("Group");
    default: return {};
    }
}

void AlarmSummaryModel::queue(const AlarmStatus &status)
{
    const QString key = keyOf(status.connection, status.alarmId);
    if (const auto it = m_pendingIndex.constFind(key); it != m_pendingIndex.cend()) {
        m_pending[*it] = status;
    } else {
        m_pendingIndex.insert(key, static_cast<int>(m_pending.size()));
        m_pending.append(status);
    }
    m_flushTimer.start();
}

void AlarmSummaryModel::updateAlarm(const AlarmStatus &status)
{
    queue(status);
}

void AlarmSummaryModel::setAlarms(const QString &connection, const QList<AlarmStatus> &alarms)
{
    // The rows of the connection that are not among them go: queued as normal.
    QSet<QString> keep;
    for (const AlarmStatus &a : alarms) {
        keep.insert(a.alarmId);
        queue(a);
    }
    for (const AlarmStatus &row : std::as_const(m_rows)) {
        if (row.connection == connection && !keep.contains(row.alarmId)) {
            AlarmStatus gone = row;
            gone.state = AlarmState::Normal;
            queue(gone);
        }
    }
    for (AlarmStatus &pending : m_pending) {
        if (pending.connection == connection && !keep.contains(pending.alarmId))
            pending.state = AlarmState::Normal;
    }
}

void AlarmSummaryModel::flush()
{
    m_flushTimer.stop();
    if (m_pending.isEmpty())
        return;
    std::vector<int> changed;
    std::vector<int> valueChanged;
    std::vector<int> removed;
    QList<AlarmStatus> added;
    for (const AlarmStatus &pending : std::as_const(m_pending)) {
        const int row = m_rowOf.value(keyOf(pending.connection, pending.alarmId), -1);
        const bool listed = Alarms::isListed(pending.state);
        if (row >= 0 && listed) {
            AlarmStatus &shown = m_rows[row];
            const bool same
                = shown.state == pending.state && shown.sinceMs == pending.sinceMs
                  && shown.chattering == pending.chattering
                  && shown.shelvedUntilMs == pending.shelvedUntilMs
                  && shown.message == pending.message && shown.definition == pending.definition
                  && shown.lastUser == pending.lastUser && shown.lastComment == pending.lastComment;
            if (same && shown.value == pending.value)
                continue; // a refresh that changes nothing reports nothing
            // Only the value: one column, so that the sort and the filters stay as they are
            // (a new value moves no row: it is neither a sort key nor a filter's).
            (same ? valueChanged : changed).push_back(row);
            shown = pending;
        } else if (row >= 0) {
            removed.push_back(row);
        } else if (listed) {
            added.append(pending);
        }
    }
    m_pending.clear();
    m_pendingIndex.clear();
    emitRuns(std::move(changed), 0, ColumnCount - 1, {});
    emitRuns(std::move(valueChanged), ValueColumn, ValueColumn, {Qt::DisplayRole, SortRole});
    // From the bottom up, one step per run of consecutive rows: the rows above keep their place.
    std::sort(removed.begin(), removed.end());
    for (auto end = removed.size(); end > 0;) {
        auto begin = end - 1;
        while (begin > 0 && removed[begin - 1] + 1 == removed[begin])
            --begin;
        beginRemoveRows({}, removed[begin], removed[end - 1]);
        m_rows.remove(removed[begin], removed[end - 1] - removed[begin] + 1);
        endRemoveRows();
        end = begin;
    }
    if (!added.isEmpty()) {
        beginInsertRows({}, static_cast<int>(m_rows.size()),
                        static_cast<int>(m_rows.size() + added.size() - 1));
        m_rows += added;
        endInsertRows();
    }
    rebuildIndex();
    const bool anyUnacked = std::any_of(m_rows.cbegin(), m_rows.cend(), [](const AlarmStatus &a) {
        return Alarms::isUnacked(a.state);
    });
    if (anyUnacked && !m_flashTimer.isActive()) {
        m_flashOn = true;
        m_flashTimer.start();
    } else if (!anyUnacked) {
        m_flashTimer.stop();
        m_flashOn = false;
    }
}

void AlarmSummaryModel::rebuildIndex()
{
    m_rowOf.clear();
    m_rowOf.reserve(m_rows.size());
    for (int r = 0; r < m_rows.size(); ++r)
        m_rowOf.insert(keyOf(m_rows.at(r).connection, m_rows.at(r).alarmId), r);
}

void AlarmSummaryModel::flash()
{
    m_flashOn = !m_flashOn;
    std::vector<int> rows;
    for (int r = 0; r < m_rows.size(); ++r) {
        if (Alarms::isUnacked(m_rows.at(r).state))
            rows.push_back(r);
    }
    if (rows.empty()) {
        m_flashTimer.stop();
        m_flashOn = false;
        return;
    }
    emitRuns(std::move(rows), 0, ColumnCount - 1,
             {FlashRole, Qt::BackgroundRole, Qt::ForegroundRole});
}

void AlarmSummaryModel::emitRuns(std::vector<int> rows, int firstColumn, int lastColumn,
                                 const QList<int> &roles)
{
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (std::size_t i = 0; i < rows.size();) {
        std::size_t j = i;
        while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1)
            ++j;
        Q_EMIT dataChanged(index(rows[i], firstColumn), index(rows[j], lastColumn), roles);
        i = j + 1;
    }
}

} // namespace Fatek
