// AddressRange: the one grammar for ranges of addresses, "R0..R9" (watch lists, fatek-cli) and
// "Y0-255" (forcing tools), with its errors.
#include "core/protocol/addressrange.h"

#include <QTest>

using namespace Fatek;

namespace {

QString text(const std::string &s)
{
    return QString::fromStdString(s);
}

} // namespace

class TestAddressRange : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void parse_data();
    void parse();
    void errors_data();
    void errors();
    void toStringParsesBack();
    void addresses();
    void list_data();
    void list();
};

void TestAddressRange::parse_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("first");
    QTest::addColumn<int>("count");
    QTest::addColumn<QString>("last");
    QTest::newRow("dots") << "R0..R9"
                          << "R0" << 10 << "R9";
    QTest::newRow("dots, number only") << "R100..163"
                                       << "R100" << 64 << "R163";
    QTest::newRow("dash") << "Y0-255"
                          << "Y0" << 256 << "Y255";
    QTest::newRow("dash, symbol repeated") << "X16-X31"
                                           << "X16" << 16 << "X31";
    QTest::newRow("dots, lower case") << "m100..199"
                                      << "M100" << 100 << "M199";
    QTest::newRow("single") << "M100"
                            << "M100" << 1 << "M100";
    QTest::newRow("single register") << "R12"
                                     << "R12" << 1 << "R12";
    QTest::newRow("blanks everywhere") << "  y 0 - 15 "
                                       << "Y0" << 16 << "Y15";
    QTest::newRow("blanks around dots") << " r100 .. r103 "
                                        << "R100" << 4 << "R103";
    QTest::newRow("W step, dash") << "WY0-32"
                                  << "WY0" << 3 << "WY32";
    QTest::newRow("W step, dots") << "WY0..WY32"
                                  << "WY0" << 3 << "WY32";
    QTest::newRow("double words") << "DR0..DR4"
                                  << "DR0" << 3 << "DR4";
    QTest::newRow("same ends") << "R5-5"
                               << "R5" << 1 << "R5";
    QTest::newRow("to the end") << "R65530..R65535"
                                << "R65530" << 6 << "R65535";
}

void TestAddressRange::parse()
{
    QFETCH(QString, input);
    QFETCH(QString, first);
    QFETCH(int, count);
    QFETCH(QString, last);
    const Result<AddressRange> r = AddressRange::parse(input.toStdString());
    QVERIFY2(r.ok(), r.ok() ? "" : r.error().text().c_str());
    QCOMPARE(text(r->start.toString()), first);
    QCOMPARE(r->count, std::uint32_t(count));
    QCOMPARE(text(r->last().toString()), last);
}

void TestAddressRange::errors_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("message");
    QTest::newRow("backwards, dots")
        << "R103..R100"
        << "Range \"R103..R100\" runs backwards: write the lower address first (R100..R103).";
    QTest::newRow("backwards, dash")
        << "Y10-2"
        << "Range \"Y10-2\" runs backwards: write the lower address first (Y2-Y10).";
    QTest::newRow("mixed, dots")
        << "R100..D103"
        << "Range \"R100..D103\" mixes R100 and D103: both ends must be the same element type.";
    QTest::newRow("mixed, dash")
        << "X0-Y5"
        << "Range \"X0-Y5\" mixes X0 and Y5: both ends must be the same element type.";
    QTest::newRow("off step")
        << "WY0-40"
        << "Range \"WY0-40\" does not end on a whole element: WY elements are 16 apart "
           "(WY0, WY16, ...).";
    QTest::newRow("no end, dots")
        << "R100.."
        << "Incomplete range \"R100..\": write it as first..last, e.g. R100..R163.";
    QTest::newRow("no end, dash")
        << "Y0 -"
        << "Incomplete range \"Y0 -\": write it as first..last, e.g. R100..R163.";
    QTest::newRow("no start, dots")
        << "..R5"
        << "Incomplete range \"..R5\": write it as first..last, e.g. R100..R163.";
    QTest::newRow("no start, dash")
        << "-5"
        << "Invalid address \"-5\": it must start with an element type such as R, X or DWM.";
    QTest::newRow("minus sign, no range")
        << "R-1"
        << "Invalid address \"R-1\": \"-1\" is not a decimal element number.";
    QTest::newRow("bad start")
        << "R-1..R5"
        << "Invalid address \"R-1\": \"-1\" is not a decimal element number.";
    QTest::newRow("end out of range")
        << "M9990-10010"
        << "Address M10010 is out of range: M numbers go from 0 to 9999.";
    QTest::newRow("garbage") << "hello"
                             << "Invalid address \"hello\": unknown element type \"hello\" "
                                "(known: X Y M S T C, WX..WC, RT RC R D F, DWX..DWC, DRT DRC DR "
                                "DD DF).";
    QTest::newRow("number too large")
        << "Y0-99999999999"
        << "Invalid address \"Y99999999999\": element number too large.";
    QTest::newRow("empty") << "  "
                           << "Empty address: type an element such as R12 or X0.";
}

void TestAddressRange::errors()
{
    QFETCH(QString, input);
    QFETCH(QString, message);
    const Result<AddressRange> r = AddressRange::parse(input.toStdString());
    QVERIFY(!r.ok());
    QCOMPARE(text(r.error().text()), message);
    QCOMPARE(r.error().kind, ErrorKind::InvalidAddress);
}

void TestAddressRange::toStringParsesBack()
{
    for (const char *input : {"Y0-255", "M7", "WY0-32", "DR10-14", "R0-65535", "X16-31"}) {
        const Result<AddressRange> r = AddressRange::parse(input);
        QVERIFY2(r.ok(), input);
        QCOMPARE(text(r->toString()), QLatin1String(input));
        const Result<AddressRange> again = AddressRange::parse(r->toString());
        QVERIFY(again.ok());
        QVERIFY(*again == *r);
    }
}

void TestAddressRange::addresses()
{
    const Result<AddressRange> r = AddressRange::parse("DWM0..DWM64");
    QVERIFY(r.ok());
    const std::vector<Address> all = r->addresses();
    QCOMPARE(all.size(), std::size_t(3));
    QCOMPARE(text(all[0].toString()), QStringLiteral("DWM0"));
    QCOMPARE(text(all[1].toString()), QStringLiteral("DWM32"));
    QCOMPARE(text(all[2].toString()), QStringLiteral("DWM64"));
}

void TestAddressRange::list_data()
{
    QTest::addColumn<QString>("input");
    QTest::addColumn<QString>("expected"); // ranges joined by ";", or the error message
    QTest::newRow("commas and blanks") << "X0-7, Y 0 - 15; S3"
                                       << "X0-7;Y0-15;S3";
    QTest::newRow("both grammars") << "R0..R9 Y0-255"
                                   << "R0-9;Y0-255";
    QTest::newRow("blanks only") << "M0 M1   M2"
                                 << "M0;M1;M2";
    QTest::newRow("empty") << " ,; "
                           << "No range given; write for example X0-255, Y0-255.";
    QTest::newRow("one bad")
        << "X0-7, Y10-2"
        << "Range \"Y10-2\" runs backwards: write the lower address first (Y2-Y10).";
}

void TestAddressRange::list()
{
    QFETCH(QString, input);
    QFETCH(QString, expected);
    const auto r = AddressRange::parseList(input.toStdString());
    if (!r.ok()) {
        QCOMPARE(text(r.error().text()), expected);
        return;
    }
    QStringList got;
    for (const AddressRange &range : *r)
        got << text(range.toString());
    QCOMPARE(got.join(QLatin1Char(';')), expected);
}

QTEST_GUILESS_MAIN(TestAddressRange)
#include "tst_addressrange.moc"
