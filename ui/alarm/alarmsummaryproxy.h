#pragma once

#include <QSortFilterProxyModel>

#include <optional>

namespace Fatek {

// What the summary shows of its model: sorted by a header click (state, priority and time by
// their order, not their words), filtered by priority, state, group and a text found in the
// item, message, group or connection.
class AlarmSummaryProxy : public QSortFilterProxyModel
{
    Q_OBJECT

public:
    enum class StateFilter { All, Unacked, Active, Shelved, OutOfService };

    explicit AlarmSummaryProxy(QObject *parent = nullptr);

    // A priority (AlarmPriority as int) or every one.
    void setPriorityFilter(std::optional<int> priority);
    void setStateFilter(StateFilter filter);
    // Empty: every group.
    void setGroupFilter(const QString &group);
    void setText(const QString &text);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    std::optional<int> m_priority;
    StateFilter m_state = StateFilter::All;
    QString m_group;
    QString m_text;
};

} // namespace Fatek
