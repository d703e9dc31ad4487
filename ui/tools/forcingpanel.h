#pragma once

#include "core/protocol/addressrange.h"
#include "core/protocol/request.h"
#include "ui/common/toolconfirmation.h"

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableView;

namespace Fatek {

class DiscreteTableModel;
class ForcedPointsView;
class RequestTracker;
class SymbolNames;

// Forcing of discretes: a table of a chosen range with each point's state (44) and enable flag
// (43), actions Disable / Enable / Set / Reset (42) on the selection, and the forced points view.
class ForcingPanel : public QWidget
{
    Q_OBJECT

public:
    explicit ForcingPanel(QWidget *parent = nullptr);

    // Without a direct link the panel shows "no connection" and disables its actions.
    void setTarget(const PlcTarget &target);

    // Test hook: answers the confirmation questions instead of a message box (both tabs).
    void setConfirmer(Confirmer confirmer);
    // The window's names (not owned): the discrete table and the forced points show them.
    void setSymbols(const SymbolNames *symbols);

    // Shows `count` points from `start` (X Y M S T C) and reads them.
    void showRange(ElementType type, quint32 start, quint32 count);
    void setAutoRefresh(bool on);
    DiscreteTableModel *model() const { return m_model; }
    QTableView *view() const { return m_view; }
    ForcedPointsView *forcedPointsView() const { return m_forced; }
    // Completed table reads since the target or range changed (tests wait for the next one).
    int readCount() const { return m_reads; }
    QString messageText() const;

public Q_SLOTS:
    void refresh();
    void applyToSelection(Fatek::DiscreteOp op);

protected:
    // Theme changes recolour the table (its colours are derived from the palette).
    void changeEvent(QEvent *event) override;

private:
    void applyRangeFromControls();
    void updateEnabled();

    RequestTracker *m_requests;
    PlcTarget m_target;
    Confirmer m_confirmer;
    QTimer m_timer;
    int m_pendingReads = 0;
    int m_reads = 0;
    bool m_acting = false;
    quint64 m_generation = 0;

    DiscreteTableModel *m_model;
    QLabel *m_targetLabel;
    QComboBox *m_type;
    QSpinBox *m_start;
    QSpinBox *m_count;
    QPushButton *m_readButton;
    QCheckBox *m_autoRefresh;
    QTableView *m_view;
    QList<QPushButton *> m_actionButtons;
    class MessageLine *m_message;
    ForcedPointsView *m_forced;
};

} // namespace Fatek
