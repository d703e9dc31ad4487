#pragma once

#include <QObject>
#include <QPointer>

class QMainWindow;
class QMenu;

namespace Fatek {

class ShortcutListDialog;
class UserGuideDialog;

// The Help menu: the user guide (docs/ built into the program, readable offline), the keyboard
// shortcuts (listed from the window's own actions, so the list cannot drift from them) and About.
class HelpMenu : public QObject
{
    Q_OBJECT

public:
    // Adds the menu to `window`'s menu bar.
    explicit HelpMenu(QMainWindow *window);

    // Shows (or raises) the user guide at `page` ("gui.md", "guide/forcing.md"; empty: the
    // start page). Returns the dialog.
    UserGuideDialog *showGuide(const QString &page = {});
    ShortcutListDialog *showShortcuts();

private:
    QMainWindow *m_window;
    QPointer<UserGuideDialog> m_guide;
    QPointer<ShortcutListDialog> m_shortcuts;
};

} // namespace Fatek
