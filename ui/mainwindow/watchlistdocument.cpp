#include "watchlistdocument.h"

#include "core/watch/symbolimport.h"
#include "mainwindow.h"
#include "ui/common/lastdirectory.h"
#include "ui/common/symbolnames.h"
#include "ui/common/uitext.h"
#include "ui/watch/watchtablemodel.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

namespace Fatek {

namespace {
const QString lastListKey = QStringLiteral("preferences/lastWatchList");
const QString reopenKey = QStringLiteral("preferences/reopenLastWatchList");
} // namespace

WatchListDocument::WatchListDocument(MainWindow *window)
    : QObject(window)
    , m_window(window)
    , m_symbols(new SymbolNames(this))
{
    connect(m_symbols, &SymbolNames::changed, this, &WatchListDocument::updateModified);
}

void WatchListDocument::addFileActions(QMenu *file)
{
    m_openAction = file->addAction(QIcon(QStringLiteral(":/icons/open.svg")),
                                   tr("&Open Watch List…"), this, &WatchListDocument::openDialog);
    m_openAction->setShortcut(QKeySequence::Open);
    m_saveAction = file->addAction(QIcon(QStringLiteral(":/icons/save.svg")),
                                   tr("&Save Watch List…"), this, &WatchListDocument::saveDialog);
    m_saveAction->setShortcut(QKeySequence::Save);
    auto *importAction
        = file->addAction(tr("&Import CSV…"), this, &WatchListDocument::importCsvDialog);
    importAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    auto *importNames = file->addAction(tr("Import Names and Co&mments…"), this,
                                        &WatchListDocument::importNamesDialog);
    importNames->setObjectName(QStringLiteral("importNamesAction"));
    importNames->setToolTip(tr("Read the names and comments of addresses from the ladder "
                               "project's comment/symbol list (CSV or tab-separated text)"));
    auto *reopen = file->addAction(tr("Reopen Last Watch List at Start"));
    reopen->setCheckable(true);
    reopen->setChecked(QSettings().value(reopenKey, true).toBool());
    connect(reopen, &QAction::toggled, this, [](bool on) { QSettings().setValue(reopenKey, on); });
}

Status WatchListDocument::save(const QString &path)
{
    Status s = WatchList::saveToFile(currentList(), path);
    if (s) {
        QSettings().setValue(lastListKey, QFileInfo(path).absoluteFilePath());
        markSaved(path);
    }
    return s;
}

Status WatchListDocument::load(const QString &path)
{
    const auto file = WatchList::loadFromFile(path);
    if (!file)
        return file.error();
    // The names first: the new tables take them as they are made.
    m_symbols->setTable(file->symbols);
    m_window->replaceWatchTables(file->tables);
    QSettings().setValue(lastListKey, QFileInfo(path).absoluteFilePath());
    markSaved(path);
    return Ok{};
}

bool WatchListDocument::restoreLast()
{
    QSettings settings;
    const QString path = settings.value(lastListKey).toString();
    if (!settings.value(reopenKey, true).toBool() || path.isEmpty() || !QFileInfo::exists(path))
        return false;
    if (const Status s = load(path); !s) {
        Q_EMIT statusMessage(
            tr("The last watch list %1 cannot be loaded: %2")
                .arg(QDir::toNativeSeparators(path), translated(s.error().message)));
        return false;
    }
    Q_EMIT statusMessage(tr("Reopened %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

Status WatchListDocument::importCsv(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(ErrorKind::InvalidRequest,
                         tr("Cannot open %1: %2").arg(path, f.errorString()).toStdString());
    const auto rows = WatchList::importCsv(f.readAll());
    if (!rows)
        return rows.error();
    WatchTableWidget *table
        = m_window->currentWatchTable() ? m_window->currentWatchTable() : m_window->addWatchTable();
    table->model()->addItems(*rows);
    return Ok{};
}

Result<SymbolImport> WatchListDocument::importNames(const QString &path)
{
    auto result = SymbolImport::fromFile(path);
    if (!result) {
        Q_EMIT statusMessage(
            tr("%1 cannot be imported: %2")
                .arg(QDir::toNativeSeparators(path), translated(result.error().message)));
        return result;
    }
    m_symbols->merge(result->symbols());
    Q_EMIT statusMessage(
        tr("%1: %2").arg(QFileInfo(path).fileName(), translated(result->summary())));
    return result;
}

void WatchListDocument::importNamesDialog()
{
    const QString path = QFileDialog::getOpenFileName(
        m_window, tr("Import Names and Comments"), lastDirectory(),
        tr("Comment/symbol lists (*.csv *.txt *.tsv);;All files (*)"));
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    const auto result = importNames(path);
    if (!result) {
        QMessageBox::warning(
            m_window, tr("Import Names and Comments"),
            tr("%1 cannot be imported:\n%2")
                .arg(QFileInfo(path).fileName(), translated(result.error().message)));
    } else if (result->imported() == 0) {
        // Most likely the wrong file: say so where it cannot be missed.
        QMessageBox::warning(
            m_window, tr("Import Names and Comments"),
            tr("%1: %2").arg(QFileInfo(path).fileName(), translated(result->summary())));
    }
}

void WatchListDocument::openDialog()
{
    if (!maybeSave(tr("Open Watch List")))
        return;
    const QString path
        = QFileDialog::getOpenFileName(m_window, tr("Open Watch List"), lastDirectory(),
                                       tr("Watch lists (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    open(path);
}

Status WatchListDocument::open(const QString &path)
{
    const Status loaded = load(path);
    if (!loaded) {
        // Not modal, so the window (and --screenshot at start-up) carries on.
        auto *box = new QMessageBox(
            QMessageBox::Warning, tr("Open Watch List"),
            tr("%1 cannot be loaded:\n%2")
                .arg(QFileInfo(path).fileName(), translated(loaded.error().message)),
            QMessageBox::Ok, m_window);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        return loaded;
    }
    Q_EMIT statusMessage(tr("Loaded %1.").arg(QDir::toNativeSeparators(path)));
    return loaded;
}

bool WatchListDocument::saveDialog()
{
    QString path = QFileDialog::getSaveFileName(m_window, tr("Save Watch List"),
                                                m_path.isEmpty() ? lastDirectory() : m_path,
                                                tr("Watch lists (*.json)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    setLastDirectory(path);
    if (const Status s = save(path); !s) {
        QMessageBox::warning(m_window, tr("Save Watch List"), translated(s.error().message));
        return false;
    }
    Q_EMIT statusMessage(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

void WatchListDocument::importCsvDialog()
{
    const QString path = QFileDialog::getOpenFileName(m_window, tr("Import CSV"), lastDirectory(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    if (const Status s = importCsv(path); !s) {
        QMessageBox::warning(m_window, tr("Import CSV"),
                             tr("%1 cannot be imported:\n%2")
                                 .arg(QFileInfo(path).fileName(), translated(s.error().message)));
        return;
    }
    Q_EMIT statusMessage(tr("Imported %1.").arg(QDir::toNativeSeparators(path)));
}

WatchListFile WatchListDocument::currentList() const
{
    WatchListFile file;
    for (WatchTableWidget *t : m_window->watchTables())
        file.tables.append(t->spec());
    file.symbols = m_symbols->table();
    return file;
}

void WatchListDocument::markSaved(const QString &path)
{
    m_path = path.isEmpty() ? QString() : QFileInfo(path).absoluteFilePath();
    m_saved = currentList();
    updateWindowTitle();
}

bool WatchListDocument::isModified() const
{
    return currentList() != m_saved;
}

void WatchListDocument::updateModified()
{
    m_window->setWindowModified(isModified());
}

bool WatchListDocument::maybeSave(const QString &action)
{
    if (!isModified())
        return true;
    QMessageBox box(
        QMessageBox::Question, action,
        tr("The watch list %1 has changes that are not saved.")
            .arg(m_path.isEmpty() ? tr("(untitled)") : QDir::toNativeSeparators(m_path)),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_window);
    box.setObjectName(QStringLiteral("unsavedQuestionBox"));
    box.setInformativeText(tr("Save them first?"));
    box.button(QMessageBox::Save)->setObjectName(QStringLiteral("saveButton"));
    box.button(QMessageBox::Discard)->setObjectName(QStringLiteral("discardButton"));
    box.button(QMessageBox::Cancel)->setObjectName(QStringLiteral("cancelButton"));
    box.setDefaultButton(QMessageBox::Save);
    box.setEscapeButton(QMessageBox::Cancel);
    switch (box.exec()) {
    case QMessageBox::Save: return m_path.isEmpty() ? saveDialog() : bool(save(m_path));
    case QMessageBox::Discard: return true;
    default: return false;
    }
}

void WatchListDocument::updateWindowTitle()
{
    // The platform adds the application name ("… — FATEK Studio"): the title names the document.
    // "[*]": the platform shows the unsaved-changes mark there (setWindowModified).
    const QString list
        = (m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName()) + QLatin1String("[*]");
    m_window->setWindowTitle(m_window->isReadOnly() ? tr("%1 — Operator mode (read-only)").arg(list)
                                                    : list);
    m_window->setWindowFilePath(m_path);
    updateModified();
}

} // namespace Fatek
