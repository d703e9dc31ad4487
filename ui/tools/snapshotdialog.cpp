#include "snapshotdialog.h"

#include "core/commission/commissionmessages.h"
#include "core/commission/snapshotfile.h"
#include "core/commission/snapshotreader.h"
#include "core/commission/valuesrestorer.h"
#include "core/watch/safefile.h"
#include "snapshotdiffmodel.h"
#include "ui/common/csvfilefilter.h"
#include "ui/common/uitext.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

namespace Fatek {

SnapshotDialog::SnapshotDialog(QWidget *parent)
    : QDialog(parent)
    , m_reader(new SnapshotReader(this))
    , m_restorer(new ValuesRestorer(this))
    // Closed while it reads or writes: nothing goes on behind the person's back.
    , m_frame(new ToolDialogFrame(this, 2, QStringLiteral("message"), [this] { cancel(); }))
{
    setWindowTitle(tr("Memory Snapshot"));
    QVBoxLayout *layout = m_frame->content();

    auto *form = new QFormLayout;
    m_ranges = new QLineEdit(this);
    m_ranges->setObjectName(QStringLiteral("ranges"));
    m_ranges->setPlaceholderText(tr("R0..R99, M0..M63 (empty: every element the PLC reports)"));
    form->addRow(tr("Ranges:"), m_ranges);
    layout->addLayout(form);

    auto *snapRow = new QHBoxLayout;
    m_take = new QPushButton(tr("Take Snapshot"), this);
    m_take->setObjectName(QStringLiteral("takeButton"));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("cancelButton"));
    m_save = new QPushButton(tr("Save…"), this);
    m_save->setObjectName(QStringLiteral("saveButton"));
    m_open = new QPushButton(tr("Open…"), this);
    m_open->setObjectName(QStringLiteral("openButton"));
    snapRow->addWidget(m_take);
    snapRow->addWidget(m_cancel);
    snapRow->addWidget(m_save);
    snapRow->addWidget(m_open);
    snapRow->addStretch(1);
    layout->addLayout(snapRow);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    layout->addWidget(m_progress);
    m_snapshotLabel = new QLabel(this);
    m_snapshotLabel->setObjectName(QStringLiteral("snapshotLabel"));
    m_snapshotLabel->setWordWrap(true);
    layout->addWidget(m_snapshotLabel);

    auto *compareRow = new QHBoxLayout;
    m_comparePlc = new QPushButton(tr("Compare With PLC"), this);
    m_comparePlc->setObjectName(QStringLiteral("comparePlcButton"));
    m_compareFile = new QPushButton(tr("Compare With File…"), this);
    m_compareFile->setObjectName(QStringLiteral("compareFileButton"));
    m_export = new QPushButton(tr("Export Differences…"), this);
    m_export->setObjectName(QStringLiteral("exportButton"));
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("filter"));
    m_filter->setPlaceholderText(tr("Filter"));
    m_filter->setClearButtonEnabled(true);
    compareRow->addWidget(m_comparePlc);
    compareRow->addWidget(m_compareFile);
    compareRow->addWidget(m_export);
    compareRow->addWidget(m_filter, 1);
    layout->addLayout(compareRow);

    m_model = new SnapshotDiffModel(this);
    m_proxy = new QSortFilterProxyModel(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterKeyColumn(-1);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("differences"));
    m_table->setModel(m_proxy);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    layout->addWidget(m_table, 1);

    auto *restoreRow = new QHBoxLayout;
    m_restoreRanges = new QLineEdit(this);
    m_restoreRanges->setObjectName(QStringLiteral("restoreRanges"));
    m_restoreRanges->setPlaceholderText(tr("Ranges to restore (empty: all but the inputs X)"));
    m_restore = new QPushButton(tr("Restore Values…"), this);
    m_restore->setObjectName(QStringLiteral("restoreButton"));
    restoreRow->addWidget(m_restoreRanges, 1);
    restoreRow->addWidget(m_restore);
    layout->addLayout(restoreRow);

    // A new snapshot or an opened file replaces the one held: asked first when it is not saved.
    connect(m_take, &QPushButton::clicked, this, [this] {
        if (m_frame->mayDiscard())
            takeSnapshot();
    });
    connect(m_cancel, &QPushButton::clicked, this, &SnapshotDialog::cancel);
    connect(m_comparePlc, &QPushButton::clicked, this, &SnapshotDialog::compareWithPlc);
    connect(m_restore, &QPushButton::clicked, this, &SnapshotDialog::restoreValues);
    connect(m_save, &QPushButton::clicked, this, [this] { askSaveSnapshot(); });
    connect(m_open, &QPushButton::clicked, this, [this] {
        if (!m_frame->mayDiscard())
            return;
        if (const QString path = pickSnapshotFile(false, tr("Open Snapshot")); !path.isEmpty())
            openSnapshot(path);
    });
    connect(m_compareFile, &QPushButton::clicked, this, [this] {
        if (const QString path = pickSnapshotFile(false, tr("Compare With File")); !path.isEmpty())
            compareWithFile(path);
    });
    connect(m_export, &QPushButton::clicked, this, [this] {
        QString filter;
        const QString path = m_frame->chooseFile(
            {true, tr("Export Differences"), CsvFileFilter::both(), {}, &filter});
        if (!path.isEmpty())
            exportDifferences(path, CsvFileFilter::lineEnd(filter));
    });
    connect(m_filter, &QLineEdit::textChanged, m_proxy,
            &QSortFilterProxyModel::setFilterFixedString);
    auto showProgress = [this](int doneCount, int total) {
        m_progress->setRange(0, std::max(1, total));
        m_progress->setValue(doneCount);
    };
    connect(m_reader, &SnapshotReader::progress, this, showProgress);
    connect(m_restorer, &ValuesRestorer::progress, this, showProgress);
    connect(m_reader, &SnapshotReader::finished, this, [this] {
        if (m_comparing)
            onCompared();
        else
            onSnapshotRead();
    });
    connect(m_restorer, &ValuesRestorer::finished, this, &SnapshotDialog::onRestored);
    m_frame->setUnsaved(
        [this] {
            if (!hasUnsavedSnapshot())
                return QString();
            return tr("The memory snapshot of %n value(s) taken at %1 from station %2 is not "
                      "saved.",
                      nullptr, static_cast<int>(m_snapshot->values.size()))
                .arg(QLocale().toString(m_snapshot->info.taken.toLocalTime(), QLocale::ShortFormat))
                .arg(m_snapshot->info.station);
        },
        [this] {
            askSaveSnapshot();
            return !hasUnsavedSnapshot();
        });
    setTarget(PlcTarget());
    resize(640, 560);
}

QString SnapshotDialog::pickSnapshotFile(bool save, const QString &title, CsvFile::LineEnd *lineEnd)
{
    // Saving: a second type for a .csv snapshot with Windows line ends.
    QString filter;
    const QString snapshots = tr("Snapshots (*.json *.csv)");
    const QString path = m_frame->chooseFile(
        {save,
         title,
         save ? snapshots + QStringLiteral(";;") + CsvFileFilter::windows() : snapshots,
         {},
         &filter});
    if (lineEnd)
        *lineEnd = CsvFileFilter::lineEnd(filter);
    return path;
}

void SnapshotDialog::askSaveSnapshot()
{
    CsvFile::LineEnd lineEnd = CsvFile::LineEnd::Lf;
    if (const QString path = pickSnapshotFile(true, tr("Save Snapshot"), &lineEnd); !path.isEmpty())
        saveSnapshot(path, lineEnd);
}

void SnapshotDialog::setTarget(const PlcTarget &target)
{
    if (isBusy()) {
        cancel();
        showMessage(tr("Stopped: the target changed."), true);
    }
    m_frame->setTarget(target);
    target.aim(m_reader);
    target.aim(m_restorer);
    updateControls();
}

void SnapshotDialog::setRanges(const QString &text)
{
    m_ranges->setText(text);
}

void SnapshotDialog::setRestoreRanges(const QString &text)
{
    m_restoreRanges->setText(text);
}

void SnapshotDialog::setFilter(const QString &text)
{
    m_filter->setText(text);
}

int SnapshotDialog::visibleDifferences() const
{
    return m_proxy->rowCount();
}

QString SnapshotDialog::messageText() const
{
    return m_frame->messageText();
}

bool SnapshotDialog::isBusy() const
{
    return m_reader->isRunning() || m_restorer->isRunning();
}

void SnapshotDialog::showMessage(const QString &text, bool error)
{
    m_frame->showMessage(text, error);
}

void SnapshotDialog::updateControls()
{
    const bool busy = isBusy();
    const bool connected = m_frame->target().isDirect();
    const bool have = m_snapshot.has_value();
    m_take->setEnabled(connected && !busy);
    m_cancel->setEnabled(busy);
    m_save->setEnabled(have && !busy);
    m_open->setEnabled(!busy);
    m_comparePlc->setEnabled(have && connected && !busy);
    m_compareFile->setEnabled(have && !busy);
    m_export->setEnabled(!m_model->differences().empty());
    m_restore->setEnabled(have && connected && !busy);
    m_ranges->setEnabled(!busy);
    m_restoreRanges->setEnabled(!busy);
    if (have) {
        const SnapshotInfo &i = m_snapshot->info;
        m_snapshotLabel->setText(
            tr("Snapshot: %1 values, %2, station %3, %4")
                .arg(m_snapshot->values.size())
                .arg(QLocale().toString(i.taken.toLocalTime(), QLocale::ShortFormat))
                .arg(i.station)
                .arg(i.model.isEmpty() ? i.link : UiText::modelText(i.model)));
    } else {
        m_snapshotLabel->setText(tr("No snapshot yet: take one or open a file."));
    }
}

void SnapshotDialog::takeSnapshot()
{
    if (!m_frame->target().isDirect() || isBusy())
        return;
    const auto ranges = Snapshot::parseRanges(m_ranges->text());
    if (!ranges) {
        showMessage(translated(ranges.error().message), true);
        return;
    }
    m_comparing = false;
    showMessage(tr("Reading…"), false);
    m_reader->start(m_frame->target().station(), ranges.value());
    updateControls();
}

void SnapshotDialog::reject()
{
    if (m_frame->mayDiscard())
        QDialog::reject();
}

void SnapshotDialog::cancel()
{
    m_reader->cancel();
    m_restorer->cancel();
    updateControls();
}

void SnapshotDialog::onSnapshotRead()
{
    if (!m_reader->ok()) {
        showMessage(translated(m_reader->error().message), true);
    } else {
        m_snapshot = m_reader->snapshot();
        m_snapshotSaved = false;
        showMessage(translated(msg<MsgId::SnapshotTaken>(m_snapshot->values.size(),
                                                         m_reader->requestsTotal())),
                    false);
    }
    updateControls();
    Q_EMIT actionFinished();
}

void SnapshotDialog::compareWithPlc()
{
    if (!m_frame->target().isDirect() || !m_snapshot || isBusy())
        return;
    std::vector<Address> addresses;
    addresses.reserve(m_snapshot->values.size());
    for (const SnapshotValue &v : m_snapshot->values)
        addresses.push_back(v.address);
    m_comparing = true;
    showMessage(tr("Reading…"), false);
    m_reader->start(m_frame->target().station(), Snapshot::rangesOf(addresses));
    updateControls();
}

void SnapshotDialog::onCompared()
{
    m_comparing = false;
    if (!m_reader->ok()) {
        showMessage(translated(m_reader->error().message), true);
    } else {
        std::size_t compared = 0;
        auto d = SnapshotDiff::compare(*m_snapshot, m_reader->snapshot(), &compared);
        const std::size_t count = d.size();
        m_model->setDifferences(std::move(d), tr("Snapshot"), tr("PLC"));
        showMessage(translated(SnapshotDiff::summary(count, compared)), false);
    }
    updateControls();
    Q_EMIT actionFinished();
}

bool SnapshotDialog::saveSnapshot(const QString &path, CsvFile::LineEnd lineEnd)
{
    if (!m_snapshot)
        return false;
    if (const auto problem = SnapshotFile::saveToFile(*m_snapshot, path, lineEnd)) {
        showMessage(translated(problem->message), true);
        return false;
    }
    m_snapshotSaved = true;
    showMessage(tr("Saved %1.").arg(path), false);
    return true;
}

bool SnapshotDialog::openSnapshot(const QString &path)
{
    const SnapshotFile::Loaded loaded = SnapshotFile::loadFromFile(path);
    if (!loaded.ok()) {
        showMessage(translated(loaded.error.message), true);
        return false;
    }
    m_snapshot = loaded.snapshot;
    m_snapshotSaved = true;
    m_model->setDifferences({}, tr("Before"), tr("After"));
    showMessage(tr("Opened %1.").arg(path), false);
    updateControls();
    return true;
}

bool SnapshotDialog::compareWithFile(const QString &path)
{
    if (!m_snapshot)
        return false;
    const SnapshotFile::Loaded loaded = SnapshotFile::loadFromFile(path);
    if (!loaded.ok()) {
        showMessage(translated(loaded.error.message), true);
        return false;
    }
    std::size_t compared = 0;
    auto d = SnapshotDiff::compare(*m_snapshot, *loaded.snapshot, &compared);
    const std::size_t count = d.size();
    m_model->setDifferences(std::move(d), tr("Snapshot"), tr("File"));
    showMessage(translated(SnapshotDiff::summary(count, compared)), false);
    updateControls();
    return true;
}

bool SnapshotDialog::exportDifferences(const QString &path, CsvFile::LineEnd lineEnd)
{
    if (const QString reason = SafeFile::write(path, m_model->toCsv(lineEnd)); !reason.isEmpty()) {
        showMessage(translated(msg<MsgId::SnapshotFileCannotWrite>(
                        path.toStdString(), Message::text(reason.toStdString()))),
                    true);
        return false;
    }
    showMessage(tr("Exported %1 differences to %2.").arg(m_model->differences().size()).arg(path),
                false);
    return true;
}

void SnapshotDialog::restoreValues()
{
    if (!m_frame->target().isDirect() || !m_snapshot || isBusy())
        return;
    if (m_frame->target().isReadOnly()) {
        // The restorer refuses too; saying it here spares the question.
        showMessage(translated(msg<MsgId::RestoreReadOnly>()), true);
        return;
    }
    // An empty field restores what fatek-cli restore-values without RANGES does.
    const auto ranges = Snapshot::parseRanges(m_restoreRanges->text());
    if (!ranges) {
        showMessage(translated(ranges.error().message), true);
        return;
    }
    std::vector<SnapshotValue> values = m_snapshot->toRestore(ranges.value());
    if (values.empty()) {
        showMessage(translated(msg<MsgId::RestoreNothing>()), true);
        return;
    }
    const auto frames = ValuesRestorer::writeRequests(m_frame->target().station(), values).size();
    const QString question
        = tr("Write %1 values of the snapshot to %2 in %n request(s), then read them back?",
             nullptr, static_cast<int>(frames))
              .arg(values.size())
              .arg(m_frame->targetText());
    if (!m_frame->ask(tr("Restore Values"), question)) {
        showMessage(tr("Not restored: nothing was written."), false);
        return;
    }
    m_restoreValues = std::move(values);
    startRestore(false);
}

void SnapshotDialog::startRestore(bool otherModel)
{
    showMessage(tr("Writing…"), false);
    m_restorer->setAllowOtherModel(otherModel);
    m_restorer->start(m_frame->target().station(), m_restoreValues, m_snapshot->info.model);
    updateControls();
}

void SnapshotDialog::onRestored()
{
    // Another model than the PLC's: nothing was written; the person decides.
    if (m_restorer->refusedForModel() && m_snapshot) {
        const QString question
            = tr("The snapshot is of another model than the PLC at %1.\n\nSnapshot: %2\nPLC: "
                 "%3\n\nWrite its values all the same? Elements the PLC does not have are "
                 "refused before anything is written.")
                  .arg(m_frame->targetText(), m_snapshot->info.model, m_restorer->plcModel());
        if (m_frame->ask(tr("Restore Values"), question))
            return startRestore(true);
    }
    if (!m_restorer->error())
        m_model->setDifferences(m_restorer->mismatches(), tr("Written"), tr("Read back"));
    showMessage(translated(m_restorer->outcome()), !m_restorer->ok());
    updateControls();
    Q_EMIT actionFinished();
}

} // namespace Fatek
