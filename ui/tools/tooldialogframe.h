#pragma once

#include "core/plant/plctarget.h"
#include "ui/common/toolconfirmation.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>

class QDialog;
class QLabel;
class QVBoxLayout;

namespace Fatek {

class MessageLine;

// The frame every commissioning dialog shares (Loopback Test, Program Backup / Restore, Memory
// Snapshot, I/O Checkout): the target line at the top, the message line and Close at the bottom,
// the dialog's own controls between them (content()). Closing the dialog (Close, Esc, the
// window's button) cancels its running job: nothing goes on behind the person's back; a dialog
// that holds unsaved work asks first (setUnsaved, mayDiscard). It holds
// the target, asks the dialog's questions and picks its files, each with an automatic answer for
// tests so that no modal dialog blocks them.
class ToolDialogFrame : public QObject
{
    Q_OBJECT

public:
    // A file the dialog asks for: to open or to save, the file dialog's title and filter, the
    // name a save suggests.
    struct FileQuestion
    {
        bool save = false;
        QString title;
        QString filter;
        QString suggested;
        // Where the filter the person chose is put (a save as CSV: which line ends); may be null.
        QString *selectedFilter = nullptr;
    };
    // Returns the chosen path; empty: the person cancelled.
    using FileChooser = std::function<QString(const FileQuestion &question)>;
    // A line of text the dialog asks for (a remark, a reason, a prefix): the question and the
    // text it starts with; nothing: the person cancelled.
    using TextAsker
        = std::function<std::optional<QString>(const QString &question, const QString &text)>;

    // Lays `dialog` out; `cancel` stops its job when it is closed. The message line keeps
    // `messageLines` lines and is named `messageName` (tests and the translation check find it).
    ToolDialogFrame(QDialog *dialog, int messageLines, const QString &messageName,
                    std::function<void()> cancel);

    QDialog *dialog() const { return m_dialog; }
    // Where the dialog puts its own controls (between the target line and the message line).
    QVBoxLayout *content() const { return m_content; }

    // Shows "Station 1 on “Line 3”", or that there is no connection; `note` follows the station
    // (the dialog's operator-mode remark) when the tools can talk to the PLC.
    void setTarget(const PlcTarget &target, const QString &note = {});
    const PlcTarget &target() const { return m_target; }
    // How a question names the target: "station 1 on “Line 3 (TCP 10.0.0.5:500)”".
    QString targetText() const;

    void showMessage(const QString &text, bool error);
    void clearMessage();
    QString messageText() const;
    bool messageIsError() const;

    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    // Yes/No, default No (or the confirmer's answer).
    bool ask(const QString &title, const QString &question) const;

    // What the dialog holds that is in no file yet, in a sentence ("The memory snapshot of 11,378
    // values taken … is not saved."; empty: nothing), and how to save it (false: not saved).
    void setUnsaved(std::function<QString()> describe, std::function<bool()> save);
    // What the dialog holds may be dropped (closed, replaced, the main window quits): nothing is
    // unsaved, or the person saved it or chose Discard; false: Cancel, keep it. The confirmer of
    // the tests answers instead (true: discard).
    bool mayDiscard() const;
    // Whether the dialog holds something unsaved now.
    bool hasUnsaved() const { return m_describeUnsaved && !m_describeUnsaved().isEmpty(); }

    void setTextAsker(TextAsker asker) { m_textAsker = std::move(asker); }
    // An input dialog (or the asker's answer); nothing: cancelled.
    std::optional<QString> askText(const QString &title, const QString &question,
                                   const QString &text = {}) const;

    // What the dialog must finish before it goes, as the main window asks before it quits: true
    // while it holds something of the PLC's it is undoing (an output forced, being released). The
    // dialog's reject() starts it and closes the dialog once it is done; the window closes after.
    void setSettling(std::function<bool()> settling) { m_settling = std::move(settling); }
    bool isSettling() const { return m_settling && m_settling(); }

    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    // The file dialog (or the chooser's answer); empty: cancelled.
    QString chooseFile(const FileQuestion &question) const;

private:
    QDialog *m_dialog;
    QVBoxLayout *m_content;
    QLabel *m_targetLabel;
    MessageLine *m_message;
    PlcTarget m_target;
    Confirmer m_confirmer;
    FileChooser m_chooser;
    TextAsker m_textAsker;
    std::function<bool()> m_settling;
    std::function<QString()> m_describeUnsaved;
    std::function<bool()> m_saveUnsaved;
};

} // namespace Fatek
