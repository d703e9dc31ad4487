#include "tooldialogframe.h"

#include "ui/common/messageline.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace Fatek {

ToolDialogFrame::ToolDialogFrame(QDialog *dialog, int messageLines, const QString &messageName,
                                 std::function<void()> cancel)
    : QObject(dialog)
    , m_dialog(dialog)
{
    auto *layout = new QVBoxLayout(dialog);
    m_targetLabel = new QLabel(dialog);
    m_targetLabel->setObjectName(QStringLiteral("targetLabel"));
    layout->addWidget(m_targetLabel);
    m_content = new QVBoxLayout;
    layout->addLayout(m_content, 1);
    m_message = new MessageLine(messageLines, dialog);
    m_message->setObjectName(messageName);
    layout->addWidget(m_message);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    layout->addWidget(box);
    connect(box, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    connect(dialog, &QDialog::rejected, this, [cancel = std::move(cancel)] { cancel(); });
    setTarget(PlcTarget());
}

void ToolDialogFrame::setTarget(const PlcTarget &target, const QString &note)
{
    m_target = target;
    QString text = target.isDirect() ? tr("Station %1 on \u201c%2\u201d")
                                           .arg(target.station())
                                           .arg(target.connectionName())
                                     : tr("No connection: choose a connection and a station.");
    if (target.isDirect() && !note.isEmpty())
        text += QLatin1Char(' ') + note;
    m_targetLabel->setText(text);
}

QString ToolDialogFrame::targetText() const
{
    return ToolConfirmation::target(m_target);
}

void ToolDialogFrame::showMessage(const QString &text, bool error)
{
    m_message->setMessage(text, error);
}

void ToolDialogFrame::clearMessage()
{
    m_message->clear();
}

QString ToolDialogFrame::messageText() const
{
    return m_message->text();
}

bool ToolDialogFrame::messageIsError() const
{
    return m_message->isError();
}

bool ToolDialogFrame::ask(const QString &title, const QString &question) const
{
    return ToolConfirmation::ask(m_dialog, title, question, m_confirmer);
}

void ToolDialogFrame::setUnsaved(std::function<QString()> describe, std::function<bool()> save)
{
    m_describeUnsaved = std::move(describe);
    m_saveUnsaved = std::move(save);
}

bool ToolDialogFrame::mayDiscard() const
{
    const QString what = m_describeUnsaved ? m_describeUnsaved() : QString();
    if (what.isEmpty())
        return true;
    if (m_confirmer)
        return m_confirmer(what);
    // As an editor asks about an unsaved document: Save is the default, Esc keeps it.
    QMessageBox box(QMessageBox::Warning, m_dialog->windowTitle(), what, QMessageBox::NoButton,
                    m_dialog);
    box.setObjectName(QStringLiteral("unsavedBox"));
    box.setInformativeText(tr("Save it first? Discarded, it is lost."));
    QPushButton *save = box.addButton(tr("&Save…"), QMessageBox::AcceptRole);
    save->setObjectName(QStringLiteral("saveButton"));
    QPushButton *discard = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
    discard->setObjectName(QStringLiteral("discardButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    cancel->setObjectName(QStringLiteral("cancelButton"));
    box.setDefaultButton(save);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == discard)
        return true;
    if (box.clickedButton() == save)
        return m_saveUnsaved && m_saveUnsaved();
    return false;
}

std::optional<QString> ToolDialogFrame::askText(const QString &title, const QString &question,
                                                const QString &text) const
{
    if (m_textAsker)
        return m_textAsker(question, text);
    bool ok = false;
    const QString answer
        = QInputDialog::getText(m_dialog, title, question, QLineEdit::Normal, text, &ok);
    if (!ok)
        return std::nullopt;
    return answer;
}

QString ToolDialogFrame::chooseFile(const FileQuestion &question) const
{
    if (m_chooser)
        return m_chooser(question);
    return question.save
               ? QFileDialog::getSaveFileName(m_dialog, question.title, question.suggested,
                                              question.filter, question.selectedFilter)
               : QFileDialog::getOpenFileName(m_dialog, question.title, question.suggested,
                                              question.filter, question.selectedFilter);
}

} // namespace Fatek
