// Shared by the tst_tools_* tests that answer the tools' real questions: a hand that clicks Yes or
// No on each message box as it shows up, as a person would.
#pragma once

#include <QApplication>
#include <QMessageBox>
#include <QPointer>
#include <QStringList>
#include <QTest>
#include <QTimer>

namespace ToolsTest {

// Answers the next message boxes with `answers` in order (true: Yes), while it lives; a box
// beyond them is answered No. Their texts are kept in `questions`.
class BoxHand
{
public:
    explicit BoxHand(QList<bool> answers)
        : m_answers(std::move(answers))
    {
        // A modal box turns its own event loop: the answer comes from a timer.
        m_timer.setInterval(30);
        QObject::connect(&m_timer, &QTimer::timeout, &m_timer, [this] { answer(); });
        m_timer.start();
    }

    QStringList questions;

private:
    void answer()
    {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box || box == m_last)
            return;
        m_last = box;
        questions << box->text();
        const bool yes = !m_answers.isEmpty() && m_answers.takeFirst();
        QAbstractButton *button = box->button(yes ? QMessageBox::Yes : QMessageBox::No);
        if (!button || !button->isVisible()) {
            qWarning("the box has no visible %s button", yes ? "Yes" : "No");
            return;
        }
        QTest::mouseClick(button, Qt::LeftButton);
    }

    QList<bool> m_answers;
    QPointer<QMessageBox> m_last;
    QTimer m_timer;
};

} // namespace ToolsTest
