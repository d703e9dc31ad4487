#pragma once

#include "core/protocol/plcstatus.h"
#include "ui/common/toolconfirmation.h"

#include <QTimer>
#include <QWidget>

#include <optional>

class QFormLayout;
class QLabel;
class QPushButton;

namespace Fatek {

class RequestTracker;
class SessionResult;
class StatusIndicator;

// RUN/STOP and status of one PLC: every STATUS1 bit as a lamp (40, refreshed periodically), the
// detail status (53) decoded where the reference documents it, and RUN/STOP buttons that ask
// for confirmation naming the station and the connection.
class PlcControlPanel : public QWidget
{
    Q_OBJECT

public:
    explicit PlcControlPanel(QWidget *parent = nullptr);

    // Without a direct link the panel shows "no connection" and disables its actions.
    void setTarget(const PlcTarget &target);

    // Test hook: answers the confirmation questions instead of a message box.
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    void setRefreshInterval(int ms);

    std::optional<PlcStatus> status() const { return m_status; }
    std::optional<DetailStatus> detailStatus() const { return m_detail; }
    // The outcome of the last RUN/STOP ("PLC error 5: cannot RUN: ladder checksum error").
    QString outcomeText() const;

public Q_SLOTS:
    void refresh();
    void refreshDetail();
    void requestRun();
    void requestStop();

private:
    void requestMode(bool run);
    void onBriefStatus(const SessionResult &result);
    void onDetailStatus(const SessionResult &result);
    void showStatus(const std::optional<PlcStatus> &status);
    void showDetail();
    void updateEnabled();
    QLabel *addDetailRow(const QString &label);

    RequestTracker *m_requests;
    PlcTarget m_target;
    Confirmer m_confirmer;
    QTimer m_timer;
    int m_ticks = 0;
    bool m_briefPending = false;
    bool m_detailPending = false;
    bool m_modePending = false;
    QMetaObject::Connection m_linkWatch; // the target's link state, for the RUN/STOP buttons

    std::optional<PlcStatus> m_status;
    std::optional<DetailStatus> m_detail;

    QLabel *m_targetLabel;
    QLabel *m_modeLabel;
    QList<StatusIndicator *> m_indicators;
    QPushButton *m_runButton;
    QPushButton *m_stopButton;
    QPushButton *m_refreshButton;
    QLabel *m_refreshLabel;
    QLabel *m_outcomeLabel;
    QFormLayout *m_detailForm;
    QLabel *m_model, *m_io, *m_os, *m_program, *m_discretes, *m_analog, *m_relays, *m_registers,
        *m_timersCounters, *m_raw;
};

} // namespace Fatek
