#include "helpmenu.h"

#include "shortcutlistdialog.h"
#include "userguidedialog.h"

#include <QAction>
#include <QApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

namespace Fatek {

HelpMenu::HelpMenu(QMainWindow *window)
    : QObject(window)
    , m_window(window)
{
    QMenu *help = window->menuBar()->addMenu(tr("&Help"));
    help->setObjectName(QStringLiteral("helpMenu"));
    QAction *guide = help->addAction(tr("&User Guide"), this, [this] { showGuide(); });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence(Qt::Key_F1));
    QAction *keys = help->addAction(tr("&Keyboard Shortcuts"), this, [this] { showShortcuts(); });
    keys->setObjectName(QStringLiteral("shortcutListAction"));
    help->addSeparator();
    help->addAction(tr("&About FATEK Studio"), this, [this] {
        QMessageBox::about(m_window, tr("About FATEK Studio"),
                           tr("FATEK Studio %1\nCommissioning and monitoring tool for FATEK PLCs.")
                               .arg(QApplication::applicationVersion()));
    });
}

UserGuideDialog *HelpMenu::showGuide(const QString &page)
{
    if (!m_guide) {
        m_guide = new UserGuideDialog(m_window);
        m_guide->setObjectName(QStringLiteral("userGuideDialog"));
        m_guide->setAttribute(Qt::WA_DeleteOnClose);
    }
    if (!page.isEmpty())
        m_guide->showPage(page);
    m_guide->show();
    m_guide->raise();
    m_guide->activateWindow();
    return m_guide;
}

ShortcutListDialog *HelpMenu::showShortcuts()
{
    // Made afresh each time: it lists the actions as they are now (a new table adds its own).
    delete m_shortcuts;
    m_shortcuts = new ShortcutListDialog(m_window);
    m_shortcuts->setObjectName(QStringLiteral("shortcutListDialog"));
    m_shortcuts->setAttribute(Qt::WA_DeleteOnClose);
    m_shortcuts->show();
    return m_shortcuts;
}

} // namespace Fatek
