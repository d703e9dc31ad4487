// RawConsole against the simulator: typed frames (ASCII and hex, with and without automatic
// framing) get their decoded answers in the log; corrupted answers are error lines; filters, cap,
// save. The frame text itself (views, parsing, header peek) is tested in tst_frametext.
#include "tst_tools_fixture.h"
#include "ui/common/toolpalette.h"
#include "ui/tools/rawconsole.h"
#include "ui/tools/rawsendbar.h"
#include "ui/tools/trafficfilterproxy.h"
#include "ui/tools/trafficlogmodel.h"

#include <QCheckBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;
using ToolsTest::Rig;

class TestToolsConsole : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup();

    void modelCapsRows();
    void errorColoursFollowThePalette();
    void typedFaconFrameDecoded();
    void typedBinaryFrameDecoded();
    void wholeFrameWithoutFraming();
    void corruptedAnswerIsErrorLine();
    void writeFrameAsksFirst();
    void filtersPauseClearSave();
    void noConnection();
    void hiddenConsoleKeepsShortLog();

private:
    void open(LinkSettings::ProtocolChoice protocol = LinkSettings::ProtocolChoice::Facon);
    // Rows of the model (not the filter) received after `after`.
    int findRow(TrafficEntry::Direction direction, const QString &meaningPart, int after = 0) const;

    Rig m_rig;
    std::unique_ptr<RawConsole> m_console;
};

void TestToolsConsole::open(LinkSettings::ProtocolChoice protocol)
{
    m_rig = Rig();
    QVERIFY(m_rig.start(protocol, 500, 0));
    m_console = std::make_unique<RawConsole>();
    m_console->setConfirmer(m_rig.confirmer());
    m_console->setTarget(m_rig.target(1));
    m_console->resize(1000, 500);
    m_console->show();
}

void TestToolsConsole::cleanup()
{
    m_console.reset();
    m_rig.link.reset();
    m_rig.server.reset();
    m_rig.plc.reset();
}

int TestToolsConsole::findRow(TrafficEntry::Direction direction, const QString &meaningPart,
                              int after) const
{
    TrafficLogModel *model = m_console->model();
    for (int r = after; r < model->rowCount(); ++r) {
        const TrafficEntry &e = model->entryAt(r);
        if (e.direction == direction && englishText(e.summary).contains(meaningPart))
            return r;
    }
    return -1;
}

void TestToolsConsole::modelCapsRows()
{
    TrafficLogModel model;
    model.setCapacity(10);
    QList<TrafficEntry> batch;
    for (int i = 1; i <= 7; ++i) {
        TrafficEntry e;
        e.sequence = static_cast<quint64>(i);
        e.direction = TrafficEntry::Direction::Out;
        batch << e;
    }
    model.append(batch);
    QCOMPARE(model.rowCount(), 7);
    for (TrafficEntry &e : batch)
        e.sequence += 7;
    model.append(batch);
    QCOMPARE(model.rowCount(), 10);
    QCOMPARE(model.entryAt(0).sequence, quint64(5));
    QCOMPARE(model.entryAt(9).sequence, quint64(14));
    QList<TrafficEntry> huge;
    for (int i = 0; i < 25; ++i) {
        TrafficEntry e;
        e.sequence = static_cast<quint64>(100 + i);
        huge << e;
    }
    model.append(huge);
    QCOMPARE(model.rowCount(), 10);
    QCOMPARE(model.entryAt(0).sequence, quint64(115));
}

void TestToolsConsole::errorColoursFollowThePalette()
{
    QPalette light;
    light.setColor(QPalette::Text, Qt::black);
    light.setColor(QPalette::Base, Qt::white);
    QPalette dark;
    dark.setColor(QPalette::Text, Qt::white);
    dark.setColor(QPalette::Base, Qt::black);
    const QColor onLight = ToolPalette::errorText(light);
    const QColor onDark = ToolPalette::errorText(dark);
    QVERIFY(onLight.lightnessF() < onDark.lightnessF());
    QCOMPARE(onLight.hslHue(), 0);
    // Row backgrounds stay close to Base so the text remains readable.
    QVERIFY(ToolPalette::errorBackground(light).lightnessF() > 0.8);
    QVERIFY(ToolPalette::errorBackground(dark).lightnessF() < 0.2);
}

void TestToolsConsole::typedFaconFrameDecoded()
{
    open();
    m_rig.plc->setValue(ToolsTest::addr("R12"), 0x1234);
    RawSendBar *bar = m_console->sendBar();
    bar->setMode(RawSendBar::Mode::Ascii);
    bar->setAddFraming(true);
    bar->setText(QStringLiteral("014603R00012"));
    bar->send();
    QVERIFY(m_rig.questions.isEmpty()); // a read needs no confirmation
    QTRY_COMPARE_WITH_TIMEOUT(bar->answersReceived(), 1, 10000);
    QVERIFY2(bar->resultText().contains(QStringLiteral("Sent    <STX>014603R00012")),
             qPrintable(bar->resultText()));
    QVERIFY2(bar->resultText().contains(QStringLiteral("1234")), qPrintable(bar->resultText()));
    QVERIFY2(bar->resultText().contains(QStringLiteral("answer: OK")),
             qPrintable(bar->resultText()));
    // The console shows the frame out and the decoded answer in.
    QTRY_VERIFY_WITH_TIMEOUT(findRow(TrafficEntry::Direction::In, QStringLiteral("46")) >= 0,
                             10000);
    const int out = findRow(TrafficEntry::Direction::Out, QStringLiteral("46"));
    QVERIFY(out >= 0);
    const int in = findRow(TrafficEntry::Direction::In, QStringLiteral("46"), out);
    QVERIFY(in > out);
    TrafficLogModel *model = m_console->model();
    QVERIFY(model->index(out, TrafficLogModel::AsciiColumn)
                .data()
                .toString()
                .startsWith(QStringLiteral("<STX>014603R00012")));
    QVERIFY(model->index(in, TrafficLogModel::AsciiColumn)
                .data()
                .toString()
                .contains(QStringLiteral("1234")));
    QVERIFY(model->index(in, TrafficLogModel::ErrorColumn).data().toString().isEmpty());
    QVERIFY(!model->index(in, 0).data(TrafficLogModel::IsErrorRole).toBool());
    QCOMPARE(model->index(in, TrafficLogModel::StationColumn).data().toInt(), 1);
}

void TestToolsConsole::typedBinaryFrameDecoded()
{
    open(LinkSettings::ProtocolChoice::Binary);
    m_rig.plc->setValue(ToolsTest::addr("R12"), 0xBEEF);
    RawSendBar *bar = m_console->sendBar();
    bar->setMode(RawSendBar::Mode::Hex);
    bar->setAddFraming(true);
    bar->setText(QStringLiteral("01 46 03 52 00 0C"));
    bar->send();
    QTRY_COMPARE_WITH_TIMEOUT(bar->answersReceived(), 1, 10000);
    QVERIFY2(bar->resultText().contains(QStringLiteral("BE EF")), qPrintable(bar->resultText()));
    QTRY_VERIFY_WITH_TIMEOUT(findRow(TrafficEntry::Direction::In, QStringLiteral("46")) >= 0,
                             10000);
    const int in = findRow(TrafficEntry::Direction::In, QStringLiteral("46"));
    QVERIFY(m_console->model()
                ->index(in, TrafficLogModel::HexColumn)
                .data()
                .toString()
                .startsWith(QStringLiteral("52 10")));
}

void TestToolsConsole::wholeFrameWithoutFraming()
{
    open();
    RawSendBar *bar = m_console->sendBar();
    bar->setMode(RawSendBar::Mode::Ascii);
    bar->setAddFraming(false);
    bar->setText(QStringLiteral("<STX>0140C7<ETX>"));
    bar->send();
    QTRY_COMPARE_WITH_TIMEOUT(bar->answersReceived(), 1, 10000);
    QVERIFY(bar->lastAnswer().startsWith("\x02"
                                         "0140"));
}

void TestToolsConsole::corruptedAnswerIsErrorLine()
{
    open();
    FaultConfig faults;
    faults.corruptRate = 0.5;
    faults.seed = 3;
    m_rig.server->setFaults(faults);
    RawSendBar *bar = m_console->sendBar();
    bar->setMode(RawSendBar::Mode::Ascii);
    bar->setAddFraming(true);
    bar->setText(QStringLiteral("014603R00000"));
    bar->send();
    QTRY_VERIFY_WITH_TIMEOUT(!bar->isBusy(), 10000);
    TrafficLogModel *model = m_console->model();
    int errorRow = -1;
    QTRY_VERIFY_WITH_TIMEOUT(
        ([&] {
            for (int r = 0; r < model->rowCount(); ++r) {
                if (model->entryAt(r).direction != TrafficEntry::Direction::Out
                    && model->index(r, 0).data(TrafficLogModel::IsErrorRole).toBool()) {
                    errorRow = r;
                    return true;
                }
            }
            return false;
        }()),
        10000);
    QVERIFY(!model->index(errorRow, TrafficLogModel::ErrorColumn).data().toString().isEmpty());
    // Highlighted with the palette-derived error colours.
    const QPalette palette = m_console->palette();
    QCOMPARE(model->index(errorRow, TrafficLogModel::MeaningColumn)
                 .data(Qt::ForegroundRole)
                 .value<QColor>(),
             ToolPalette::errorText(palette));
    QCOMPARE(model->index(errorRow, 0).data(Qt::BackgroundRole).value<QColor>(),
             ToolPalette::errorBackground(palette));
    // "Errors only" keeps it and hides the sent frame.
    auto *errorsOnly = m_console->findChild<QCheckBox *>(QStringLiteral("errorsOnly"));
    QVERIFY(errorsOnly);
    errorsOnly->setChecked(true);
    QVERIFY(m_console->filter()->rowCount() >= 1);
    for (int r = 0; r < m_console->filter()->rowCount(); ++r)
        QVERIFY(m_console->filter()->index(r, 0).data(TrafficLogModel::IsErrorRole).toBool());
}

void TestToolsConsole::writeFrameAsksFirst()
{
    open();
    RawSendBar *bar = m_console->sendBar();
    bar->setMode(RawSendBar::Mode::Ascii);
    bar->setAddFraming(true);
    bar->setText(QStringLiteral("01410")); // STOP
    m_rig.answer = false;
    bar->send();
    QCOMPARE(m_rig.questions.size(), 1);
    QVERIFY2(m_rig.questions.last().contains(QStringLiteral("station 1")),
             qPrintable(m_rig.questions.last()));
    QVERIFY(m_rig.questions.last().contains(Rig::connectionName()));
    QVERIFY(bar->resultText().contains(QStringLiteral("Cancelled")));
    QTest::qWait(200);
    QVERIFY(m_rig.plc->isRunning());

    m_rig.answer = true;
    bar->send();
    QCOMPARE(m_rig.questions.size(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(!m_rig.plc->isRunning(), 10000);
    QTRY_VERIFY_WITH_TIMEOUT(!bar->isBusy(), 10000);
    QVERIFY2(bar->resultText().contains(QStringLiteral("Answer  <STX>01410")),
             qPrintable(bar->resultText()));

    // Operator mode: the session refuses raw frames before the wire; shown as an error that
    // says nothing was sent.
    m_rig.link->setReadOnly(true);
    bar->setText(QStringLiteral("01411"));
    bar->send();
    QTRY_VERIFY_WITH_TIMEOUT(bar->resultText().startsWith(QStringLiteral("Not sent")), 10000);
    QVERIFY(!m_rig.plc->isRunning());
}

void TestToolsConsole::filtersPauseClearSave()
{
    open();
    Request read = Request::readRegisters(1, ToolsTest::addr("R0"), 2);
    QSignalSpy finished(m_rig.session(), &Session::finished);
    m_rig.session()->submit(read);
    m_rig.session()->submit(Request::briefStatus(1));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 10000);
    QTRY_VERIFY_WITH_TIMEOUT(m_console->model()->rowCount() >= 4, 10000);

    TrafficFilterProxy *filter = m_console->filter();
    filter->setDirection(TrafficEntry::Direction::Out);
    QCOMPARE(filter->rowCount(), 2);
    filter->setCommand(0x40);
    QCOMPARE(filter->rowCount(), 1);
    filter->setDirection(std::nullopt);
    QCOMPARE(filter->rowCount(), 2);
    filter->setStation(2);
    QCOMPARE(filter->rowCount(), 0);
    filter->setStation(std::nullopt);
    filter->setCommand(std::nullopt);

    // Pause: frames wait in the log and show up on resume.
    m_console->setPaused(true);
    const int before = m_console->model()->rowCount();
    m_rig.session()->submit(Request::briefStatus(1));
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, 10000);
    QTest::qWait(200);
    QCOMPARE(m_console->model()->rowCount(), before);
    m_console->setPaused(false);
    QTRY_COMPARE_WITH_TIMEOUT(m_console->model()->rowCount(), before + 2, 10000);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("traffic.tsv"));
    QCOMPARE(m_console->saveToFile(path), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines
        = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), before + 2 + 1);
    QVERIFY(lines.first().startsWith(QStringLiteral("Time\tDirection")));
    QVERIFY(lines.at(1).contains(QStringLiteral("<STX>01460")));
    QVERIFY(!m_console->saveToFile(dir.filePath(QStringLiteral("no/such/dir/x.tsv"))).isEmpty());
    // A device that takes nothing: the reason, and the traffic saved before is as it was.
    const QByteArray saved = [&path] {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }();
    if (QFileInfo(QStringLiteral("/dev/full")).exists()) {
        const QString full = m_console->saveToFile(QStringLiteral("/dev/full"));
        QVERIFY2(full.contains(QLatin1String("No space left on device")), qPrintable(full));
        QVERIFY(!QFileInfo(QStringLiteral("/dev/full")).isFile());
    }
    QFile again(path);
    QVERIFY(again.open(QIODevice::ReadOnly));
    QCOMPARE(again.readAll(), saved);

    QCOMPARE(m_console->copyRows().split(QLatin1Char('\n')).size(), before + 2);
    m_console->clear();
    QCOMPARE(m_console->model()->rowCount(), 0);
}

void TestToolsConsole::noConnection()
{
    open();
    m_console->setTarget(PlcTarget());
    QCOMPARE(m_console->model()->rowCount(), 0);
    m_console->sendBar()->setText(QStringLiteral("0140"));
    m_console->sendBar()->send();
    QVERIFY(m_console->sendBar()->resultText().contains(QStringLiteral("No connection")));

    // A link closed under the console leaves it in "no connection" too.
    m_console->setTarget(m_rig.target(1));
    m_rig.session()->submit(Request::briefStatus(1));
    QTRY_VERIFY_WITH_TIMEOUT(m_console->model()->rowCount() >= 2, 10000);
    m_rig.link.reset();
    m_console->sendBar()->send();
    QVERIFY(m_console->sendBar()->resultText().contains(QStringLiteral("No connection")));
    m_console->setTarget(PlcTarget(nullptr, 2, {}));
    QCOMPARE(m_console->model()->rowCount(), 0);
}

// The console reads its link's log only while on screen. Hidden (a docked console behind another
// tab), its table stays empty and the link keeps a short log; shown, the newest frames appear and
// the log grows to its full length, so frames while it is hidden again are all kept.
void TestToolsConsole::hiddenConsoleKeepsShortLog()
{
    m_rig = Rig();
    QVERIFY(m_rig.start(LinkSettings::ProtocolChoice::Facon, 500, 0));
    m_console = std::make_unique<RawConsole>();
    m_console->setTarget(m_rig.target(1));
    m_console->resize(1000, 500);
    TrafficLog *log = m_rig.session()->trafficLog();
    QCOMPARE(log->capacity(), TrafficLog::idleCapacity);

    int finished = 0;
    connect(m_rig.session(), &Session::finished, this, [&finished] { ++finished; });
    const auto transactions = [this, &finished](int count) {
        const int until = finished + count;
        for (int i = 0; i < count; ++i)
            m_rig.session()->submit(Request::briefStatus(1));
        QTRY_COMPARE_WITH_TIMEOUT(finished, until, 20000);
    };
    // A frame out and one in each: more than the short log keeps.
    transactions(TrafficLog::idleCapacity / 2 + 20);
    QCOMPARE(log->size(), TrafficLog::idleCapacity);
    QTest::qWait(200);
    QCOMPARE(m_console->model()->rowCount(), 0);

    m_console->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_console.get()));
    QTRY_COMPARE(m_console->model()->rowCount(), TrafficLog::idleCapacity);
    QCOMPARE(log->capacity(), TrafficLog::fullCapacity);
    QCOMPARE(m_console->model()->entryAt(m_console->model()->rowCount() - 1).sequence,
             log->lastSequence());
    auto *status = m_console->findChild<QLabel *>(QStringLiteral("consoleStatus"));
    QVERIFY(status);
    QVERIFY2(status->text().contains(QStringLiteral("not kept while the console was closed")),
             qPrintable(status->text()));

    m_console->hide();
    transactions(TrafficLog::idleCapacity);
    QTest::qWait(200);
    QCOMPARE(m_console->model()->rowCount(), TrafficLog::idleCapacity);
    m_console->show();
    // Every frame since is there: nothing was dropped while hidden with the full log.
    QTRY_COMPARE(m_console->model()->rowCount(), 3 * TrafficLog::idleCapacity);
    QVERIFY2(!status->text().contains(QStringLiteral("not kept")), qPrintable(status->text()));
}

QTEST_MAIN(TestToolsConsole)
#include "tst_tools_console.moc"
