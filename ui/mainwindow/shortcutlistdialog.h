#pragma once

#include <QDialog>
#include <QKeySequence>
#include <QList>
#include <QString>

class QTableWidget;

namespace Fatek {

// Help > Keyboard Shortcuts: every action of the window that has a shortcut (menus, docks,
// tables), read from the actions themselves when the list opens, so it cannot drift from them:
// what it does, the keys, where it is (the menu, or the part of the window).
class ShortcutListDialog : public QDialog
{
    Q_OBJECT

public:
    struct Entry
    {
        QString action; // "New Connection" (no & nor …)
        QKeySequence keys;
        QString where; // "File", "Watch table", "Raw Console"
    };

    explicit ShortcutListDialog(QWidget *window);

    // The entries of `window`, sorted by place then name; one per action and keys (the same
    // action of two watch tables is listed once).
    static QList<Entry> entries(const QWidget *window);
    QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table;
};

} // namespace Fatek
