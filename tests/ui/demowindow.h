#pragma once

#include "ui/mainwindow/mainwindow.h"

#include <QTest>

#include <memory>

namespace UiTestUtil {

// The main window as on a first start: every confirmation answered yes, shown (maximized when
// asked), the demo PLC connected and its table polling. False when it was not exposed or showed
// no value within `waitMs`.
inline bool openDemoWindow(std::unique_ptr<Fatek::MainWindow> &window, bool maximized, int waitMs)
{
    window = std::make_unique<Fatek::MainWindow>();
    window->setConfirmHandler([](QWidget *, const QString &) { return true; });
    if (maximized)
        window->showMaximized();
    else
        window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        return false;
    window->startDemo();
    return QTest::qWaitFor([&window] { return window->hasValues(); }, waitMs);
}

} // namespace UiTestUtil
