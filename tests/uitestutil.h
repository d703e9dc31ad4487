#pragma once

#include <QSize>
#include <QString>
#include <QTemporaryDir>

#include <functional>

class QLabel;
class QWidget;

namespace UiTestUtil {

// Runs `answer` on the first modal dialog that shows up while `action` runs (modal dialogs have
// their own event loop, so the answer must come from a timer, as a person's hand would). Returns
// the question's text when the dialog is a QMessageBox.
QString answerModal(const std::function<void()> &action,
                    const std::function<void(QWidget *)> &answer);

// An answer for answerModal: clicks the dialog's button with this object name.
std::function<void(QWidget *)> clickButton(const char *objectName);

// In a raw console: clicks the send line, types `frame` (hex) at a person's pace and clicks Send.
// Returns the line that shows what was sent and what came back (nullptr: no send line).
QLabel *sendRawFrame(QWidget *console, const QString &frame);

// A screen of `size` (a laptop's, 1366x768) for the offscreen platform, which reads it from a
// configuration file: made before the QApplication, kept while it runs. The file is in the
// working folder and named relative to it, since the platform's arguments are separated by ':'
// and a Windows path ("C:\\...") would cut the name short.
class OffscreenScreen
{
public:
    explicit OffscreenScreen(QSize size);
    // The file is written and QT_QPA_PLATFORM names it.
    bool isReady() const { return m_ready; }

private:
    QTemporaryDir m_dir;
    bool m_ready = false;
};

} // namespace UiTestUtil
