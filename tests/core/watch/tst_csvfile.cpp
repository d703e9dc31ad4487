// CsvFile: CSV text as the bytes of a file Excel on Windows opens right (UTF-8 with the byte
// order mark, LF or CRLF), and the readers taking such a file back.
#include "core/watch/csvfile.h"
#include "core/watch/watchlist.h"

#include <QTest>

using namespace Fatek;

class TestCsvFile : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void bytesStartWithTheMark();
    void crlfWhenAsked();
    void crlfIsNeverDoubled();
    void linesHaveNoMark();
    void lineEndOfAFirstLine();
    void watchListImportReadsCrlfWithMark();
};

void TestCsvFile::bytesStartWithTheMark()
{
    const QString text
        = QStringLiteral("address,name\nR1,") + QString::fromUtf8("液位") + QLatin1Char('\n');
    const QByteArray data = CsvFile::bytes(text, CsvFile::LineEnd::Lf);
    QCOMPARE(data, QByteArray("\xEF\xBB\xBF"
                              "address,name\nR1,\xE6\xB6\xB2\xE4\xBD\x8D\n"));
    QCOMPARE(CsvFile::bytes({}, CsvFile::LineEnd::CrLf), QByteArray("\xEF\xBB\xBF"));
}

void TestCsvFile::crlfWhenAsked()
{
    const QByteArray data = CsvFile::bytes(QStringLiteral("a,b\n1,2\n3,4"), CsvFile::LineEnd::CrLf);
    QCOMPARE(data, QByteArray("\xEF\xBB\xBF"
                              "a,b\r\n1,2\r\n3,4"));
}

void TestCsvFile::crlfIsNeverDoubled()
{
    // A "\r\n" already in the text (a quoted cell from a Windows program) stays one; a lone '\r'
    // stays as it is.
    const QString text = QStringLiteral("a,\"one\r\ntwo\"\nb,x\ry\n\r\n");
    QCOMPARE(CsvFile::bytes(text, CsvFile::LineEnd::CrLf),
             QByteArray("\xEF\xBB\xBF"
                        "a,\"one\r\ntwo\"\r\nb,x\ry\r\n\r\n"));
    QCOMPARE(CsvFile::bytes(text, CsvFile::LineEnd::Lf),
             QByteArray("\xEF\xBB\xBF") + text.toUtf8());
    QCOMPARE(CsvFile::bytes(QStringLiteral("\n"), CsvFile::LineEnd::CrLf),
             QByteArray("\xEF\xBB\xBF\r\n"));
}

void TestCsvFile::linesHaveNoMark()
{
    QCOMPARE(CsvFile::lines(QStringLiteral("x,1\n"), CsvFile::LineEnd::CrLf),
             QByteArray("x,1\r\n"));
    QCOMPARE(CsvFile::lines(QStringLiteral("x,1\n"), CsvFile::LineEnd::Lf), QByteArray("x,1\n"));
}

void TestCsvFile::lineEndOfAFirstLine()
{
    using LE = CsvFile::LineEnd;
    QCOMPARE(CsvFile::lineEndOf("timestamp,R0,status\r\n"), LE::CrLf);
    QCOMPARE(CsvFile::lineEndOf("\xEF\xBB\xBFtimestamp,R0,status\r\n"), LE::CrLf);
    QCOMPARE(CsvFile::lineEndOf("timestamp,R0,status\n"), LE::Lf);
    QCOMPARE(CsvFile::lineEndOf("\r\n"), LE::CrLf);
    QCOMPARE(CsvFile::lineEndOf("\n"), LE::Lf);
    QCOMPARE(CsvFile::lineEndOf("no line end"), LE::Lf);
    QCOMPARE(CsvFile::lineEndOf({}), LE::Lf);
}

void TestCsvFile::watchListImportReadsCrlfWithMark()
{
    // A list saved by Excel on Windows: the mark, CRLF, a quoted cell; the last cell of each row
    // gets no '\r' of the line end.
    const QByteArray data
        = CsvFile::bytes(QStringLiteral("address,name,comment\nR1,\"Tank, A\",cm\nY0,")
                             + QString::fromUtf8("泵") + QStringLiteral(",\n"),
                         CsvFile::LineEnd::CrLf);
    QVERIFY(data.startsWith("\xEF\xBB\xBF") && data.contains("\r\n"));
    const auto items = WatchList::importCsv(data);
    QVERIFY2(items.ok(), items.ok() ? "" : items.error().text().c_str());
    QCOMPARE(items->size(), 2);
    QCOMPARE(items->at(0).address.toString(), std::string("R1"));
    QCOMPARE(items->at(0).name, QStringLiteral("Tank, A"));
    QCOMPARE(items->at(0).comment, QStringLiteral("cm"));
    QCOMPARE(items->at(1).address.toString(), std::string("Y0"));
    QCOMPARE(items->at(1).name, QString::fromUtf8("泵"));
    QCOMPARE(items->at(1).comment, QString());
}

QTEST_GUILESS_MAIN(TestCsvFile)
#include "tst_csvfile.moc"
