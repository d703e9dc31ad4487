// Issue 54, item 11: the studio in both of its languages. Keyboard accelerators ("&File",
// "通訊協定(&T)") are unique in every menu, dock and dialog, in English and in Traditional
// Chinese; the zh_TW leftovers (bit values, the snapshot's summary) read in Chinese; English
// counts say "1 row", "4 rows". The main window runs the demo PLC at 1366x768.
#include "demowindow.h"
#include "testutil.h"
#include "ui/mainwindow/languagemenu.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"
#include "uitestutil.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;

// The key of a text's accelerator ("Pro&tocol" → 't'), or nothing.
QChar acceleratorOf(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("(?<!&)&([^&\\s])"));
    const QRegularExpressionMatch m = re.match(text);
    return m.hasMatch() ? m.captured(1).at(0).toLower() : QChar();
}

// The texts with the same accelerator among `texts`, as "'t': Pro&tocol, S&tation".
QStringList clashes(const QString &where, const QStringList &texts)
{
    QMap<QChar, QStringList> byKey;
    for (const QString &text : texts) {
        if (const QChar key = acceleratorOf(text); !key.isNull())
            byKey[key] << text;
    }
    QStringList out;
    for (auto it = byKey.cbegin(); it != byKey.cend(); ++it) {
        if (it.value().size() > 1)
            out << QStringLiteral("%1: '%2' in %3")
                       .arg(where, it.key(), it.value().join(QStringLiteral(", ")));
    }
    return out;
}

// Every menu and submenu: its entries' accelerators.
QStringList menuClashes(const QMenu *menu)
{
    QStringList texts;
    QStringList out;
    for (const QAction *a : menu->actions()) {
        if (a->isSeparator() || !a->isVisible())
            continue;
        texts << a->text();
        if (a->menu())
            out << menuClashes(a->menu());
    }
    return clashes(QStringLiteral("menu \"%1\"").arg(menu->title()), texts) + out;
}

// A person's view of `root`: the labels' (with a buddy), buttons', group boxes' and tabs'
// texts of its visible controls in its own window, each dock of a main window on its own.
QStringList controlTexts(const QWidget *root)
{
    QStringList texts;
    for (const QWidget *w : root->findChildren<QWidget *>()) {
        if (!w->isVisible() || w->window() != root->window())
            continue;
        // A dock's controls are the dock's group (checked with the dock), not the window's.
        bool inOtherDock = false;
        for (const QWidget *p = w->parentWidget(); p && p != root; p = p->parentWidget())
            inOtherDock = inOtherDock || qobject_cast<const QDockWidget *>(p);
        if (inOtherDock)
            continue;
        if (const auto *label = qobject_cast<const QLabel *>(w); label && label->buddy())
            texts << label->text();
        else if (const auto *button = qobject_cast<const QAbstractButton *>(w))
            texts << button->text();
        else if (const auto *box = qobject_cast<const QGroupBox *>(w))
            texts << box->title();
        else if (const auto *tabs = qobject_cast<const QTabBar *>(w)) {
            for (int i = 0; i < tabs->count(); ++i)
                texts << tabs->tabText(i);
        }
    }
    return texts;
}

void removeTranslators()
{
    for (QTranslator *t : qApp->findChildren<QTranslator *>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
}

} // namespace

class TestUiLanguage : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;

    bool openDemo() { return UiTestUtil::openDemoWindow(m_window, false, longWait); }

    // Each page of the New Connection dialog (serial, TCP, UDP, gateway), as the person sees it.
    QStringList connectionDialogClashes()
    {
        QStringList out;
        auto *dialog = qobject_cast<QDialog *>(m_window->openTool(QStringLiteral("connection")));
        if (!dialog)
            return {QStringLiteral("no connection dialog")};
        if (!QTest::qWaitForWindowExposed(dialog))
            return {QStringLiteral("the connection dialog did not show")};
        auto *kind = dialog->findChild<QComboBox *>(QStringLiteral("linkKindCombo"));
        for (int i = 0; kind && i < kind->count(); ++i) {
            kind->setCurrentIndex(i);
            QTest::qWait(50);
            out << clashes(QStringLiteral("%1 (%2)").arg(dialog->windowTitle(), kind->itemText(i)),
                           controlTexts(dialog));
        }
        dialog->reject();
        return out;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_language"));
    }

    void cleanup()
    {
        m_window.reset();
        QSettings().clear();
        removeTranslators();
        QLocale::setDefault(QLocale::c());
    }

    void acceleratorsAreUnique_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
    }
    void acceleratorsAreUnique()
    {
        QFETCH(QString, language);
        QVERIFY(Language::install(qApp, QLocale(language)));
        QVERIFY(openDemo());
        QStringList problems;
        QStringList titles;
        for (const QAction *a : m_window->menuBar()->actions()) {
            titles << a->text();
            if (a->menu())
                problems << menuClashes(a->menu());
        }
        // The menu bar's titles and the controls of the window around the docks.
        problems << clashes(QStringLiteral("main window"),
                            titles + controlTexts(m_window->centralWidget()));
        for (const char *tool : {"control", "forcing", "console", "trend"})
            QVERIFY2(m_window->openTool(QString::fromLatin1(tool)), tool);
        QTest::qWait(300);
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>()) {
            if (dock->isVisible())
                problems << clashes(QStringLiteral("dock \"%1\"").arg(dock->windowTitle()),
                                    controlTexts(dock->widget()));
        }
        for (const char *tool : {"loopback", "program", "snapshot", "checkout"}) {
            QWidget *opened = m_window->openTool(QString::fromLatin1(tool));
            QVERIFY2(opened, tool);
            QWidget *top = opened->window();
            QVERIFY(QTest::qWaitForWindowExposed(top));
            problems << clashes(QStringLiteral("dialog \"%1\"").arg(top->windowTitle()),
                                controlTexts(top));
            top->close();
        }
        problems << connectionDialogClashes();
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    // In Chinese: a bit reads 導通/斷開 as the forcing table says it; the snapshot's summary
    // gives its date and the PLC's words in Chinese.
    void chineseLeftovers()
    {
        QVERIFY(Language::install(qApp, QLocale(QStringLiteral("zh_TW"))));
        QVERIFY(openDemo());
        WatchTableWidget *table = m_window->currentWatchTable();
        QVERIFY(table);
        const QAbstractItemModel *model = table->model();
        int bitRow = -1;
        for (int r = 0; r < model->rowCount(); ++r) {
            if (model->index(r, WatchTableModel::AddressColumn).data().toString()
                == QLatin1String("Y0"))
                bitRow = r;
        }
        QVERIFY(bitRow >= 0);
        const QModelIndex value = model->index(bitRow, WatchTableModel::ValueColumn);
        QTRY_VERIFY_WITH_TIMEOUT(value.data().toString() != QLatin1String("…"), longWait);
        const QString bit = value.data().toString();
        QVERIFY2(bit == QStringLiteral("導通") || bit == QStringLiteral("斷開"), qPrintable(bit));
        // What is edited stays in the PLC's words, which the parser reads.
        const QString edit = value.data(Qt::EditRole).toString();
        QVERIFY2(edit == QLatin1String("ON") || edit == QLatin1String("OFF"), qPrintable(edit));

        QWidget *snapshot = m_window->openTool(QStringLiteral("snapshot"));
        QVERIFY(snapshot);
        auto *ranges = snapshot->findChild<QLineEdit *>(QStringLiteral("ranges"));
        QVERIFY(ranges);
        ranges->setText(QStringLiteral("R0-99"));
        auto *take = snapshot->findChild<QPushButton *>(QStringLiteral("takeButton"));
        auto *summary = snapshot->findChild<QLabel *>(QStringLiteral("snapshotLabel"));
        QVERIFY(take && summary);
        const QString none = summary->text();
        QTRY_VERIFY_WITH_TIMEOUT(take->isEnabled(), longWait);
        take->click();
        QTRY_VERIFY_WITH_TIMEOUT(summary->text() != none, longWait);
        const QString text = summary->text();
        // The date as Chinese writes it (2026/12/7), the model's words translated.
        QVERIFY2(text.contains(QLocale(QStringLiteral("zh_TW"))
                                   .toString(QDate::currentDate(), QLocale::ShortFormat)),
                 qPrintable(text));
        QVERIFY2(!text.contains(QStringLiteral("program"))
                     && !text.contains(QStringLiteral("words")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("程式")), qPrintable(text));
    }

    // English counts: "Copied 1 row.", "Copied 4 rows.", "in 1 request".
    void englishCounts()
    {
        QVERIFY(Language::install(qApp, QLocale(QStringLiteral("en"))));
        QCOMPARE(
            QCoreApplication::translate("Fatek::WatchTableWidget", "Copied %n row(s).", nullptr, 4),
            QStringLiteral("Copied 4 rows."));
        QCOMPARE(
            QCoreApplication::translate("Fatek::WatchTableWidget", "Copied %n row(s).", nullptr, 1),
            QStringLiteral("Copied 1 row."));
        QCOMPARE(QCoreApplication::translate(
                     "Fatek::SnapshotDialog",
                     "Write %1 values of the snapshot to %2 in %n request(s), then read them back?",
                     nullptr, 1)
                     .arg(3)
                     .arg(QStringLiteral("station 1")),
                 QStringLiteral(
                     "Write 3 values of the snapshot to station 1 in 1 request, then read them "
                     "back?"));
    }
};

int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(QSize(1366, 768));
    if (!screen.isReady())
        return 1;
    QApplication app(argc, argv);
    TestUiLanguage test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_language.moc"
