// The alarm summary's model with 1,000 active alarms (issue 50): they arrive as one insert, update
// with one dataChanged per run of rows (never a reset), flash with one dataChanged per run of
// unacknowledged rows and nothing for the others, and go as removals; the summary's filters.
#include "ui/alarm/alarmsummarymodel.h"
#include "ui/alarm/alarmsummaryproxy.h"

#include <QSignalSpy>
#include <QTest>

using namespace Fatek;

namespace {

constexpr int alarmCount = 1000;

AlarmStatus alarm(int i, AlarmState state)
{
    AlarmStatus a;
    a.connection = QStringLiteral("Line %1").arg(i % 2 + 1);
    a.alarmId = QStringLiteral("1-R%1-high").arg(i);
    a.address = QStringLiteral("R%1").arg(i);
    a.itemName = a.address;
    a.definition.priority = static_cast<AlarmPriority>(i % 4);
    a.definition.group = i % 10 == 0 ? QStringLiteral("Boiler") : QStringLiteral("Tank");
    a.message = QStringLiteral("R%1 high").arg(i);
    a.state = state;
    a.conditionActive = true;
    a.raisedMs = 1'700'000'000'000 + i;
    a.sinceMs = a.raisedMs;
    a.value = QString::number(i);
    return a;
}

} // namespace

class TestUiAlarmModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void thousandAlarmsCoalesced()
    {
        AlarmSummaryModel model;
        QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy removed(&model, &QAbstractItemModel::rowsRemoved);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);

        // Rows 0..499 wait for an acknowledge, 500..999 are acknowledged.
        for (int i = 0; i < alarmCount; ++i)
            model.updateAlarm(
                alarm(i, i < alarmCount / 2 ? AlarmState::ActiveUnacked : AlarmState::ActiveAcked));
        // Applied by the event loop, once: one insert of every row.
        QTRY_COMPARE(model.rowCount(), alarmCount);
        QCOMPARE(inserted.count(), 1);
        QCOMPARE(changed.count(), 0);

        // A poll cycle changes every value: one dataChanged for the one run of rows.
        changed.clear();
        for (int i = 0; i < alarmCount; ++i) {
            AlarmStatus a = alarm(i, i < alarmCount / 2 ? AlarmState::ActiveUnacked
                                                        : AlarmState::ActiveAcked);
            a.value = QString::number(i + 1);
            model.updateAlarm(a);
        }
        model.flush();
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.first().at(0).toModelIndex().row(), 0);
        QCOMPARE(changed.first().at(1).toModelIndex().row(), alarmCount - 1);
        QCOMPARE(model.index(7, AlarmSummaryModel::ValueColumn).data().toString(),
                 QStringLiteral("8"));

        // Every other row of the first 100 changes: one dataChanged per run (50), not per value.
        changed.clear();
        for (int i = 0; i < 100; i += 2)
            model.updateAlarm(alarm(i, AlarmState::ActiveUnacked));
        model.flush();
        QCOMPARE(changed.count(), 50);

        // The flash: only the unacknowledged rows (0..499, one run), and only the flash's roles.
        changed.clear();
        const bool before = model.isFlashOn();
        QTRY_VERIFY_WITH_TIMEOUT(model.isFlashOn() != before, 3 * AlarmSummaryModel::flashMs);
        QCOMPARE(changed.count(), 1);
        const QList<QVariant> flash = changed.first();
        QCOMPARE(flash.at(0).toModelIndex().row(), 0);
        QCOMPARE(flash.at(1).toModelIndex().row(), alarmCount / 2 - 1);
        const auto roles = flash.at(2).value<QList<int>>();
        QVERIFY(roles.contains(AlarmSummaryModel::FlashRole));
        QVERIFY(!roles.contains(Qt::DisplayRole));
        QCOMPARE(model.index(0, 0).data(AlarmSummaryModel::FlashRole).toBool(), model.isFlashOn());
        QCOMPARE(model.index(600, 0).data(AlarmSummaryModel::FlashRole).toBool(), false);

        // 100 alarms back to normal: removed in one step per run (here one), no reset.
        for (int i = 200; i < 300; ++i)
            model.updateAlarm(alarm(i, AlarmState::Normal));
        model.flush();
        QCOMPARE(model.rowCount(), alarmCount - 100);
        QCOMPARE(removed.count(), 1);
        QCOMPARE(model.rowOf(QStringLiteral("Line 1"), QStringLiteral("1-R200-high")), -1);
        QCOMPARE(model.rowOf(QStringLiteral("Line 1"), QStringLiteral("1-R300-high")), 200);

        // Every alarm acknowledged: the flash stops, nothing more is reported.
        for (int i = 0; i < alarmCount; ++i) {
            if (i < 200 || i >= 300)
                model.updateAlarm(alarm(i, AlarmState::ActiveAcked));
        }
        model.flush();
        changed.clear();
        QTest::qWait(3 * AlarmSummaryModel::flashMs);
        QCOMPARE(changed.count(), 0);
        QCOMPARE(reset.count(), 0);
    }

    // A connection's engine reset: the alarms it no longer has go, the others stay.
    void connectionReset()
    {
        AlarmSummaryModel model;
        for (int i = 0; i < 10; ++i)
            model.updateAlarm(alarm(i, AlarmState::ActiveUnacked));
        model.flush();
        QCOMPARE(model.rowCount(), 10);
        // Line 1 holds the even ones; it keeps only R0 and R2.
        model.setAlarms(QStringLiteral("Line 1"),
                        {alarm(0, AlarmState::ActiveAcked), alarm(2, AlarmState::ActiveUnacked)});
        model.flush();
        QCOMPARE(model.rowCount(), 7);
        const int r0 = model.rowOf(QStringLiteral("Line 1"), QStringLiteral("1-R0-high"));
        QCOMPARE(model.status(r0).state, AlarmState::ActiveAcked);
        model.setAlarms(QStringLiteral("Line 2"), {});
        model.flush();
        QCOMPARE(model.rowCount(), 2);
    }

    // The summary's filters: priority, state, group and text.
    void filters()
    {
        AlarmSummaryModel model;
        for (int i = 0; i < 40; ++i)
            model.updateAlarm(
                alarm(i, i % 3 == 0 ? AlarmState::Shelved : AlarmState::ActiveUnacked));
        model.flush();
        AlarmSummaryProxy proxy;
        proxy.setSourceModel(&model);
        QCOMPARE(proxy.rowCount(), 40);
        proxy.setPriorityFilter(static_cast<int>(AlarmPriority::Critical));
        QCOMPARE(proxy.rowCount(), 10);
        proxy.setPriorityFilter(std::nullopt);
        proxy.setStateFilter(AlarmSummaryProxy::StateFilter::Shelved);
        QCOMPARE(proxy.rowCount(), 14);
        proxy.setStateFilter(AlarmSummaryProxy::StateFilter::Unacked);
        QCOMPARE(proxy.rowCount(), 26);
        proxy.setStateFilter(AlarmSummaryProxy::StateFilter::All);
        proxy.setGroupFilter(QStringLiteral("Boiler"));
        QCOMPARE(proxy.rowCount(), 4);
        proxy.setGroupFilter({});
        proxy.setText(QStringLiteral("r1"));
        QCOMPARE(proxy.rowCount(), 11); // R1, R10..R19
        // Sorting by priority goes by its order (critical first), not by its word.
        proxy.setText({});
        proxy.sort(AlarmSummaryModel::PriorityColumn, Qt::AscendingOrder);
        QCOMPARE(proxy.index(0, 0).data(AlarmSummaryModel::PriorityRole).toInt(),
                 static_cast<int>(AlarmPriority::Critical));
        QCOMPARE(proxy.index(39, 0).data(AlarmSummaryModel::PriorityRole).toInt(),
                 static_cast<int>(AlarmPriority::Low));
    }
};

QTEST_MAIN(TestUiAlarmModel)
#include "tst_ui_alarmmodel.moc"
