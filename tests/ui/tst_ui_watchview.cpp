// The watch table's view repaints only the visible cells that changed: a poll that changes the
// value and time of some rows paints those cells, not their neighbours (Qt 6.4's QTableView
// painted the next column and row of every changed range too).
#include "itemfeed.h"
#include "ui/watch/watchdelegate.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtableview.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QPointer>
#include <QSet>
#include <QTest>

using namespace Fatek;

namespace {

// Notes which cells are painted.
class CountingDelegate : public WatchDelegate
{
public:
    using WatchDelegate::WatchDelegate;
    void paint(QPainter *painter, const QStyleOptionViewItem &option,
               const QModelIndex &index) const override
    {
        painted.insert({index.row(), index.column()});
        WatchDelegate::paint(painter, option, index);
    }
    mutable QSet<std::pair<int, int>> painted;
};

WatchValue good(std::uint64_t id, std::uint32_t value, const QDateTime &t)
{
    WatchValue v;
    v.itemId = id;
    v.value = value;
    v.quality = ValueQuality::Good;
    v.timestamp = t;
    return v;
}

} // namespace

class TestUiWatchView : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void pollRepaintsOnlyChangedCells()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        QList<WatchItemSpec> items;
        for (int n = 0; n < 200; ++n) {
            WatchItemSpec spec;
            spec.address = {ElementType::R, static_cast<std::uint32_t>(n)};
            spec.format = DisplayFormat::Unsigned;
            items.append(spec);
        }
        model.addItems(items);
        const QList<WatchEntry> entries = feed.entries(100);
        WatchTableView view;
        auto *delegate = new CountingDelegate(&view);
        view.setItemDelegate(delegate);
        view.setModel(&model);
        view.verticalHeader()->hide();
        view.horizontalHeader()->setStretchLastSection(true);
        view.resize(900, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));

        QDateTime t = QDateTime::currentDateTimeUtc();
        QList<WatchValue> first;
        for (const WatchEntry &e : entries)
            first.append(good(e.id, 1, t));
        feed.apply(first);
        // The flash of the first values ends (a repaint of the value column) before counting.
        QTRY_VERIFY_WITH_TIMEOUT(
            !model.index(0, WatchTableModel::ValueColumn).data(Qt::BackgroundRole).isValid(),
            10000);
        QTest::qWait(200);
        delegate->painted.clear();

        // Rows 2..5 and row 150 (not visible) get new values at a new time.
        t = t.addMSecs(100);
        QList<WatchValue> next;
        for (int row : {2, 3, 4, 5, 150})
            next.append(good(entries.at(row).id, 2, t));
        feed.apply(next);
        QTRY_VERIFY(!delegate->painted.isEmpty());
        QTest::qWait(50);
        // The quality column repaints on its own timer (the values' age): not counted here.
        delegate->painted.removeIf([](const std::pair<int, int> &cell) {
            return cell.second == WatchTableModel::QualityColumn;
        });
        QSet<std::pair<int, int>> expected;
        for (int row : {2, 3, 4, 5}) {
            expected.insert({row, WatchTableModel::ValueColumn});
            expected.insert({row, WatchTableModel::UpdatedColumn});
        }
        QCOMPARE(delegate->painted, expected);

        // An editor open on a changed row keeps what is typed while the row's values change.
        const QModelIndex value = model.index(3, WatchTableModel::ValueColumn);
        view.setCurrentIndex(value);
        view.edit(value);
        QPointer<QLineEdit> editor = view.viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);
        editor->setText(QStringLiteral("77"));
        t = t.addMSecs(100);
        next.clear();
        for (int row : {2, 3, 4})
            next.append(good(entries.at(row).id, 3, t));
        feed.apply(next);
        QTest::qWait(50);
        QVERIFY(editor);
        QCOMPARE(editor->text(), QStringLiteral("77"));
        QCOMPARE(model.valueText(3), QStringLiteral("3"));
    }
};

QTEST_MAIN(TestUiWatchView)
#include "tst_ui_watchview.moc"
