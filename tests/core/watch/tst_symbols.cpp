// The ladder project's names: a comment/symbol list (CSV or tab-separated, UTF-8 or Big5) read
// into a SymbolTable, and the table kept in the watch list file.
#include "core/watch/symbolimport.h"
#include "core/watch/watchlist.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Fatek;

namespace {

Address addr(const char *text)
{
    return *Address::parse(text);
}

QString u(const char *utf8)
{
    return QString::fromUtf8(utf8);
}

QStringList problemTexts(const SymbolImport &result)
{
    QStringList texts;
    for (const Message &m : result.problems())
        texts << QString::fromStdString(english(m));
    return texts;
}

SymbolImport imported(const QByteArray &bytes)
{
    auto result = SymbolImport::fromBytes(bytes);
    if (!result)
        qFatal("import failed: %s", result.error().text().c_str());
    return std::move(result).value();
}

} // namespace

class TestSymbols : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void utf8CsvWithHeader()
    {
        // As a spreadsheet saves it: BOM, header, CRLF, Chinese names.
        const QByteArray csv = "\xEF\xBB\xBF"
                               "Address,Name,Comment\r\n"
                               "R00012,\xE6\xB6\xB2\xE4\xBD\x8D,Tank level in cm\r\n"
                               "X0,Start button,\r\n"
                               "\r\n"
                               "# a remark\r\n"
                               "Y3,,Valve open\r\n";
        const SymbolImport result = imported(csv);
        QCOMPARE(result.encoding(), SymbolImport::Encoding::Utf8);
        QCOMPARE(result.imported(), 3);
        QCOMPARE(result.skipped(), 0);
        QCOMPARE(result.symbols().size(), 3);
        QCOMPARE(result.symbols().name(addr("R12")), u("液位"));
        QCOMPARE(result.symbols().comment(addr("R12")), u("Tank level in cm"));
        QCOMPARE(result.symbols().name(addr("X0")), u("Start button"));
        QCOMPARE(result.symbols().comment(addr("X0")), QString());
        QCOMPARE(result.symbols().name(addr("Y3")), QString());
        QCOMPARE(result.symbols().comment(addr("Y3")), u("Valve open"));
        QCOMPARE(QString::fromStdString(english(result.summary())),
                 u("Names imported: 3, lines skipped: 0"));
    }

    void tabSeparatedWithoutHeader()
    {
        // Commas inside a tab-separated comment stay in the comment.
        const QByteArray text = "R12\tTank level\tcm, from sensor A\n"
                                "M100\tPump run\n"
                                "DR20\tFlow total\ttotal, litres; since reset\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.imported(), 3);
        QCOMPARE(result.skipped(), 0);
        QCOMPARE(result.symbols().name(addr("R12")), u("Tank level"));
        QCOMPARE(result.symbols().comment(addr("R12")), u("cm, from sensor A"));
        QCOMPARE(result.symbols().name(addr("M100")), u("Pump run"));
        QCOMPARE(result.symbols().comment(addr("DR20")), u("total, litres; since reset"));
    }

    void semicolons()
    {
        const QByteArray text = "address;name;comment\n"
                                "R12;Tank level;cm, approx.\n"
                                "T5;Delay;\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.imported(), 2);
        QCOMPARE(result.symbols().comment(addr("R12")), u("cm, approx."));
        QCOMPARE(result.symbols().name(addr("T5")), u("Delay"));
    }

    void quotedFields()
    {
        const QByteArray text = "R12,\"Tank, level\",\"say \"\"hi\"\", then go\"\n"
                                "  \"R13\" , \"Pressure\" ,\"bar\"\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.skipped(), 0);
        QCOMPARE(result.symbols().name(addr("R12")), u("Tank, level"));
        QCOMPARE(result.symbols().comment(addr("R12")), u("say \"hi\", then go"));
        QCOMPARE(result.symbols().name(addr("R13")), u("Pressure"));
        QCOMPARE(result.symbols().comment(addr("R13")), u("bar"));
    }

    void big5()
    {
        // "液位" is B2 47 A6 EC and "馬達啟動" B0 A8 B9 46 B1 D2 B0 CA in Big5 (iconv -t BIG5);
        // B2 47 is not UTF-8, so the file is read as Big5.
        const QByteArray text
            = "\xA6\xEC\xA7\x7D,\xA6\x57\xBA\xD9,\xB5\xF9\xB8\xD1\r\n" // 位址,名稱,註解
              "R00012,\xB2\x47\xA6\xEC,cm\r\n"
              "Y0,\xB0\xA8\xB9\x46\xB1\xD2\xB0\xCA,\xB2\x47\xA6\xEC\r\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.encoding(), SymbolImport::Encoding::Big5);
        QCOMPARE(result.imported(), 2);
        QCOMPARE(result.skipped(), 0);
        QCOMPARE(result.symbols().name(addr("R12")), u("液位"));
        QCOMPARE(result.symbols().name(addr("Y0")), u("馬達啟動"));
        QCOMPARE(result.symbols().comment(addr("Y0")), u("液位"));
        QCOMPARE(QString::fromStdString(english(result.summary())),
                 u("Names imported: 2, lines skipped: 0; read as Big5"));
    }

    void big5BadBytesSkipLine()
    {
        // A lead byte (B2) followed by a byte that cannot end a character (a space): that line
        // goes, the others stay.
        const QByteArray text = "R1,\xB2\x47\xA6\xEC\n"
                                "R2,\xB2 level\n"
                                "R3,\xB0\xA8\xB9\x46\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.encoding(), SymbolImport::Encoding::Big5);
        QCOMPARE(result.imported(), 2);
        QCOMPARE(result.skipped(), 1);
        QCOMPARE(problemTexts(result),
                 QStringList{u("line 2: the line is neither UTF-8 nor Big5 text")});
        QCOMPARE(result.symbols().name(addr("R3")), u("馬達"));
    }

    void badLinesReportedWithLineNumbers()
    {
        const QByteArray text = "Address,Name,Comment\n"   // 1
                                "R12,Tank level,cm\n"      // 2
                                "R70000,Too far,\n"        // 3: no such register
                                "\n"                       // 4
                                "Q5,What,\n"               // 5: no such element type
                                ",Orphan name,\n"          // 6
                                "X1\n"                     // 7: neither name nor comment
                                "R13,\"open quote,\n"      // 8
                                "R14,\"Name\" trailing,\n" // 9
                                "R15,Pressure,bar\n"       // 10
                                "R16,Speed,rpm";           // 11, no final line end
        const SymbolImport result = imported(text);
        QCOMPARE(result.imported(), 3);
        QCOMPARE(result.skipped(), 6);
        QCOMPARE(result.symbols().name(addr("R12")), u("Tank level"));
        QCOMPARE(result.symbols().name(addr("R15")), u("Pressure"));
        QCOMPARE(result.symbols().name(addr("R16")), u("Speed"));
        const QStringList problems = problemTexts(result);
        QCOMPARE(problems.size(), SymbolImport::maxProblems);
        QVERIFY2(problems.at(0).startsWith(u("line 3: ")), qPrintable(problems.at(0)));
        QVERIFY2(problems.at(0).contains(u("R70000")), qPrintable(problems.at(0)));
        QVERIFY2(problems.at(1).startsWith(u("line 5: ")), qPrintable(problems.at(1)));
        QCOMPARE(problems.at(2), u("line 6: no address in the first column"));
        QCOMPARE(problems.at(3), u("line 7: X1 has neither a name nor a comment"));
        QCOMPARE(problems.at(4),
                 u("line 8: a quoted field is not closed on its line (missing \")"));
        const QString summary = QString::fromStdString(english(result.summary()));
        QVERIFY2(summary.startsWith(u("Names imported: 3, lines skipped: 6 (line 3: ")),
                 qPrintable(summary));
        QVERIFY2(summary.endsWith(u("; and 1 more)")), qPrintable(summary));
    }

    void firstLineBadAddressIsNoHeader()
    {
        // A header's first cell holds no digit: "R99999" on line 1 is a bad address, reported.
        const SymbolImport result = imported("R99999,Too far\nR1,One\n");
        QCOMPARE(result.imported(), 1);
        QCOMPARE(result.skipped(), 1);
        QVERIFY2(problemTexts(result).value(0).startsWith(u("line 1: ")),
                 qPrintable(problemTexts(result).value(0)));
        // Without a digit it names the columns.
        const SymbolImport header = imported("\xE4\xBD\x8D\xE5\x9D\x80\tName\nR1\tOne\n");
        QCOMPARE(header.imported(), 1);
        QCOMPARE(header.skipped(), 0);
    }

    void addressesNormalised()
    {
        // R00012 and R12 are one key: the later line wins.
        const QByteArray text = "R00012,Old name,\n"
                                "r12,Tank level,cm\n"
                                "X0016,Door closed,\n";
        const SymbolImport result = imported(text);
        QCOMPARE(result.imported(), 3);
        QCOMPARE(result.symbols().size(), 2);
        QCOMPARE(result.symbols().name(addr("R12")), u("Tank level"));
        QCOMPARE(result.symbols().name(addr("R00012")), u("Tank level"));
        QCOMPARE(result.symbols().name(addr("X16")), u("Door closed"));
        QVERIFY(!result.symbols().find(addr("R13")));
    }

    void tableMergeAndRemove()
    {
        SymbolTable table;
        table.insert(addr("R1"), {u("One"), {}});
        table.insert(addr("R2"), {u("Two"), u("second")});
        SymbolTable update;
        update.insert(addr("R2"), {u("Zwei"), {}});
        update.insert(addr("R3"), {u("Three"), {}});
        table.merge(update);
        QCOMPARE(table.size(), 3);
        QCOMPARE(table.name(addr("R2")), u("Zwei"));
        QCOMPARE(table.comment(addr("R2")), QString());
        table.insert(addr("R1"), {});
        QCOMPARE(table.size(), 2);
    }

    void fileErrors()
    {
        const auto missing = SymbolImport::fromFile(QStringLiteral("/nonexistent/names.csv"));
        QVERIFY(!missing);
        QVERIFY(QString::fromStdString(missing.error().text()).startsWith(u("Cannot read ")));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("names.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("R12\tTank level\n");
        f.close();
        const auto read = SymbolImport::fromFile(path);
        QVERIFY(read);
        QCOMPARE(read->symbols().name(addr("R12")), u("Tank level"));
    }

    void savedWithTheWatchList()
    {
        WatchListFile file;
        WatchTableSpec table;
        table.name = u("Main");
        WatchItemSpec item;
        item.address = addr("R12");
        table.items = {item};
        file.tables = {table};
        // Without names the file is as before (no "symbols" key).
        QVERIFY(!WatchList::save(file).contains("symbols"));

        file.symbols.insert(addr("R12"), {u("液位"), u("cm")});
        file.symbols.insert(addr("X0"), {u("Start"), {}});
        const QByteArray json = WatchList::save(file);
        QVERIFY(json.contains("\"symbols\""));
        QVERIFY(json.contains("\"version\": 1"));
        const auto loaded = WatchList::load(json);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().text().c_str());
        QCOMPARE(*loaded, file);

        // A bad entry is refused with its place, as items are.
        const QByteArray bad = "{\"format\":\"fatek-studio-watchlist\",\"version\":1,\"tables\":[],"
                               "\"symbols\":[{\"address\":\"R1\",\"name\":\"a\"},"
                               "{\"address\":\"Q9\",\"name\":\"b\"}]}";
        const auto refused = WatchList::load(bad);
        QVERIFY(!refused);
        QVERIFY2(QString::fromStdString(refused.error().text()).startsWith(u("symbol 2: ")),
                 refused.error().text().c_str());
    }
};

QTEST_GUILESS_MAIN(TestSymbols)
#include "tst_symbols.moc"
