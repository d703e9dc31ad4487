#pragma once

#include "core/commission/memorysnapshot.h"
#include "core/watch/csvfile.h"
#include "tooldialogframe.h"

#include <QDialog>

#include <optional>

class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;

namespace Fatek {

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

    // Without a direct link the dialog shows "no connection"; files can still be compared.
    void setTarget(const PlcTarget &target);
    // Tests answer the restore question and pick the files without modal dialogs.
    void setConfirmer(Confirmer confirmer) { m_frame->setConfirmer(std::move(confirmer)); }
    void setFileChooser(ToolDialogFrame::FileChooser chooser)
    {
        m_frame->setFileChooser(std::move(chooser));
    }

    void setRanges(const QString &text);
    void setRestoreRanges(const QString &text);
    void setFilter(const QString &text);

    // The snapshot the dialog holds (taken or opened), compared and restored from.
    const std::optional<MemorySnapshot> &snapshot() const { return m_snapshot; }
    SnapshotDiffModel *differences() const { return m_model; }
    int visibleDifferences() const;
    QString messageText() const;
    bool isBusy() const;
    // A snapshot taken from the PLC that is in no file yet (Close, Esc, Take, Open and quitting
    // the main window ask first).
    bool hasUnsavedSnapshot() const { return m_snapshot && !m_snapshotSaved; }
    // Close, Esc, the window's button: asks first when the snapshot is not saved.
    void reject() override;

public Q_SLOTS:
    void takeSnapshot();
    void cancel();
    void compareWithPlc();
    void restoreValues();
    // The file actions, without their file dialogs (the buttons ask for the name first).
    // A .csv snapshot or difference list: the byte order mark, `lineEnd` (CsvFile).
    bool saveSnapshot(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);
    bool openSnapshot(const QString &path);
    bool compareWithFile(const QString &path);
    bool exportDifferences(const QString &path, CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf);

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
    // Asks for a snapshot file (JSON or CSV); empty: cancelled. Saving: `lineEnd` gets the line
    // ends of the file type chosen.
    QString pickSnapshotFile(bool save, const QString &title, CsvFile::LineEnd *lineEnd = nullptr);
    void askSaveSnapshot();

    SnapshotReader *m_reader;
    ValuesRestorer *m_restorer;
    ToolDialogFrame *m_frame;
    std::optional<MemorySnapshot> m_snapshot;
    bool m_snapshotSaved = false;               // m_snapshot is in a file (saved or opened)
    std::vector<SnapshotValue> m_restoreValues; // what the confirmed restore writes
    bool m_comparing = false;

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
};

} // namespace Fatek
