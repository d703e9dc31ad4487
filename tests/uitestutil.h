#pragma once

#include <QString>

#include <functional>

class QWidget;

namespace UiTestUtil {

// Runs `answer` on the first modal dialog that shows up while `action` runs (modal dialogs have
// their own event loop, so the answer must come from a timer, as a person's hand would). Returns
// the question's text when the dialog is a QMessageBox.
QString answerModal(const std::function<void()> &action,
                    const std::function<void(QWidget *)> &answer);

// An answer for answerModal: clicks the dialog's button with this object name.
std::function<void(QWidget *)> clickButton(const char *objectName);

} // namespace UiTestUtil
