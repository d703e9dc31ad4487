// Alarms in the studio (issue 50), as a person meets them at a laptop's 1366x768, against a
// fatek-sim child running the demo ladder (R1 a sine of +-1000 over 10 s): a high alarm defined on
// R1 below its peak through the row's dialog is raised, flashes in the summary and in the status
// bar's count, is acknowledged by keyboard with a comment, returns to normal, and the journal
// holds its events (the journal is a temporary file: FATEK_ALARM_JOURNAL). The definition dialog
// names a wrong definition in words, its change is undone and redone as a table edit, and operator
// mode refuses it.
#include "simchild.h"
#include "testutil.h"
#include "ui/alarm/alarmannunciator.h"
#include "ui/alarm/alarmcenter.h"
#include "ui/alarm/alarmdefinitiondialog.h"
#include "ui/alarm/alarmjournaldialog.h"
#include "ui/alarm/alarmsui.h"
#include "ui/alarm/alarmsummarymodel.h"
#include "ui/alarm/alarmsummarywidget.h"
#include "ui/common/messageline.h"
#include "ui/connection/connection.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/watch/watchtablemodel.h"
#include "uitestutil.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace Fatek;

namespace {

constexpr int longWait = 20000;
// A person types about 5 characters a second and needs a moment to aim the mouse.
constexpr int keyDelayMs = 120;
constexpr int mouseDelayMs = 300;
const QSize laptop(1366, 768);

bool onScreen(const QWidget *w)
{
    if (!w || !w->isVisible() || w->width() < 10 || w->height() < 10)
        return false;
    const QRect global(w->mapToGlobal(QPoint(0, 0)), w->size());
    return w->screen()->availableGeometry().contains(global);
}

void click(QWidget *w)
{
    QTest::mouseClick(w, Qt::LeftButton, {}, QPoint(), mouseDelayMs);
}

// A check box is clicked on its box, as a person aims (the widget may be wider than its text).
void tick(QCheckBox *box)
{
    QStyleOptionButton option;
    option.initFrom(box);
    const QRect indicator
        = box->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, box);
    QTest::mouseClick(box, Qt::LeftButton, {}, indicator.center(), mouseDelayMs);
}

void typeInto(QWidget *w, const QString &text)
{
    click(w);
    QTest::keyClicks(w, text, {}, keyDelayMs);
}

void clickCell(QTableView *view, const QModelIndex &index)
{
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(index).center(),
                      mouseDelayMs);
}

} // namespace

class TestUiAlarms : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    std::unique_ptr<TestUtil::SimChild> m_sim;
    std::unique_ptr<MainWindow> m_window;

    bool openWindow()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->setConfirmHandler([](QWidget *, const QString &) { return true; });
        m_window->show();
        if (!QTest::qWaitForWindowExposed(m_window.get()))
            return false;
        return activate();
    }

    // The main window active again, as a window manager makes it when a dialog closes (the
    // offscreen platform leaves no window active).
    bool activate()
    {
        m_window->activateWindow();
        return QTest::qWaitForWindowActive(m_window.get());
    }

    // The window on the simulator, one table polling `items` every 200 ms.
    WatchTableWidget *openTable(const QString &items)
    {
        m_sim = std::make_unique<TestUtil::SimChild>();
        QString error;
        if (!m_sim->start(QStringLiteral(FATEK_SIM_PATH), false, {QStringLiteral("--demo-ladder")},
                          &error)) {
            qWarning("%s", qPrintable(error));
            return nullptr;
        }
        if (!openWindow())
            return nullptr;
        SavedConnection saved;
        saved.name = QStringLiteral("Line 1");
        saved.settings = LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_sim->port());
        saved.station = 1;
        Connection *c = m_window->openConnection(saved, false);
        if (!QTest::qWaitFor([c] { return c->linkState() == LinkState::Connected; }, longWait))
            return nullptr;
        WatchTableWidget *table = m_window->currentWatchTable();
        table->setIntervalMs(200);
        typeInto(table->addressEdit(), items);
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        return table;
    }

    // Selects the table's row and opens its alarms with Ctrl+Shift+A.
    AlarmDefinitionDialog *openDefinitions(WatchTableWidget *table, int row)
    {
        clickCell(table->view(), table->viewIndex(table->model()->index(row, 1)));
        QTest::keyClick(table->view(), Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier,
                        keyDelayMs);
        AlarmDefinitionDialog *dialog = nullptr;
        // Null when it did not open: the caller's QVERIFY says so.
        (void)QTest::qWaitFor(
            [&] {
                dialog = table->findChild<AlarmDefinitionDialog *>();
                return dialog && dialog->isVisible();
            },
            5000);
        return dialog;
    }

    static QPushButton *okButton(QDialog *dialog)
    {
        return dialog->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    }

    template<typename T>
    static T *field(QWidget *dialog, const QString &name)
    {
        return dialog->findChild<T *>(name);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        TestUtil::useTestSettings(m_dir.path(), QStringLiteral("tst_ui_alarms"));
        QCOMPARE(QGuiApplication::primaryScreen()->size(), laptop);
    }

    void cleanup()
    {
        m_window.reset(); // deleted, not closed: no question on the way out
        m_sim.reset();
    }

    // The test: raised, flashing, acknowledged by keyboard, normal again, journaled.
    void raiseAcknowledgeReturn()
    {
        WatchTableWidget *table = openTable(QStringLiteral("R1"));
        QVERIFY(table);
        WatchTableModel *model = table->model();
        QTRY_COMPARE(model->rowCount(), 1);

        AlarmDefinitionDialog *dialog = openDefinitions(table, 0);
        QVERIFY(dialog);
        QVERIFY(onScreen(dialog));
        // A number item: the limit kinds and quality, no bit kinds.
        QVERIFY(field<QCheckBox>(dialog, QStringLiteral("alarm_high")));
        QVERIFY(!field<QCheckBox>(dialog, QStringLiteral("alarm_on")));
        tick(field<QCheckBox>(dialog, QStringLiteral("alarm_high")));
        typeInto(field<QLineEdit>(dialog, QStringLiteral("limit_high")), QStringLiteral("800"));
        auto *priority = field<QComboBox>(dialog, QStringLiteral("priority_high"));
        priority->setFocus(Qt::TabFocusReason);
        QTest::keyClick(priority, Qt::Key_Home, {}, keyDelayMs); // critical
        typeInto(field<QLineEdit>(dialog, QStringLiteral("message_high")),
                 QStringLiteral("R1 above 800"));
        typeInto(field<QLineEdit>(dialog, QStringLiteral("group_high")), QStringLiteral("Demo"));
        click(okButton(dialog));
        QTRY_VERIFY(!dialog->isVisible());
        QVERIFY(activate());
        QCOMPARE(model->item(0).alarms.size(), 1);
        QCOMPARE(model->item(0).alarms.first().limit, 800.0);
        QCOMPARE(model->item(0).alarms.first().priority, AlarmPriority::Critical);
        // The bell beside the address says the row has alarms.
        QVERIFY(!model->index(0, WatchTableModel::AddressColumn)
                     .data(Qt::DecorationRole)
                     .value<QIcon>()
                     .isNull());

        // The sine passes 800 within one period (10 s): the count shows in the status bar, and
        // flashes.
        AlarmsUi *alarms = m_window->alarms();
        AlarmAnnunciator *count = alarms->annunciator();
        QTRY_VERIFY_WITH_TIMEOUT(count->isVisible(), longWait);
        QCOMPARE(count->count(), 1);
        QVERIFY(onScreen(count));
        QVERIFY(count->text().contains(QLatin1String("1 unacknowledged alarm")));
        const bool countFlash = count->isFlashOn();
        QTRY_VERIFY_WITH_TIMEOUT(count->isFlashOn() != countFlash, 2000);
        QVERIFY(count->beeps() >= 1);

        // A click on the count opens the summary: the alarm is there, flashing.
        click(count);
        AlarmSummaryWidget *summary = alarms->summary();
        QTRY_VERIFY(onScreen(summary->view()));
        QTableView *view = summary->view();
        QTRY_COMPARE(view->model()->rowCount(), 1);
        const QModelIndex first = view->model()->index(0, AlarmSummaryModel::MessageColumn);
        QCOMPARE(first.data().toString(), QStringLiteral("R1 above 800"));
        QCOMPARE(view->model()->index(0, AlarmSummaryModel::PriorityColumn).data().toString(),
                 QStringLiteral("critical"));
        QVERIFY(Alarms::isUnacked(
            static_cast<AlarmState>(first.data(AlarmSummaryModel::StateRole).toInt())));
        const bool rowFlash = first.data(AlarmSummaryModel::FlashRole).toBool();
        QTRY_VERIFY_WITH_TIMEOUT(
            view->model()->index(0, 0).data(AlarmSummaryModel::FlashRole).toBool() != rowFlash,
            2000);
        if (const QString shot = qEnvironmentVariable("FATEK_ALARM_SCREENSHOT"); !shot.isEmpty())
            QVERIFY(m_window->grab().save(shot, "PNG"));

        // By keyboard: the count's click put the focus in the list; Home picks the alarm, the
        // comment is typed, Ctrl+K acknowledges.
        QTRY_VERIFY(view->hasFocus());
        QTest::keyClick(view, Qt::Key_Home, {}, keyDelayMs);
        QVERIFY(view->selectionModel()->isRowSelected(0, {}));
        typeInto(summary->commentEdit(), QStringLiteral("pump checked"));
        QTest::keyClick(summary->commentEdit(), Qt::Key_K, Qt::ControlModifier, keyDelayMs);
        QTRY_VERIFY(summary->commentEdit()->text().isEmpty());
        // No longer flashing nor counted; back to normal (off the list) once R1 is below 800.
        QTRY_VERIFY(!count->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(view->model()->rowCount(), 0, longWait);

        // The journal: raised, acknowledged (who and the comment), returned.
        click(summary->findChild<QPushButton *>(QStringLiteral("journalButton")));
        AlarmJournalDialog *journal = m_window->findChild<AlarmJournalDialog *>();
        QVERIFY(journal);
        QTRY_VERIFY(journal->isVisible());
        QVERIFY(onScreen(journal));
        QSignalSpy queried(journal, &AlarmJournalDialog::queried);
        QList<AlarmEventType> types;
        const AlarmEvent *ack = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                click(journal->findChild<QPushButton *>(QStringLiteral("journalShow")));
                if (!queried.wait(5000))
                    return false;
                types.clear();
                ack = nullptr;
                for (const AlarmEvent &e : journal->model()->events()) {
                    types.append(e.type);
                    if (e.type == AlarmEventType::Acknowledged)
                        ack = &e;
                }
                return types.contains(AlarmEventType::Returned) && ack;
            }(),
            longWait);
        QCOMPARE(types.first(), AlarmEventType::Raised);
        QVERIFY(types.contains(AlarmEventType::Acknowledged));
        QCOMPARE(ack->comment, QStringLiteral("pump checked"));
        QVERIFY(!ack->user.isEmpty());
        QCOMPARE(ack->connection, QStringLiteral("Line 1"));
        QCOMPARE(ack->alarmId, QStringLiteral("1-R1-high"));
        const QString csv = m_dir.filePath(QStringLiteral("alarms.csv"));
        QCOMPARE(journal->exportCsv(csv), QString());
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY(text.contains(QLatin1String("pump checked")));
        QVERIFY(text.contains(QLatin1String("1-R1-high")));
        // A file for Excel on Windows: the byte order mark, and CRLF when that type is chosen.
        file.seek(0);
        QVERIFY(file.readAll().startsWith("\xEF\xBB\xBFtime,connection,alarm,"));
        file.close();
        QCOMPARE(journal->exportCsv(csv, CsvFile::LineEnd::CrLf), QString());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray crlf = file.readAll();
        QVERIFY2(crlf.startsWith("\xEF\xBB\xBFtime,connection,alarm,") && crlf.contains("\r\n")
                     && crlf.count('\n') == crlf.count("\r\n"),
                 crlf.constData());
    }

    // The dialog names a wrong definition in words and stays; the change is one undoable step;
    // operator mode refuses the dialog.
    void definitionDialog()
    {
        QVERIFY(openWindow());
        WatchTableWidget *table = m_window->currentWatchTable();
        typeInto(table->addressEdit(), QStringLiteral("R100 X0"));
        QTest::keyClick(table->addressEdit(), Qt::Key_Return);
        WatchTableModel *model = table->model();
        QTRY_COMPARE(model->rowCount(), 2);

        AlarmDefinitionDialog *dialog = openDefinitions(table, 0);
        QVERIFY(dialog);
        tick(field<QCheckBox>(dialog, QStringLiteral("alarm_high")));
        typeInto(field<QLineEdit>(dialog, QStringLiteral("limit_high")), QStringLiteral("100"));
        tick(field<QCheckBox>(dialog, QStringLiteral("alarm_low")));
        typeInto(field<QLineEdit>(dialog, QStringLiteral("limit_low")), QStringLiteral("200"));
        click(okButton(dialog));
        // Low above high: refused, in words, and the dialog stays for the correction.
        QVERIFY(dialog->isVisible());
        QVERIFY2(!dialog->error().isEmpty(), "no error shown");
        QVERIFY(model->item(0).alarms.isEmpty());
        QLineEdit *low = field<QLineEdit>(dialog, QStringLiteral("limit_low"));
        low->selectAll();
        QTest::keyClicks(low, QStringLiteral("10"), {}, keyDelayMs);
        // A deadband below zero is refused too.
        QLineEdit *deadband = field<QLineEdit>(dialog, QStringLiteral("deadband_high"));
        typeInto(deadband, QString());
        deadband->selectAll();
        QTest::keyClicks(deadband, QStringLiteral("-5"), {}, keyDelayMs);
        click(okButton(dialog));
        QVERIFY(dialog->isVisible());
        QVERIFY(!dialog->error().isEmpty());
        deadband->selectAll();
        QTest::keyClicks(deadband, QStringLiteral("5"), {}, keyDelayMs);
        click(okButton(dialog));
        QTRY_VERIFY(!dialog->isVisible());
        QVERIFY(activate());
        QCOMPARE(model->item(0).alarms.size(), 2);

        // A discrete offers the bit alarms, not the limits.
        AlarmDefinitionDialog *bits = openDefinitions(table, 1);
        QVERIFY(bits);
        QVERIFY(field<QCheckBox>(bits, QStringLiteral("alarm_on")));
        QVERIFY(!field<QCheckBox>(bits, QStringLiteral("alarm_high")));
        click(bits->findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Cancel));
        QTRY_VERIFY(!bits->isVisible());
        QVERIFY(activate());

        // Undo and redo as any edit of the table (Ctrl+Z, Ctrl+Y in the table).
        clickCell(table->view(), table->viewIndex(model->index(0, 1)));
        QTest::keyClick(table->view(), Qt::Key_Z, Qt::ControlModifier, keyDelayMs);
        QTRY_VERIFY(model->item(0).alarms.isEmpty());
        QTest::keyClick(table->view(), Qt::Key_Y, Qt::ControlModifier, keyDelayMs);
        QTRY_COMPARE(model->item(0).alarms.size(), 2);

        // Operator mode: no dialog, and the status bar says why.
        QAction *operatorMode = nullptr;
        for (QAction *a : m_window->findChildren<QAction *>()) {
            if (a->isCheckable() && a->text().contains(QLatin1String("Operator Mode")))
                operatorMode = a;
        }
        QVERIFY(operatorMode);
        operatorMode->trigger();
        QVERIFY(m_window->isReadOnly());
        clickCell(table->view(), table->viewIndex(model->index(0, 1)));
        QTest::keyClick(table->view(), Qt::Key_A, Qt::ControlModifier | Qt::ShiftModifier,
                        keyDelayMs);
        QTest::qWait(500);
        const auto open = table->findChildren<AlarmDefinitionDialog *>();
        for (AlarmDefinitionDialog *d : open)
            QVERIFY(!d->isVisible());
        QVERIFY(m_window->statusBar()->currentMessage().contains(QLatin1String("Operator mode")));
        QCOMPARE(model->item(0).alarms.size(), 2);
    }
};

// A screen of a laptop's size, and the journal in a temporary folder, before the application.
int main(int argc, char *argv[])
{
    const UiTestUtil::OffscreenScreen screen(laptop);
    if (!screen.isReady())
        return 1;
    QTemporaryDir journalDir;
    if (!journalDir.isValid())
        return 1;
    qputenv("FATEK_ALARM_JOURNAL", journalDir.filePath(QStringLiteral("alarms.sqlite")).toUtf8());
    QApplication app(argc, argv);
    TestUiAlarms test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_ui_alarms.moc"
