#pragma once

#include "core/plant/plctarget.h"

#include <QObject>
#include <QTimer>

#include <functional>

namespace Fatek {

class RequestTracker;
class WatchTableModel;

// Keeps the "forced" marks of a watch table's discretes current: once a second at most it reads
// the enable flags (43) of the discrete rows, one request per run of up to 256 points of one kind
// and station, and hands them to the model. A new burst starts only when the previous one is
// answered, at the polling priority (user actions go first), and only while `active` says so
// (table visible, polling, link up).
class ForcedMarks : public QObject
{
    Q_OBJECT

public:
    static constexpr int intervalMs = 1000;

    ForcedMarks(WatchTableModel *model, QObject *parent = nullptr);

    // Reads through `target`'s link (every station of the table's rows, not only the target's);
    // without a direct link the reads stop and every mark is forgotten.
    void setTarget(const PlcTarget &target);
    void setActiveCheck(std::function<bool()> active) { m_active = std::move(active); }

private:
    void readBurst();

    WatchTableModel *m_model;
    RequestTracker *m_requests;
    std::function<bool()> m_active;
    QTimer m_timer;
    int m_pending = 0;
    quint64 m_generation = 0;
};

} // namespace Fatek
