#include "alarmjournaldialog.h"

#include "alarmtext.h"
#include "core/alarm/alarmjournal.h"
#include "core/alarm/alarmjournalwriter.h"
#include "core/watch/safefile.h"
#include "ui/common/csvfilefilter.h"
#include "ui/common/lastdirectory.h"
#include "ui/common/messageline.h"
#include "ui/common/uitext.h"

#include <QComboBox>
#include <QDateTime>
#include <QDateTimeEdit>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace Fatek {

namespace {

// The journal's columns (Journal... so that they never meet the summary's names in one unit).
enum JournalColumn {
    JournalTimeColumn,
    JournalConnectionColumn,
    JournalAlarmColumn,
    JournalEventColumn,
    JournalStateColumn,
    JournalPriorityColumn,
    JournalMessageColumn,
    JournalValueColumn,
    JournalUserColumn,
    JournalCommentColumn,
    JournalColumnCount
};

} // namespace

void AlarmEventsModel::setEvents(const QList<AlarmEvent> &events)
{
    // A new answer replaces the whole list: a reset once per query, not per poll.
    beginResetModel();
    m_events = events;
    endResetModel();
}

int AlarmEventsModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_events.size());
}

int AlarmEventsModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : JournalColumnCount;
}

QVariant AlarmEventsModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || role != Qt::DisplayRole || index.row() >= m_events.size())
        return {};
    const AlarmEvent &e = m_events.at(index.row());
    switch (index.column()) {
    case JournalTimeColumn:
        // Local time as it was then, with its offset (a summer-time change stays readable).
        return QDateTime::fromMSecsSinceEpoch(e.timeMs, Qt::OffsetFromUTC, e.utcOffsetS)
            .toString(Qt::ISODate);
    case JournalConnectionColumn: return e.connection;
    case JournalAlarmColumn: return e.alarmId;
    case JournalEventColumn:
        return e.type == AlarmEventType::Shelved && e.shelvedUntilMs > 0
                   ? tr("%1 until %2")
                         .arg(AlarmText::event(e.type), AlarmText::time(e.shelvedUntilMs))
                   : AlarmText::event(e.type);
    case JournalStateColumn: return AlarmText::state(e.state);
    case JournalPriorityColumn: return AlarmText::priority(e.priority);
    case JournalMessageColumn: return e.message;
    case JournalValueColumn: return e.value;
    case JournalUserColumn: return e.user;
    case JournalCommentColumn: return e.comment;
    default: return {};
    }
}

QVariant AlarmEventsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case JournalTimeColumn: return tr("Time");
    case JournalConnectionColumn: return tr("Connection");
    case JournalAlarmColumn: return tr("Alarm");
    case JournalEventColumn: return tr("Event");
    case JournalStateColumn: return tr("State after");
    case JournalPriorityColumn: return tr("Priority");
    case JournalMessageColumn: return tr("Message");
    case JournalValueColumn: return tr("Value");
    case JournalUserColumn: return tr("User");
    case JournalCommentColumn: return tr("Comment");
    default: return {};
    }
}

AlarmJournalDialog::AlarmJournalDialog(AlarmJournalWriter *journal, const QStringList &connections,
                                       QWidget *parent)
    : QDialog(parent)
    , m_journal(journal)
    , m_model(new AlarmEventsModel(this))
    , m_from(new QDateTimeEdit(this))
    , m_to(new QDateTimeEdit(this))
    , m_connection(new QComboBox(this))
    , m_query(new QPushButton(tr("&Show"), this))
    , m_export(new QPushButton(tr("&Export CSV…"), this))
    , m_view(new QTableView(this))
    , m_message(new MessageLine(1, this))
{
    setObjectName(QStringLiteral("alarmJournalDialog"));
    setWindowTitle(tr("Alarm Journal"));
    const QDateTime now = QDateTime::currentDateTime();
    for (QDateTimeEdit *edit : {m_from, m_to}) {
        edit->setDisplayFormat(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
        edit->setCalendarPopup(true);
    }
    m_from->setObjectName(QStringLiteral("journalFrom"));
    m_to->setObjectName(QStringLiteral("journalTo"));
    m_from->setDateTime(now.addDays(-1));
    // Events keep coming: the end is a minute ahead so that "now" includes them.
    m_to->setDateTime(now.addSecs(60));
    m_connection->setObjectName(QStringLiteral("journalConnection"));
    m_connection->addItem(tr("All connections"));
    m_connection->addItems(connections);
    m_query->setObjectName(QStringLiteral("journalShow"));
    m_query->setDefault(true);
    m_export->setObjectName(QStringLiteral("journalExport"));
    m_export->setEnabled(false);
    m_view->setObjectName(QStringLiteral("journalView"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->verticalHeader()->hide();
    m_view->setWordWrap(false);
    m_view->horizontalHeader()->setStretchLastSection(true);

    auto *range = new QHBoxLayout;
    range->addWidget(new QLabel(tr("From:"), this));
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("To:"), this));
    range->addWidget(m_to);
    range->addWidget(new QLabel(tr("Connection:"), this));
    range->addWidget(m_connection, 1);
    range->addWidget(m_query);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_export, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_query, &QPushButton::clicked, this, &AlarmJournalDialog::query);
    connect(m_export, &QPushButton::clicked, this, &AlarmJournalDialog::exportDialog);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(range);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    resize(1100, 560);
}

void AlarmJournalDialog::query()
{
    const qint64 from = m_from->dateTime().toMSecsSinceEpoch();
    const qint64 to = m_to->dateTime().toMSecsSinceEpoch();
    if (to <= from) {
        m_message->setMessage(tr("The end of the range must come after its start."), true);
        return;
    }
    const QString connection
        = m_connection->currentIndex() > 0 ? m_connection->currentText() : QString();
    ++m_pending;
    m_query->setEnabled(false);
    m_message->setMessage(tr("Reading the journal…"), false);
    m_journal->query(from, to, connection, this, [this](const auto &result) {
        m_query->setEnabled(--m_pending == 0);
        if (!result) {
            m_message->setMessage(
                tr("The journal could not be read: %1").arg(translated(result.error().message)),
                true);
            return;
        }
        m_model->setEvents(result.value());
        m_view->resizeColumnsToContents();
        m_export->setEnabled(!result.value().isEmpty());
        m_message->setMessage(tr("%n event(s).", nullptr, static_cast<int>(result.value().size())),
                              false);
        Q_EMIT queried();
    });
}

QString AlarmJournalDialog::exportCsv(const QString &path, CsvFile::LineEnd lineEnd) const
{
    return SafeFile::write(path, AlarmJournal::toCsvFile(m_model->events(), lineEnd));
}

void AlarmJournalDialog::exportDialog()
{
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Alarm Journal"), lastDirectory() + QStringLiteral("/alarms.csv"),
        CsvFileFilter::both() + QStringLiteral(";;") + tr("All files (*)"), &filter);
    if (path.isEmpty())
        return;
    setLastDirectory(path);
    if (const QString reason = exportCsv(path, CsvFileFilter::lineEnd(filter)); !reason.isEmpty())
        m_message->setMessage(tr("Not exported: %1").arg(reason), true);
    else
        m_message->setMessage(
            tr("%n event(s) written to %1.", nullptr, static_cast<int>(m_model->events().size()))
                .arg(path),
            false);
}

} // namespace Fatek
