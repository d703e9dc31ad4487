#pragma once

#include "core/protocol/result.h"
#include "core/watch/symbolimport.h"
#include "core/watch/watchlist.h"

#include <QObject>
#include <QString>

class QAction;
class QMenu;

namespace Fatek {

class MainWindow;
class SymbolNames;

// The watch list file of the main window: all its tables saved to or loaded from one file, CSV
// rows imported into the current table, the last list reopened at start, and whether the tables
// changed since they were saved. The window title names the file. It owns the window's names
// (SymbolNames: the ladder project's names and comments, imported and saved with the list).
class WatchListDocument : public QObject
{
    Q_OBJECT

public:
    explicit WatchListDocument(MainWindow *window);

    // The file (absolute), empty while untitled.
    QString path() const { return m_path; }
    // Load replaces the tables only if the file is valid.
    Status save(const QString &path);
    Status load(const QString &path);
    // load() and its outcome for the technician: a (non-modal) warning naming the file, or
    // "Loaded …" in the status bar. File > Open and a FILE given at start-up both use it.
    Status open(const QString &path);
    // CSV rows into the current table.
    Status importCsv(const QString &path);
    // A comment/symbol list of the ladder project (SymbolImport) into the window's names, which
    // every table, the trend and the forcing tool show; the outcome (names imported, lines
    // skipped and why) goes to the status bar. File > Import Names and Comments… calls it.
    Result<SymbolImport> importNames(const QString &path);
    // The window's names: the one table of them (see SymbolNames).
    const SymbolNames *symbols() const { return m_symbols; }
    // Opens the watch list saved or opened last (when that preference is on); false if none.
    bool restoreLast();

    // Adds Open, Save, Import CSV and Reopen Last Watch List at Start to `file`.
    void addFileActions(QMenu *file);
    QAction *openAction() const { return m_openAction; }
    QAction *saveAction() const { return m_saveAction; }

    // false when cancelled or failed
    bool saveDialog();
    // The tables as saved to (or loaded from) `path` (empty: untitled); the title follows.
    void markSaved(const QString &path);
    bool isModified() const;
    void updateWindowTitle();
    // The title's unsaved-changes mark ("[*]") follows isModified(); the tables call it when
    // they change.
    void updateModified();
    // With unsaved changes: Save, Discard or Cancel (`action` names what comes next, e.g.
    // "Open Watch List"); true when the changes are saved or may go.
    bool maybeSave(const QString &action);

Q_SIGNALS:
    void statusMessage(const QString &text);

private:
    void openDialog();
    void importCsvDialog();
    void importNamesDialog();
    WatchListFile currentList() const;

    MainWindow *m_window;
    SymbolNames *m_symbols;
    QString m_path;
    WatchListFile m_saved;
    QAction *m_openAction = nullptr;
    QAction *m_saveAction = nullptr;
};

} // namespace Fatek
