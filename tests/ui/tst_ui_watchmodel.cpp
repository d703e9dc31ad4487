// The watch table model and the typed-input parsing, without a window or a PLC: values arrive as
// the session would deliver them.
#include "core/watch/itemvalues.h"
#include "itemfeed.h"
#include "ui/watch/watchinput.h"
#include "ui/watch/watchtablemodel.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace Fatek;

class TestUiWatchModel : public QObject
{
    Q_OBJECT

private:
    static WatchItemSpec item(const char *address, DisplayFormat format, quint8 station = 1)
    {
        WatchItemSpec spec;
        spec.address = *Address::parse(address);
        spec.format = format;
        spec.station = station;
        return spec;
    }
    static WatchValue good(std::uint64_t id, std::uint32_t value)
    {
        WatchValue v;
        v.itemId = id;
        v.value = value;
        v.quality = ValueQuality::Good;
        v.timestamp = QDateTime::currentDateTimeUtc();
        return v;
    }

private Q_SLOTS:
    void parseAddressesAndRanges()
    {
        const auto list = WatchInput::parseAddresses(QStringLiteral("R100 X0..X3, DR10;Y0"));
        QVERIFY(list.ok());
        QCOMPARE(list->size(), 7);
        QCOMPARE(QString::fromStdString(list->at(1).toString()), QStringLiteral("X0"));
        QCOMPARE(QString::fromStdString(list->at(4).toString()), QStringLiteral("X3"));
        QCOMPARE(QString::fromStdString(list->at(5).toString()), QStringLiteral("DR10"));
    }

    void badAddressNamesTheToken()
    {
        const auto list = WatchInput::parseAddresses(QStringLiteral("R100 Q7 R101"));
        QVERIFY(!list.ok());
        QVERIFY2(QString::fromStdString(list.error().text()).contains(QStringLiteral("\"Q7\"")),
                 list.error().text().c_str());
        QVERIFY(!WatchInput::parseAddresses(QStringLiteral("   ")).ok());
    }

    void pastedCsvKeepsNames()
    {
        const auto rows
            = WatchInput::parsePasted(QStringLiteral("R100,Tank level\nR101,Pump speed\n"), 3);
        QVERIFY2(rows.ok(), rows.ok() ? "" : rows.error().text().c_str());
        QCOMPARE(rows->size(), 2);
        QCOMPARE(rows->at(0).name, QStringLiteral("Tank level"));
        QCOMPARE(rows->at(1).station, quint8(3));
        const auto withFormat = WatchInput::parsePasted(QStringLiteral("R10\tfloat\tFlow\n"), 1);
        QVERIFY2(withFormat.ok(), withFormat.ok() ? "" : withFormat.error().text().c_str());
        QCOMPARE(withFormat->at(0).format, DisplayFormat::Float32);
        QCOMPARE(withFormat->at(0).name, QStringLiteral("Flow"));
        const auto positional = WatchInput::parsePasted(QStringLiteral("R10,4,hex,Speed"), 1);
        QVERIFY(positional.ok());
        QCOMPARE(positional->at(0).station, quint8(4));
        QVERIFY(!WatchInput::parsePasted(QStringLiteral("R10,Flow\nQ9,Bad"), 1).ok());
        const auto plain = WatchInput::parsePasted(QStringLiteral("R100, R101\nX0..X1"), 2);
        QVERIFY(plain.ok());
        QCOMPARE(plain->size(), 4);
        QCOMPARE(plain->at(3).format, DisplayFormat::Bit);
    }

    void floatJoinsTwoRegisters()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R100", DisplayFormat::Float32)});
        const QList<WatchEntry> entries = feed.entries(250);
        QCOMPARE(entries.size(), 2);
        QCOMPARE(QString::fromStdString(entries.at(1).address.toString()), QStringLiteral("R101"));
        QCOMPARE(entries.at(0).intervalMs, 250);
        QVERIFY(!model.hasValue(0));
        // 1.5f = 0x3FC00000: high word in R101.
        feed.apply({good(entries.at(0).id, 0x0000), good(entries.at(1).id, 0x3FC0)});
        QVERIFY(model.hasValue(0));
        QCOMPARE(model.rawValue(0), std::uint64_t(0x3FC00000));
        QCOMPARE(model.data(model.index(0, WatchTableModel::ValueColumn)).toString(),
                 QStringLiteral("1.5"));
    }

    void doubleJoinsFourRegistersAndChangedValuesFlash()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R0", DisplayFormat::Double64)});
        const QList<WatchEntry> entries = feed.entries(500);
        QCOMPARE(entries.size(), 4);
        // 1.0 = 0x3FF0000000000000: the highest word in R3.
        feed.apply({good(entries.at(0).id, 0), good(entries.at(1).id, 0), good(entries.at(2).id, 0),
                    good(entries.at(3).id, 0x3FF0)});
        QCOMPARE(model.valueText(0), QStringLiteral("1"));
        const QModelIndex value = model.index(0, WatchTableModel::ValueColumn);
        QVERIFY(value.data(Qt::BackgroundRole).isValid()); // a new value flashes ...
        QTRY_VERIFY_WITH_TIMEOUT(!value.data(Qt::BackgroundRole).isValid(), 10000); // ... briefly
        // The same value again does not flash.
        feed.apply({good(entries.at(3).id, 0x3FF0)});
        QVERIFY(!value.data(Qt::BackgroundRole).isValid());
        // Swapped words: the same registers read the other way round.
        QVERIFY(model.setFormat(0, DisplayFormat::Double64, true).ok());
        QCOMPARE(feed.entries(500).size(), 4);
    }

    void batchGivesCoalescedDataChanged()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R0", DisplayFormat::Signed), item("R1", DisplayFormat::Signed),
                        item("R2", DisplayFormat::Signed), item("R5", DisplayFormat::Signed)});
        const QList<WatchEntry> entries = feed.entries(500);
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
        // Every signal covers one column and a run of rows; "column,first,last" per signal.
        const auto ranges = [&changed] {
            QStringList list;
            for (const QList<QVariant> &args : std::as_const(changed)) {
                const QModelIndex first = args.at(0).toModelIndex();
                const QModelIndex last = args.at(1).toModelIndex();
                if (first.column() != last.column())
                    return QStringList{QStringLiteral("several columns")};
                list << QStringLiteral("%1,%2,%3")
                            .arg(first.column())
                            .arg(first.row())
                            .arg(last.row());
            }
            list.sort();
            changed.clear();
            return list;
        };
        const int value = WatchTableModel::ValueColumn;
        const int quality = WatchTableModel::QualityColumn;
        const int updated = WatchTableModel::UpdatedColumn;
        auto expected = [](std::initializer_list<int> columns, const QStringList &runs) {
            QStringList list;
            for (int c : columns) {
                for (const QString &run : runs)
                    list << QStringLiteral("%1,%2").arg(c).arg(run);
            }
            list.sort();
            return list;
        };
        QDateTime t = QDateTime::currentDateTimeUtc();
        auto at = [&t](WatchValue v) {
            v.timestamp = t;
            return v;
        };
        // First values: value, quality ("waiting" ends) and time change, rows 0..1 and row 3.
        feed.apply({at(good(entries.at(0).id, 1)), at(good(entries.at(1).id, 2)),
                    at(good(entries.at(3).id, 4))});
        QCOMPARE(reset.count(), 0);
        QCOMPARE(ranges(), expected({value, quality, updated}, {"0,1", "3,3"}));
        // The same values later: only the time changes (no format, name or value cell is touched).
        t = t.addMSecs(500);
        feed.apply({at(good(entries.at(0).id, 1)), at(good(entries.at(1).id, 2)),
                    at(good(entries.at(3).id, 4))});
        QCOMPARE(ranges(), expected({updated}, {"0,1", "3,3"}));
        // One value moves: its value cell and the times.
        t = t.addMSecs(500);
        feed.apply({at(good(entries.at(0).id, 1)), at(good(entries.at(1).id, 3)),
                    at(good(entries.at(3).id, 4))});
        QStringList moved{QStringLiteral("%1,1,1").arg(value),
                          QStringLiteral("%1,0,1").arg(updated),
                          QStringLiteral("%1,3,3").arg(updated)};
        moved.sort();
        QCOMPARE(ranges(), moved);
    }

    void queuedBurstEndsWithNewestValues()
    {
        // Six rows, the last a float over two registers. 40 batches come at once (a UI thread that
        // fell behind): batch k reads every element as k at t0 + k s, except that the newest
        // batch lacks row 4 and says row 3 is stale (timeout): rows 3 and 4 must keep their newest
        // good value (38 and 38 at t0 + 38 s) and row 3 must not look fresh.
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R0", DisplayFormat::Unsigned), item("R1", DisplayFormat::Unsigned),
                        item("R2", DisplayFormat::Unsigned), item("R3", DisplayFormat::Unsigned),
                        item("R4", DisplayFormat::Unsigned), item("R5", DisplayFormat::Float32)});
        const QList<WatchEntry> entries = feed.entries(100);
        QCOMPARE(entries.size(), 7);
        const QDateTime t0 = QDateTime::currentDateTimeUtc();
        const auto time = [&t0](int k) {
            return t0.addSecs(k);
        };
        const int batches = 40;
        for (int k = 1; k <= batches; ++k) {
            QList<WatchValue> batch;
            for (int e = 0; e < entries.size(); ++e) {
                WatchValue v = good(entries.at(e).id, static_cast<std::uint32_t>(k));
                v.timestamp = time(k);
                if (k == batches && e == 4)
                    continue;
                if (k == batches && e == 3) {
                    v.quality = ValueQuality::Stale;
                    v.value = static_cast<std::uint32_t>(k - 1); // the poller's last good value
                    v.timestamp = time(k - 1);
                    v.error = Message::text("timeout after 1000 ms");
                }
                batch.append(v);
            }
            feed.queue(batch);
        }
        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QSignalSpy reset(&model, &QAbstractItemModel::modelReset);
        // Nothing is applied inside the caller's slot: the event loop applies it.
        QVERIFY(model.hasQueuedValues());
        QVERIFY(!model.hasValue(0));
        QTRY_VERIFY(!model.hasQueuedValues());

        const auto text = [&model](int row, int column) {
            return model.data(model.index(row, column)).toString();
        };
        const auto shown = [](const QDateTime &t) {
            return t.toLocalTime().toString(QStringLiteral("HH:mm:ss.zzz"));
        };
        for (int row = 0; row < 3; ++row) {
            QCOMPARE(model.rawValue(row), std::uint64_t(batches));
            QCOMPARE(model.quality(row), ValueQuality::Good);
            QCOMPARE(text(row, WatchTableModel::UpdatedColumn), shown(time(batches)));
        }
        QCOMPARE(model.rawValue(3), std::uint64_t(batches - 1));
        QCOMPARE(model.quality(3), ValueQuality::Stale);
        // The quality without the value's age ("stale, 0.0 s").
        QCOMPARE(text(3, WatchTableModel::QualityColumn).section(QStringLiteral(", "), 0, 0),
                 QStringLiteral("stale"));
        QCOMPARE(text(3, WatchTableModel::UpdatedColumn), shown(time(batches - 1)));
        QCOMPARE(model.rawValue(4), std::uint64_t(batches - 1));
        QCOMPARE(model.quality(4), ValueQuality::Good);
        QCOMPARE(text(4, WatchTableModel::UpdatedColumn), shown(time(batches - 1)));
        QCOMPARE(model.rawValue(5), (std::uint64_t(batches) << 16) | std::uint64_t(batches));

        // Coalesced: one signal per changed column over the run of rows 0..5, not one per batch.
        // The newest batch comes first and older ones only fill rows 3 and 4 (it lacks their
        // values) in the same slice: a slice applies 64 values before it looks at the clock.
        QCOMPARE(reset.count(), 0);
        QStringList ranges;
        for (const QList<QVariant> &args : std::as_const(changed)) {
            const QModelIndex first = args.at(0).toModelIndex();
            const QModelIndex last = args.at(1).toModelIndex();
            ranges << QStringLiteral("%1:%2,%3:%4")
                          .arg(first.column())
                          .arg(first.row())
                          .arg(last.column())
                          .arg(last.row());
        }
        ranges.sort();
        QStringList expected;
        for (int column : {WatchTableModel::ValueColumn, WatchTableModel::QualityColumn,
                           WatchTableModel::UpdatedColumn})
            expected << QStringLiteral("%1:0,%1:5").arg(column);
        expected.sort();
        QCOMPARE(ranges, expected);

        // A batch applied now (applyValues) also takes what is still queued, newest last.
        QList<WatchValue> older{good(entries.at(0).id, 1000)};
        QList<WatchValue> newer{good(entries.at(0).id, 2000)};
        feed.queue(older);
        feed.apply(newer);
        QVERIFY(!model.hasQueuedValues());
        QCOMPARE(model.rawValue(0), std::uint64_t(2000));
    }

    void staleMarkingWaitsForNothingQueued()
    {
        // Values delivered before the link went down are applied first, then marked stale: a
        // queued good value must never turn a row fresh after markAllStale.
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R0", DisplayFormat::Unsigned)});
        const quint64 id = feed.entries(100).at(0).id;
        feed.queue({good(id, 7)});
        model.markAllStale(QStringLiteral("link down"));
        QVERIFY(!model.hasQueuedValues());
        QCOMPARE(model.rawValue(0), std::uint64_t(7));
        QCOMPARE(model.quality(0), ValueQuality::Stale);
        QTest::qWait(2 * WatchTableModel::frameMs);
        QCOMPARE(model.quality(0), ValueQuality::Stale);
    }

    void rowsChangedWhileValuesAreQueued()
    {
        // Queued values find their rows by item key when applied: a row removed or re-spanned
        // meanwhile gets nothing, the others get theirs.
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R0", DisplayFormat::Unsigned), item("R1", DisplayFormat::Unsigned),
                        item("R2", DisplayFormat::Unsigned)});
        const QList<WatchEntry> entries = feed.entries(100);
        feed.queue(
            {good(entries.at(0).id, 10), good(entries.at(1).id, 11), good(entries.at(2).id, 12)});
        QVERIFY(model.removeRows(0, 1));
        QVERIFY(model.setFormat(1, DisplayFormat::Float32, false).ok()); // R2 gets a new item key
        QTRY_VERIFY(!model.hasQueuedValues());
        QCOMPARE(model.rowCount(), 2);
        QCOMPARE(model.rawValue(0), std::uint64_t(11));
        QVERIFY(!model.hasValue(1));
    }

    void staleKeepsValueWithReason()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R7", DisplayFormat::Unsigned)});
        const quint64 id = feed.entries(500).at(0).id;
        feed.apply({good(id, 42)});
        WatchValue stale;
        stale.itemId = id;
        stale.value = 42;
        stale.quality = ValueQuality::Stale;
        stale.error = Message::text("timeout after 1000 ms");
        feed.apply({stale});
        QCOMPARE(model.quality(0), ValueQuality::Stale);
        QCOMPARE(model.data(model.index(0, WatchTableModel::ValueColumn)).toString(),
                 QStringLiteral("42"));
        QVERIFY(model.data(model.index(0, WatchTableModel::QualityColumn), Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("timeout after 1000 ms")));
        QCOMPARE(model.data(model.index(0, WatchTableModel::QualityColumn))
                     .toString()
                     .section(QStringLiteral(", "), 0, 0),
                 QStringLiteral("stale"));
    }

    void typedValueBecomesWriteRequest()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R10", DisplayFormat::Hex), item("Y3", DisplayFormat::Bit)});
        const QList<WatchEntry> entries = feed.entries(500);
        feed.apply({good(entries.at(0).id, 0), good(entries.at(1).id, 0)});
        QSignalSpy writes(&model, &WatchTableModel::writeRequested);
        QSignalSpy rejected(&model, &WatchTableModel::inputRejected);
        QVERIFY(
            !model.setData(model.index(0, WatchTableModel::ValueColumn), QStringLiteral("1Ah")));
        QCOMPARE(writes.count(), 1);
        QCOMPARE(writes.at(0).at(1).toULongLong(), 0x1Aull);
        model.setData(model.index(0, WatchTableModel::ValueColumn), QStringLiteral("0x10000"));
        QCOMPARE(rejected.count(), 1);
        QCOMPARE(writes.count(), 1);
        model.setData(model.index(1, WatchTableModel::ValueColumn), Qt::Checked,
                      Qt::CheckStateRole);
        QCOMPARE(writes.count(), 2);
        QCOMPARE(writes.at(1).at(0).toInt(), 1);
        QCOMPARE(writes.at(1).at(1).toULongLong(), 1ull);
    }

    void formatChangeRepollsAndIsValidated()
    {
        WatchTableModel model;
        TestUtil::ItemFeed feed{model, {}};
        model.addItems({item("R65535", DisplayFormat::Signed), item("X0", DisplayFormat::Bit)});
        QSignalSpy rejected(&model, &WatchTableModel::inputRejected);
        // R65535 as float would need R65536.
        QVERIFY(!model.setFormat(0, DisplayFormat::Float32, false).ok());
        QVERIFY(!model.availableFormats(1).contains(DisplayFormat::Float32));
        QVERIFY(
            !model.setData(model.index(1, WatchTableModel::FormatColumn), QStringLiteral("float")));
        QCOMPARE(rejected.count(), 1);
        model.addItems({item("R0", DisplayFormat::Signed)});
        QSignalSpy repoll(&model, &WatchTableModel::pollListChanged);
        QVERIFY(model.setFormat(2, DisplayFormat::Double64, true).ok());
        QCOMPARE(repoll.count(), 1);
        QCOMPARE(feed.entries(500).size(), 1 + 1 + 4);
    }

    void writeRequestCoversEverySpannedRegister()
    {
        WatchItemSpec f = item("R20", DisplayFormat::Float32, 2);
        const Request r = ItemValues(f).writeRequest(0x3FC00000);
        QCOMPARE(r.command, Command::WriteRegisters);
        QCOMPARE(r.station, std::uint8_t(2));
        QCOMPARE(r.values, (std::vector<std::uint32_t>{0x0000, 0x3FC0}));
        const Request d = ItemValues(item("DR4", DisplayFormat::Unsigned)).writeRequest(99999);
        QCOMPARE(d.values, (std::vector<std::uint32_t>{99999}));
        const Request b = ItemValues(item("Y1", DisplayFormat::Bit)).writeRequest(1);
        QCOMPARE(b.command, Command::WriteDiscretes);
        QCOMPARE(b.values, (std::vector<std::uint32_t>{1}));
    }

    // Issue 34: every edit of the rows is one step on the undo stack, taken back exactly (rows in
    // their places, their specs as they were), and a loaded list starts a new history.
    void rowEditsAreUndoSteps()
    {
        WatchTableModel model;
        const auto addresses = [&model] {
            QStringList out;
            for (int r = 0; r < model.rowCount(); ++r)
                out << QString::fromStdString(model.item(r).address.toString());
            return out.join(QLatin1Char(' '));
        };
        QUndoStack *undo = model.undoStack();
        model.addItems({item("R0", DisplayFormat::Signed), item("R1", DisplayFormat::Signed),
                        item("R2", DisplayFormat::Signed), item("R3", DisplayFormat::Signed),
                        item("Y0", DisplayFormat::Bit)});
        QCOMPARE(undo->count(), 1);

        model.removeItems({3, 1});
        QCOMPARE(addresses(), QStringLiteral("R0 R2 Y0"));
        undo->undo();
        QCOMPARE(addresses(), QStringLiteral("R0 R1 R2 R3 Y0"));
        undo->redo();
        undo->undo();

        // Runs move as blocks past their neighbour; at the edge nothing moves.
        QVERIFY(model.moveItems({0, 1}, 1));
        QCOMPARE(addresses(), QStringLiteral("R2 R0 R1 R3 Y0"));
        QVERIFY(model.moveItems({0, 4}, -1));
        QCOMPARE(addresses(), QStringLiteral("R2 R0 R1 Y0 R3"));
        QVERIFY(!model.moveItems({0}, -1));
        QVERIFY(model.moveItemsTo({1, 3}, 5));
        QCOMPARE(addresses(), QStringLiteral("R2 R1 R3 R0 Y0"));
        undo->undo();
        undo->undo();
        undo->undo();
        QCOMPARE(addresses(), QStringLiteral("R0 R1 R2 R3 Y0"));

        // One format for several rows: one step; the bit keeps its own.
        const int steps = undo->index();
        QVERIFY(!model.setFormats({0, 1, 4}, DisplayFormat::Float32));
        QCOMPARE(undo->index(), steps + 1);
        QCOMPARE(model.item(0).format, DisplayFormat::Float32);
        QCOMPARE(model.item(4).format, DisplayFormat::Bit);
        undo->undo();
        QCOMPARE(model.item(0).format, DisplayFormat::Signed);
        QCOMPARE(model.item(1).format, DisplayFormat::Signed);

        // Typed into the cells: name and address.
        QVERIFY(model.setData(model.index(2, WatchTableModel::NameColumn), QStringLiteral("Tank")));
        QVERIFY(
            model.setData(model.index(2, WatchTableModel::AddressColumn), QStringLiteral("x7")));
        QCOMPARE(model.item(2).address, *Address::parse("X7"));
        QCOMPARE(model.item(2).format, DisplayFormat::Bit); // what an X can show
        QVERIFY(
            !model.setData(model.index(2, WatchTableModel::AddressColumn), QStringLiteral("Q")));
        undo->undo();
        QCOMPARE(model.item(2).address, *Address::parse("R2"));
        QCOMPARE(model.item(2).format, DisplayFormat::Signed);
        QCOMPARE(model.item(2).name, QStringLiteral("Tank"));

        model.setItems({item("R9", DisplayFormat::Hex)});
        QCOMPARE(undo->count(), 0);
    }
};

QTEST_MAIN(TestUiWatchModel)
#include "tst_ui_watchmodel.moc"
