#include "checkoutpunchdialog.h"

#include "core/commission/checkoutreport.h"
#include "core/commission/checkoutrunner.h"
#include "core/watch/safefile.h"
#include "tooldialogframe.h"
#include "ui/common/csvfilefilter.h"
#include "ui/common/toolpalette.h"
#include "ui/common/uitext.h"

#include <QDir>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace Fatek {

CheckoutPunchDialog::CheckoutPunchDialog(CheckoutRunner *runner, ToolDialogFrame *frame,
                                         QWidget *parent)
    : QDialog(parent)
    , m_runner(runner)
    , m_frame(frame)
{
    setObjectName(QStringLiteral("checkoutPunchDialog"));
    setWindowTitle(tr("Punch List"));
    auto *layout = new QVBoxLayout(this);
    m_table = new QTableWidget(this);
    m_table->setObjectName(QStringLiteral("punchTable"));
    QStringList headers;
    for (const Message &c : CheckoutReport::punchColumns())
        headers << translated(c);
    m_table->setColumnCount(static_cast<int>(headers.size()));
    m_table->setHorizontalHeaderLabels(headers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(RemarkColumn, QHeaderView::Stretch);
    // Only the owner is typed in (F2 or a double-click).
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::AnyKeyPressed);
    layout->addWidget(m_table, 1);
    auto *buttons = new QHBoxLayout;
    m_close = new QPushButton(tr("Close Out"), this);
    m_close->setObjectName(QStringLiteral("closeOutButton"));
    m_close->setToolTip(tr("Close out the chosen item: its point passes now"));
    m_export = new QPushButton(tr("Export CSV…"), this);
    m_export->setObjectName(QStringLiteral("exportPunchButton"));
    auto *done = new QPushButton(tr("Close"), this);
    buttons->addWidget(m_close);
    buttons->addWidget(m_export);
    buttons->addStretch(1);
    buttons->addWidget(done);
    layout->addLayout(buttons);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("punchMessage"));
    m_message->setWordWrap(true);
    layout->addWidget(m_message);

    connect(done, &QPushButton::clicked, this, &QDialog::close);
    connect(m_close, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (row < 0)
            return showMessage(tr("Choose the item to close out."), true);
        closeOut(row);
    });
    connect(m_export, &QPushButton::clicked, this, [this] {
        QString filter;
        const QString path = m_frame->chooseFile(
            {true, tr("Export Punch List"), CsvFileFilter::both(), {}, &filter});
        if (!path.isEmpty())
            exportCsv(path, CsvFileFilter::lineEnd(filter));
    });
    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (m_filling || item->column() != OwnerColumn)
            return;
        const int index = m_points.at(static_cast<std::size_t>(item->row()));
        if (const Status s = m_runner->setPunchOwner(index, item->text().trimmed()); !s)
            showMessage(translated(s.error().message), true);
    });
    connect(runner, &CheckoutRunner::pointChanged, this, &CheckoutPunchDialog::fill);
    fill();
    resize(820, 360);
}

QString CheckoutPunchDialog::messageText() const
{
    return m_message->text();
}

void CheckoutPunchDialog::showMessage(const QString &text, bool error)
{
    ToolPalette::showMessage(m_message, text, error);
}

void CheckoutPunchDialog::fill()
{
    // Rebuilt whole: a punch list is a few rows, and a re-test may add or mend one.
    const int current = m_table->currentRow();
    m_filling = true;
    const CheckoutReport report = CheckoutReport::of(m_runner->plan());
    m_points = m_runner->plan().punchList();
    m_table->setRowCount(static_cast<int>(report.punch.size()));
    int row = 0;
    for (const CheckoutReport::PunchRow &p : report.punch) {
        const QStringList cells = {p.address, p.name,  translated(checkoutResultMessage(p.result)),
                                   p.remark,  p.owner, translated(p.state)};
        for (int column = 0; column < static_cast<int>(cells.size()); ++column) {
            auto *item = new QTableWidgetItem(cells.at(column));
            if (column != OwnerColumn)
                item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            if (p.closed)
                item->setForeground(ToolPalette::passText(palette()));
            m_table->setItem(row, column, item);
        }
        ++row;
    }
    if (current >= 0 && current < m_table->rowCount())
        m_table->setCurrentCell(current,
                                m_table->currentColumn() < 0 ? 0 : m_table->currentColumn());
    m_filling = false;
    m_close->setEnabled(m_table->rowCount() > 0);
    m_export->setEnabled(m_table->rowCount() > 0);
}

void CheckoutPunchDialog::closeOut(int row)
{
    if (row < 0 || row >= static_cast<int>(m_points.size()))
        return;
    const int index = m_points[static_cast<std::size_t>(row)];
    const QString point = m_table->item(row, PointColumn)->text();
    if (const Status s = m_runner->closePunch(index, {}); !s)
        return showMessage(translated(s.error().message), true);
    showMessage(tr("%1 is closed out.").arg(point), false);
}

bool CheckoutPunchDialog::exportCsv(const QString &path, CsvFile::LineEnd lineEnd)
{
    const CheckoutReport report = CheckoutReport::of(m_runner->plan());
    const QString reason = SafeFile::write(
        path, report.punchCsv([](const Message &m) { return translated(m); }, lineEnd));
    if (!reason.isEmpty()) {
        showMessage(reason, true);
        return false;
    }
    showMessage(tr("Punch list written: %1").arg(QDir::toNativeSeparators(path)), false);
    return true;
}

} // namespace Fatek
