#include "watchtablewriter.h"

#include "ui/common/toolconfirmation.h"
#include "ui/common/uitext.h"
#include "watchtablemodel.h"
#include "watchtablewidget.h"

#include <QInputDialog>
#include <QLineEdit>
#include <QPointer>
#include <QTime>

namespace Fatek {

WatchTableWriter::WatchTableWriter(WatchTableModel *model, WatchTableWidget *table)
    : QObject(table)
    , m_model(model)
    , m_table(table)
{}

void WatchTableWriter::write(int row, quint64 raw)
{
    const WatchItemSpec item = m_model->item(row);
    const QString address = QString::fromStdString(item.address.toString());
    const QString text
        = ValueFormat::format(raw, m_model->valueWidth(row), item.format, item.swapWords);
    const QString what = tr("%1 (station %2) = %3").arg(address).arg(item.station).arg(text);
    Connection *connection = m_table->connection();
    if (!connection) {
        Q_EMIT message(tr("Cannot write %1: the table has no connection.").arg(what), true);
        return;
    }
    // In operator mode the link refuses the write with its own message: no question first.
    if (m_table->confirmWrites() && !connection->isReadOnly()) {
        const QString question = tr("Write %1 to the PLC on %2?").arg(what, connection->name());
        // One rule for every question before the PLC changes: the safe answer is the default,
        // so a second Enter after typing the value does not write.
        const bool go = m_confirm ? m_confirm(m_table, question)
                                  : ToolConfirmation::ask(m_table, tr("Write Value"), question, {});
        if (!go) {
            Q_EMIT message(tr("Write of %1 cancelled.").arg(what), false);
            return;
        }
    }
    // Answers meant for a connection the table has left since are dropped.
    connection->link()->write(
        item, raw, this,
        [this, rowKey = m_model->rowKey(row), what,
         written = QPointer<Connection>(connection)](const LinkWriteResult &result) {
            if (written == m_table->connection())
                onWritten(rowKey, what, result);
        });
    Q_EMIT message(tr("Writing %1 …").arg(what), false);
}

void WatchTableWriter::onWritten(quint64 rowKey, const QString &what, const LinkWriteResult &result)
{
    // Unknown (sent, not answered) is not a failure: the value is read back and this comes again,
    // final, with what the PLC holds.
    QString outcome;
    if (result.ok)
        outcome = result.error.empty() ? tr("Wrote %1.").arg(what)
                                       : tr("Wrote %1. %2").arg(what, translated(result.error));
    else if (result.outcome == ChangeOutcome::Unknown)
        outcome = tr("Write of %1: %2").arg(what, translated(result.error));
    else
        outcome = tr("Write of %1 failed: %2").arg(what, translated(result.error));
    const int row = m_model->rowOfKey(rowKey);
    if (row >= 0)
        m_model->setWriteOutcome(
            row,
            tr("%1 %2").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), outcome));
    Q_EMIT message(outcome, !result.ok);
    if (result.outcome == ChangeOutcome::Refused)
        Q_EMIT refused(what);
}

void WatchTableWriter::askAndWrite(int row)
{
    const WatchItemSpec item = m_model->item(row);
    // Operator mode: say so at once instead of asking for a value that will be refused.
    if (m_table->connection() && m_table->connection()->isReadOnly()) {
        Q_EMIT message(tr("Operator mode (read-only): %1 cannot be written.")
                           .arg(QString::fromStdString(item.address.toString())),
                       true);
        return;
    }
    bool ok = false;
    const QString text = QInputDialog::getText(
        m_table, tr("Write Value"),
        tr("New value for %1 (%2; hex as 0x1A or 1Ah):")
            .arg(QString::fromStdString(item.address.toString()), UiText::format(item.format)),
        QLineEdit::Normal, m_model->valueText(row), &ok);
    if (ok)
        m_model->setData(m_model->index(row, WatchTableModel::ValueColumn), text);
}

} // namespace Fatek
