#pragma once

#include "core/commission/memorysnapshot.h"
#include "ui/common/toolconfirmation.h"

#include <QDialog>
#include <QPointer>

#include <optional>

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace Fatek {

class MessageLine;
class Session;
class SnapshotDiffModel;
class SnapshotReader;
class ValuesRestorer;

// Tools -> Memory Snapshot: takes a snapshot of chosen ranges (progress, cancel), saves and opens
// snapshot files (JSON, CSV), compares the snapshot with the PLC or with another file in a
// filterable table, exports the differences as CSV, and restores chosen ranges of values after a
// confirmation (refused in operator mode). Outcomes in the message line.
class SnapshotDialog : public QDialog
{
    Q_OBJECT

public:
    explicit SnapshotDialog(QWidget *parent = nullptr);

    // session may be nullptr: the dialog shows "no connection"; files can still be compared.
    void setTarget(Fatek::Session *session, quint8 station, const QString &connectionName);
    // Tests answer the restore question without a modal box.
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }

    void setRanges(const QString &text);
    void setRestoreRanges(const QString &text);
    void setFilter(const QString &text);

    // The snapshot the dialog holds (taken or opened), compared and restored from.
    const std::optional<MemorySnapshot> &snapshot() const { return m_snapshot; }
    SnapshotDiffModel *differences() const { return m_model; }
    int visibleDifferences() const;
    QString messageText() const;
    bool isBusy() const;

public Q_SLOTS:
    void takeSnapshot();
    void cancel();
    void compareWithPlc();
    void restoreValues();
    // The file actions, without their file dialogs (the buttons ask for the name first).
    bool saveSnapshot(const QString &path);
    bool openSnapshot(const QString &path);
    bool compareWithFile(const QString &path);
    bool exportDifferences(const QString &path);

Q_SIGNALS:
    // Taken, compared or restored: the outcome is in the message line.
    void actionFinished();

private:
    void onSnapshotRead();
    void onCompared();
    // Writes m_restoreValues (the question answered); `otherModel`: a snapshot of another model
    // is written all the same.
    void startRestore(bool otherModel);
    void onRestored();
    void showMessage(const QString &text, bool error);
    void updateControls();
    QString fileFilter() const;

    SnapshotReader *m_reader;
    ValuesRestorer *m_restorer;
    QPointer<Session> m_session;
    quint8 m_station = 1;
    QString m_connectionName;
    Confirmer m_confirmer;
    std::optional<MemorySnapshot> m_snapshot;
    std::vector<SnapshotValue> m_restoreValues; // what the confirmed restore writes
    bool m_comparing = false;

    QLabel *m_targetLabel;
    QLineEdit *m_ranges;
    QPushButton *m_take;
    QPushButton *m_cancel;
    QPushButton *m_save;
    QPushButton *m_open;
    QLabel *m_snapshotLabel;
    QProgressBar *m_progress;
    QPushButton *m_comparePlc;
    QPushButton *m_compareFile;
    QPushButton *m_export;
    QLineEdit *m_filter;
    QTableView *m_table;
    SnapshotDiffModel *m_model;
    QSortFilterProxyModel *m_proxy;
    QLineEdit *m_restoreRanges;
    QPushButton *m_restore;
    MessageLine *m_message;
};

} // namespace Fatek
