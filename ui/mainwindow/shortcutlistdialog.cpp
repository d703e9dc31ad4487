#include "shortcutlistdialog.h"

#include "ui/watch/watchtablewidget.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QHash>
#include <QHeaderView>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <tuple>

namespace Fatek {

namespace {

// "&Save Watch List…" -> "Save Watch List": how the action is named in a sentence.
QString plainText(QString text)
{
    text.replace(QLatin1String("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QStringLiteral("\x01"), QStringLiteral("&"));
    // zh_TW menus carry the accelerator as "(&F)".
    static const QRegularExpression accelerator(QStringLiteral("\\(\\w\\)$"));
    text.remove(accelerator);
    text.remove(QChar(0x2026));
    return text.trimmed();
}

// The menu bar's menus as "File", "Tools ▸ Language": the place of each of their actions.
void collectMenus(const QMenu *menu, const QString &path, QHash<const QAction *, QString> *where)
{
    for (QAction *a : menu->actions()) {
        if (a->menu())
            collectMenus(a->menu(), path + QStringLiteral(" \u25b8 ") + plainText(a->text()),
                         where);
        else if (!where->contains(a))
            where->insert(a, path);
    }
}

// An action outside the menus: the dock it is in, or the watch table.
QString placeOf(const QAction *action)
{
    for (const QObject *o = action->parent(); o; o = o->parent()) {
        if (qobject_cast<const WatchTableWidget *>(o))
            return ShortcutListDialog::tr("Watch table");
        if (const auto *dock = qobject_cast<const QDockWidget *>(o))
            return plainText(dock->toggleViewAction()->text());
    }
    return ShortcutListDialog::tr("Main window");
}

} // namespace

QList<ShortcutListDialog::Entry> ShortcutListDialog::entries(const QWidget *window)
{
    QHash<const QAction *, QString> where;
    if (const auto *main = qobject_cast<const QMainWindow *>(window)) {
        for (QAction *a : main->menuBar()->actions()) {
            if (a->menu())
                collectMenus(a->menu(), plainText(a->text()), &where);
        }
    }
    QList<Entry> list;
    QSet<QString> seen;
    auto add = [&](const QAction *a, const QString &place) {
        for (const QKeySequence &keys : a->shortcuts()) {
            if (keys.isEmpty())
                continue;
            const Entry e{plainText(a->text()), keys, place};
            const QString key
                = e.action + QLatin1Char('\n') + keys.toString() + QLatin1Char('\n') + e.where;
            if (e.action.isEmpty() || seen.contains(key))
                continue;
            seen.insert(key);
            list.append(e);
        }
    };
    for (auto it = where.cbegin(); it != where.cend(); ++it)
        add(it.key(), it.value());
    for (const QAction *a : window->findChildren<QAction *>()) {
        if (!where.contains(a))
            add(a, placeOf(a));
    }
    std::sort(list.begin(), list.end(), [](const Entry &a, const Entry &b) {
        return std::tie(a.where, a.action) < std::tie(b.where, b.action);
    });
    return list;
}

ShortcutListDialog::ShortcutListDialog(QWidget *window)
    : QDialog(window)
{
    setWindowTitle(tr("Keyboard Shortcuts"));
    auto *layout = new QVBoxLayout(this);
    m_table = new QTableWidget(this);
    m_table->setObjectName(QStringLiteral("shortcutTable"));
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("Action"), tr("Where")});
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    const QList<Entry> list = entries(window);
    m_table->setRowCount(static_cast<int>(list.size()));
    for (int r = 0; r < list.size(); ++r) {
        const Entry &e = list.at(r);
        m_table->setItem(r, 0, new QTableWidgetItem(e.keys.toString(QKeySequence::NativeText)));
        m_table->setItem(r, 1, new QTableWidgetItem(e.action));
        m_table->setItem(r, 2, new QTableWidgetItem(e.where));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(box);
    // Tall enough for most of the list on a laptop, as wide as its columns.
    int width = 0;
    for (int c = 0; c < m_table->columnCount(); ++c)
        width += m_table->columnWidth(c);
    resize(std::max(520, width + 60), 640);
}

} // namespace Fatek
