#include "uitestutil.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>
#include <QTimer>

namespace UiTestUtil {

QString answerModal(const std::function<void()> &action,
                    const std::function<void(QWidget *)> &answer)
{
    QString seen;
    bool answered = false;
    QTimer hand;
    hand.setInterval(50);
    QObject::connect(&hand, &QTimer::timeout, &hand, [&] {
        QWidget *modal = QApplication::activeModalWidget();
        if (!modal || answered)
            return;
        hand.stop();
        if (auto *box = qobject_cast<QMessageBox *>(modal))
            seen = box->text();
        QTest::qWait(300); // reading the question
        answered = true;
        answer(modal);
    });
    hand.start();
    action();
    // The question may open after the action returns (a queued write): wait for the hand.
    if (!QTest::qWaitFor([&] { return answered; }, 10000))
        qWarning("no question showed up");
    hand.stop();
    return seen;
}

std::function<void(QWidget *)> clickButton(const char *objectName)
{
    return [objectName](QWidget *modal) {
        auto *button = modal->findChild<QPushButton *>(QLatin1String(objectName));
        if (!button) {
            qWarning("the dialog has no button %s", objectName);
            return;
        }
        QTest::mouseClick(button, Qt::LeftButton);
    };
}

QLabel *sendRawFrame(QWidget *console, const QString &frame)
{
    auto *input = console->findChild<QLineEdit *>(QStringLiteral("sendInput"));
    auto *send = console->findChild<QPushButton *>(QStringLiteral("sendButton"));
    auto *result = console->findChild<QLabel *>(QStringLiteral("sendResult"));
    if (!input || !send || !result)
        return nullptr;
    QTest::mouseClick(input, Qt::LeftButton);
    QTest::keyClicks(input, frame, {}, 20);
    QTest::mouseClick(send, Qt::LeftButton);
    return result;
}

OffscreenScreen::OffscreenScreen(QSize size)
    : m_dir(QDir::current().filePath(QStringLiteral("screen-XXXXXX")))
{
    const QString config
        = QDir::current().relativeFilePath(m_dir.filePath(QStringLiteral("screen.json")));
    QFile file(config);
    if (!m_dir.isValid() || !file.open(QIODevice::WriteOnly))
        return;
    file.write(QStringLiteral("{\"screens\": [{\"name\": \"laptop\", \"x\": 0, \"y\": 0, "
                              "\"width\": %1, \"height\": %2, \"logicalDpi\": 96, "
                              "\"logicalBaseDpi\": 96, \"dpr\": 1}]}")
                   .arg(size.width())
                   .arg(size.height())
                   .toUtf8());
    m_ready = file.flush();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + QFile::encodeName(config));
}

} // namespace UiTestUtil
