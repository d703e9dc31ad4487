// Translations: every message of the .ts files is finished and keeps its placeholders; with the
// zh_TW translator the main window running the demo (tables, connections, docks, menus, actions,
// status bar) shows no English words; core messages come out in Chinese.
#include "ui/common/uitext.h"
#include "ui/connection/connectionlistmodel.h"
#include "ui/connection/connectionspanel.h"
#include "ui/mainwindow/languagemenu.h"
#include "ui/mainwindow/mainwindow.h"
#include "ui/tools/discretetablemodel.h"
#include "ui/tools/forcingpanel.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

#include "core/protocol/address.h"
#include "core/protocol/addressrange.h"
#include "core/protocol/frametext.h"
#include "core/protocol/protocolerror.h"
#include "core/watch/valueformat.h"
#include "core/watch/watchlist.h"
#include "testutil.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextDocumentFragment>
#include <QTranslator>
#include <QXmlStreamReader>

using namespace Fatek;

namespace {

// What may stay in Latin letters in the Chinese UI, each a technical token a technician types or
// reads on the PLC, its manual or the keyboard, never a sentence word:
//   element types and addresses (R, DWM, R100, DR10, X0..X15), hex (0x1A, 1Ah, 0C), key names
//   (F2, Ctrl, Shift, Enter), file patterns (*.csv), command-line options (--read-only)
//   the product and protocol names (FATEK Studio, FACON, Windows, SQLite, PostgreSQL, Home
//   Assistant), link and
//   frame terms (TCP, UDP, IP, RTT, RS-232/485, RTS/CTS, XON/XOFF, STX, ETX, NUL, LRC, CRC, ASCII,
//   BCD, CSV, JSON, PNG, PLC, ID, OS, HMI, ROM, IPv6), link URLs (tcp://, udp://,
//   serial:///dev/ttyUSB0) and the broker's (MQTT, TLS, CA, URL, mqtt:// and mqtts:// addresses,
//   JSON commands such as
//   {"value":
//   ...}) the PLC's own words as printed on the unit (RUN, STOP, ON, OFF, model names such as
//   FBs-28MC, main unit types MA MU MC)
//   units (ms, Hz);
//   what is typed as it is: a configuration key quoted 「recordAll」, an environment variable
//   ($PGPASSWORD), a file in the home folder (~/.pgpass).
// The language menu also names "English" in English (each language in its own words).
const QRegularExpression allowed(QStringLiteral(
    R"(\bFBs-\d+M[ACU](?:/MU)?\b|\bFATEK Studio\b|\bHome Assistant\b|\b(?:FATEK|FACON|Windows|SQLite|PostgreSQL|TCP|UDP|IP|RTT|RS|RTS|CTS|XON|XOFF|STX|ETX|NUL|LRC|CRC|)"
    R"(ASCII|BCD|CSV|JSON|PDF|PNG|PLC|ID|OS|HMI|ROM|MQTT|TLS|CA|URL|RUN|STOP|ON|OFF|MA|MU|MC|Ctrl|Shift|)"
    R"(Enter|ms|Hz|IPv6)\b|「[a-z][A-Za-z]*」|\$[A-Z_]+\b|~/\.\w+|\b(?:mqtts?|tcp|udp|serial)://[^\s，。）]*|\{"\w+":[^}]*\}|)"
    R"(\b(?:[XYMSTCRDF]|W[XYMSTC]|DW[XYMSTC]|RT|RC|DRT|DRC|DR|DD|DF)(?:\d+)?\b|)"
    R"(\*\.\w+|--[a-z-]+|\b0x[0-9A-Fa-f]+\b|\b[0-9A-F]+h\b|\b[A-Z]{1,3}\d+\b|\b(?=[0-9A-F]*\d)[0-9A-F]{2,}\b)"));
const QRegularExpression englishWord(QStringLiteral("[A-Za-z]{2,}"));

QString plain(const QString &text)
{
    QString t
        = Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
    return t.remove(QLatin1Char('&'));
}

bool hasEnglish(const QString &text)
{
    QString rest = plain(text);
    rest.replace(allowed, QStringLiteral(" "));
    return rest.contains(englishWord);
}

// %1..%99 and %n of a message, as a sorted list (a translation must keep every one).
QStringList placeholders(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("%(\\d+|n)"));
    QStringList list;
    for (auto it = re.globalMatch(text); it.hasNext();)
        list << it.next().captured(0);
    list.sort();
    list.removeDuplicates();
    return list;
}

// Keyboard accelerators ("&File"): a translation keeps one when the source has one.
bool hasAccelerator(const QString &text)
{
    static const QRegularExpression re(QStringLiteral("&(?!&)\\S"));
    return text.contains(re);
}

struct TsMessage
{
    QString context;
    QString source;
    QStringList translations;
    QString type; // the translation's type attribute: empty when finished
};

QList<TsMessage> readTs(const QString &path, QString *language, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<TsMessage> messages;
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("TS")) {
            *language = xml.attributes().value(QLatin1String("language")).toString();
        } else if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            current = TsMessage{context, {}, {}, {}};
        } else if (name == QLatin1String("source")) {
            current.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            current.type = xml.attributes().value(QLatin1String("type")).toString();
            // Plain text, or <numerusform> children.
            QString text;
            while (!xml.atEnd()) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    current.translations << xml.readElementText();
                else if (xml.isEndElement() && xml.name() == QLatin1String("translation"))
                    break;
            }
            if (current.translations.isEmpty())
                current.translations << text;
            messages << current;
        }
    }
    if (xml.hasError())
        *error = xml.errorString();
    return messages;
}

} // namespace

class TestUiTranslation : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_settingsDir.isValid());
        TestUtil::useTestSettings(m_settingsDir.path(), QStringLiteral("tst_ui_translation"));
    }

    void tsFilesAreComplete_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("language");
        QTest::addColumn<int>("forms");
        // English has singular and plural; Chinese one form for every number.
        QTest::newRow("en") << QStringLiteral("fatekstudio_en.ts") << QStringLiteral("en") << 2;
        QTest::newRow("zh_TW") << QStringLiteral("fatekstudio_zh_TW.ts") << QStringLiteral("zh_TW")
                               << 1;
    }

    void tsFilesAreComplete()
    {
        QFETCH(QString, file);
        QFETCH(QString, language);
        QFETCH(int, forms);
        QString error;
        QString tsLanguage;
        const QList<TsMessage> messages = readTs(
            QDir(QStringLiteral(FATEK_TRANSLATIONS_DIR)).filePath(file), &tsLanguage, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(QLocale(tsLanguage).name(), QLocale(language).name()); // lupdate writes en_US
        QVERIFY2(messages.size() > 300, qPrintable(QString::number(messages.size())));
        QStringList problems;
        for (const TsMessage &m : messages) {
            const QString where = QStringLiteral("%1: \"%2\"").arg(m.context, m.source);
            if (!m.type.isEmpty()) {
                problems << QStringLiteral("%1 is %2").arg(where, m.type);
                continue;
            }
            const bool numerus = m.source.contains(QLatin1String("%n"));
            if (numerus && m.translations.size() != forms)
                problems << QStringLiteral("%1 has %2 plural forms")
                                .arg(where)
                                .arg(m.translations.size());
            for (const QString &t : m.translations) {
                if (t.trimmed().isEmpty() && !m.source.trimmed().isEmpty())
                    problems << QStringLiteral("%1 is empty").arg(where);
                else if (placeholders(t) != placeholders(m.source))
                    problems
                        << QStringLiteral("%1 → \"%2\" changes the placeholders").arg(where, t);
                else if (hasAccelerator(m.source) && !hasAccelerator(t))
                    problems << QStringLiteral("%1 → \"%2\" lost its accelerator").arg(where, t);
            }
            // Command-line help ("main") names option values that are typed as they are
            // (--tool control, forcing …): not part of the window.
            if (language == QLatin1String("zh_TW") && m.context != QLatin1String("main")) {
                for (const QString &t : m.translations) {
                    if (hasEnglish(t))
                        problems << QStringLiteral("%1 → \"%2\" is still English").arg(where, t);
                }
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void languageCodes()
    {
        QVERIFY(Language::isKnown(QStringLiteral("zh_TW")));
        QVERIFY(Language::isKnown(QStringLiteral("zh-TW")));
        QVERIFY(Language::isKnown(QStringLiteral("zh_Hant_HK")));
        QVERIFY(Language::isKnown(QStringLiteral("en_GB")));
        QVERIFY(!Language::isKnown(QStringLiteral("fr")));
        QVERIFY(!Language::isKnown(QStringLiteral("zh_CN"))); // Simplified: not shipped
        QVERIFY(!Language::isKnown(QStringLiteral("klingon")));
        // The override wins over the stored choice, which wins over the system.
        Language::setStored(QStringLiteral("en"));
        QCOMPARE(Language::effectiveLocale().language(), QLocale::English);
        QCOMPARE(Language::effectiveLocale(QStringLiteral("zh_TW")).territory(), QLocale::Taiwan);
        Language::setStored({});
        QCOMPARE(Language::effectiveLocale().name(), QLocale::system().name());
    }

    // From here on the application runs in Traditional Chinese.
    void installChinese()
    {
        QVERIFY(Language::install(qApp, QLocale(QStringLiteral("zh_TW"))));
        QCOMPARE(QCoreApplication::translate("Fatek::MainWindow", "&File"),
                 QStringLiteral("檔案(&F)"));
    }

    void coreMessages()
    {
        // Messages made by the real core code come out in Chinese, tokens untouched.
        const auto bad = Address::parse("Q5");
        QVERIFY(!bad);
        const QString address = translated(bad.error().message);
        QVERIFY2(!hasEnglish(address), qPrintable(address));
        QVERIFY2(address.contains(QLatin1String("Q5")), qPrintable(address));

        const QString plc = translated(makePlcError(0xA, "R70000").message);
        QVERIFY2(!hasEnglish(plc), qPrintable(plc));
        QVERIFY2(plc.contains(QLatin1String("R70000")), qPrintable(plc));
        QVERIFY2(plc.contains(QStringLiteral("不合法的位址")), qPrintable(plc));

        const auto range = Address::parse("R65535");
        QVERIFY(range);
        const QString span = translated(validateSpan(*range, 4).error().message);
        QVERIFY2(!hasEnglish(span), qPrintable(span));

        // Range and typed-frame errors are made in core (AddressRange, WatchList, FrameText).
        // Range, typed-frame and typed-value errors are made in core (AddressRange, WatchList,
        // FrameText, ValueFormat).
        std::vector<Message> typed;
        for (const char *text : {"R0..", "X0-Y5", "Y10-2", "WY0-40"})
            typed.push_back(AddressRange::parse(text).error().message);
        typed.push_back(AddressRange::parseList(" , ").error().message);
        typed.push_back(WatchList::expandRange(QStringLiteral("R0..R1024")).error().message);
        typed.push_back(FrameText::parseHex("01 G6").error().message);
        typed.push_back(FrameText::parseHex(" ").error().message);
        typed.push_back(FrameText::parseHex("01 4").error().message);
        typed.push_back(FrameText::parseAscii("01\t40").error().message);
        typed.push_back(FrameText::parseAscii("").error().message);
        for (const char *text : {"12x", "70000"})
            typed.push_back(
                ValueFormat::parse(QString::fromLatin1(text), 16, DisplayFormat::Unsigned, false)
                    .error()
                    .message);
        typed.push_back(
            ValueFormat::parse(QStringLiteral("G"), 16, DisplayFormat::Hex, false).error().message);
        typed.push_back(
            ValueFormat::parse(QStringLiteral("2"), 1, DisplayFormat::Bit, false).error().message);
        for (const Message &message : typed) {
            const QString shown = translated(message);
            const std::string english = Fatek::english(message);
            QVERIFY2(!hasEnglish(shown), qPrintable(shown));
            QVERIFY2(shown != QString::fromStdString(english), english.c_str());
        }

        // A text from outside the program (an OS error) is shown as it came, not mangled.
        QCOMPARE(translated(Message::text("something new")), QStringLiteral("something new"));
        // A reason inside a reason is translated too.
        const QString lost = translated(msg<MsgId::LinkNextAttempt>(
            msg<MsgId::LinkLostBecause>(msg<MsgId::LinkPeerClosed>("TCP 10.0.0.5:500")), "2.0"));
        QVERIFY2(!hasEnglish(lost), qPrintable(lost));
        QVERIFY2(lost.contains(QLatin1String("TCP 10.0.0.5:500")), qPrintable(lost));
        QCOMPARE(UiText::linkState(LinkState::Connected), QStringLiteral("已連線"));
        QCOMPARE(UiText::formatFromName(QStringLiteral("無號整數")), DisplayFormat::Unsigned);
        QCOMPARE(UiText::formatFromName(QStringLiteral("unsigned")), DisplayFormat::Unsigned);
    }

    void mainWindowHasNoEnglish()
    {
        MainWindow window;
        window.show();
        bool ready = false;
        connect(&window, &MainWindow::demoReady, this, [&ready] { ready = true; });
        window.startDemo();
        QTRY_VERIFY_WITH_TIMEOUT(ready, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(window.hasValues(), 20000);
        // The tool docks too: they answer from the demo PLC while they are shown.
        for (const char *tool : {"control", "forcing", "console", "trend", "checkout"}) {
            QWidget *w = window.openTool(QString::fromLatin1(tool));
            QVERIFY2(w, tool);
        }
        QTest::qWait(1500); // let the tools show their first answers

        QStringList found;
        QSet<QString> seen;
        auto check = [&](const QString &where, const QString &text) {
            if (text.isEmpty() || !hasEnglish(text))
                return;
            const QString line = QStringLiteral("%1: \"%2\"").arg(where, plain(text));
            if (!seen.contains(line)) {
                seen.insert(line);
                found << line;
            }
        };
        auto name = [](const QObject *o) {
            return QStringLiteral("%1 %2").arg(QString::fromLatin1(o->metaObject()->className()),
                                               o->objectName());
        };

        check(QStringLiteral("window title"), window.windowTitle());
        QList<QWidget *> widgets = window.findChildren<QWidget *>();
        for (QWidget *w : std::as_const(widgets)) {
            if (!w->isVisible())
                continue;
            const QString where = name(w);
            check(where + QStringLiteral(" tooltip"), w->toolTip());
            check(where + QStringLiteral(" status tip"), w->statusTip());
            if (auto *dock = qobject_cast<QDockWidget *>(w))
                check(where, dock->windowTitle());
            if (auto *label = qobject_cast<QLabel *>(w))
                check(where, label->text());
            if (auto *button = qobject_cast<QAbstractButton *>(w))
                check(where, button->text());
            if (auto *box = qobject_cast<QGroupBox *>(w))
                check(where, box->title());
            if (auto *edit = qobject_cast<QLineEdit *>(w))
                check(where + QStringLiteral(" placeholder"), edit->placeholderText());
            if (auto *combo = qobject_cast<QComboBox *>(w)) {
                for (int i = 0; i < combo->count(); ++i)
                    check(where, combo->itemText(i));
            }
            if (auto *spin = qobject_cast<QSpinBox *>(w)) {
                check(where, spin->prefix());
                check(where, spin->suffix());
                check(where, spin->specialValueText());
            }
            if (auto *tabs = qobject_cast<QTabBar *>(w)) {
                for (int i = 0; i < tabs->count(); ++i) {
                    check(where, tabs->tabText(i));
                    check(where, tabs->tabToolTip(i));
                }
            }
            if (auto *view = qobject_cast<QAbstractItemView *>(w)) {
                const QAbstractItemModel *model = view->model();
                if (!model)
                    continue;
                for (int c = 0; c < model->columnCount(); ++c) {
                    check(where + QStringLiteral(" header"),
                          model->headerData(c, Qt::Horizontal).toString());
                    check(where + QStringLiteral(" header tooltip"),
                          model->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString());
                }
                // Frame bytes (the traffic log's hex and ASCII columns) are wire data, not text.
                const QStringList frameColumns
                    = {QCoreApplication::translate("Fatek::TrafficLogModel", "ASCII"),
                       QCoreApplication::translate("Fatek::TrafficLogModel", "Bytes (hex)")};
                for (int r = 0; r < model->rowCount(); ++r) {
                    for (int c = 0; c < model->columnCount(); ++c) {
                        if (frameColumns.contains(model->headerData(c, Qt::Horizontal).toString()))
                            continue;
                        const QModelIndex index = model->index(r, c);
                        check(where + QStringLiteral(" cell"), index.data().toString());
                        check(where + QStringLiteral(" cell tooltip"),
                              index.data(Qt::ToolTipRole).toString());
                    }
                }
            }
        }
        check(QStringLiteral("status bar"), window.statusBar()->currentMessage());

        // Menus (with their submenus) and every action of the window, shown or in a context menu.
        const auto checkMenu = [&](const QMenu *menu, const auto &self) -> void {
            check(QStringLiteral("menu"), menu->title());
            const bool languages = menu->objectName() == QLatin1String("languageMenu");
            for (const QAction *a : menu->actions()) {
                if (a->menu())
                    self(a->menu(), self);
                else if (!(languages && a->text() == QLatin1String("English")))
                    check(QStringLiteral("menu %1").arg(menu->title()), a->text());
            }
        };
        for (const QAction *a : window.menuBar()->actions()) {
            QVERIFY(a->menu());
            checkMenu(a->menu(), checkMenu);
        }
        for (const QAction *a : window.findChildren<QAction *>()) {
            if (a->parent() && a->parent()->objectName() == QLatin1String("languageMenu"))
                continue;
            check(QStringLiteral("action"), a->text());
            check(QStringLiteral("action tooltip"), a->toolTip());
            check(QStringLiteral("action status tip"), a->statusTip());
        }
        QVERIFY2(found.isEmpty(), qPrintable(QStringLiteral("English in the zh_TW main window:\n")
                                             + found.join(QLatin1Char('\n'))));
        // The walk saw the window working: Chinese headers and a value-carrying demo table.
        QCOMPARE(window.currentWatchTable()->model()->headerData(WatchTableModel::ValueColumn,
                                                                 Qt::Horizontal),
                 QVariant(QStringLiteral("數值")));
    }

    // Issue 34: what was still English although its words are allowed tokens: the PLC's state in
    // the connections list, ON/OFF in the forcing table, the loopback test's greyed text, RUN in
    // a station scan; and the table's new words (the values' age, its menu).
    void issue34LeftoversAreChinese()
    {
        MainWindow window;
        window.show();
        bool ready = false;
        connect(&window, &MainWindow::demoReady, this, [&ready] { ready = true; });
        window.startDemo();
        QTRY_VERIFY_WITH_TIMEOUT(ready, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(window.hasValues(), 20000);

        auto *panel = window.findChild<ConnectionsPanel *>();
        QVERIFY(panel);
        const QModelIndex plc = panel->view()->model()->index(0, ConnectionListModel::PlcColumn);
        QTRY_VERIFY2_WITH_TIMEOUT(plc.data().toString().contains(QStringLiteral("執行")),
                                  qPrintable(plc.data().toString()), 20000);
        QVERIFY2(!plc.data().toString().contains(QStringLiteral("RUN")),
                 qPrintable(plc.data().toString()));

        auto *forcing = qobject_cast<ForcingPanel *>(window.openTool(QStringLiteral("forcing")));
        QVERIFY(forcing);
        const DiscreteTableModel *points = forcing->model();
        QTRY_VERIFY_WITH_TIMEOUT(points->rowCount() > 0, 20000);
        QStringList states;
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                states.clear();
                for (int r = 0; r < points->rowCount(); ++r)
                    states << points->index(r, DiscreteTableModel::StateColumn).data().toString();
                return states.contains(QStringLiteral("導通"))
                       || states.contains(QStringLiteral("斷開"));
            }(),
            20000);
        QVERIFY2(!states.contains(QStringLiteral("ON")) && !states.contains(QStringLiteral("OFF")),
                 qPrintable(states.join(QLatin1Char(' '))));

        QWidget *loopback = window.openTool(QStringLiteral("loopback"));
        QVERIFY(loopback);
        auto *text = loopback->findChild<QLineEdit *>(QStringLiteral("dataText"));
        QVERIFY(text);
        QVERIFY2(!hasEnglish(text->text()), qPrintable(text->text()));
        loopback->close();

        QCOMPARE(QCoreApplication::translate("Fatek::StationScanDialog", "RUN"),
                 QStringLiteral("執行"));
        const QString quality = window.currentWatchTable()
                                    ->model()
                                    ->index(0, WatchTableModel::QualityColumn)
                                    .data()
                                    .toString();
        QVERIFY2(quality.contains(QStringLiteral("秒")), qPrintable(quality));

        // The table's undo and redo, before and after a step, as its menu shows them.
        WatchTableWidget *table = window.currentWatchTable();
        auto *undo = table->findChild<QAction *>(QStringLiteral("undoAction"));
        auto *redo = table->findChild<QAction *>(QStringLiteral("redoAction"));
        QVERIFY(undo && redo);
        QVERIFY2(!hasEnglish(undo->text()) && !hasEnglish(redo->text()),
                 qPrintable(undo->text() + QStringLiteral(" | ") + redo->text()));
        QLineEdit *add = table->addressEdit();
        add->setFocus();
        QTest::keyClicks(add, QStringLiteral("R200"), {}, 50);
        QTest::keyClick(add, Qt::Key_Return);
        QTRY_VERIFY(undo->isEnabled());
        QVERIFY2(!hasEnglish(undo->text()), qPrintable(undo->text()));
        undo->trigger();
        QTRY_VERIFY(redo->isEnabled());
        QVERIFY2(!hasEnglish(redo->text()), qPrintable(redo->text()));
    }
};

QTEST_MAIN(TestUiTranslation)
#include "tst_ui_translation.moc"
