#pragma once

#include "checkoutplan.h"
#include "core/watch/csvfile.h"

#include <QByteArray>
#include <QString>

#include <functional>
#include <vector>

namespace Fatek {

// What an I/O checkout report says, before it is laid out: the header fields, one row per point
// and the summary, as messages and data. The CSV is written here (plain, Qt Core); the PDF by
// report/checkoutpdf (Qt Gui). Both take the function that turns a message into text: English by
// default, the UI's translation (or the report library's zh_TW) otherwise.
struct CheckoutReport
{
    using TextFunction = std::function<QString(const Message &)>;

    struct Field
    {
        Message label;
        Message value;
    };
    struct Row
    {
        QString address;
        QString name; // the symbol, and its comment after " - " when both are known
        QString group;
        CheckoutKind kind = CheckoutKind::Input;
        CheckoutResult result = CheckoutResult::Untested;
        Message measured;
        QString comment;
        QString time; // local "yyyy-MM-dd HH:mm:ss +08:00", empty when untested
        QString engineer;
        int attempts = 0; // tests with a result, this one included
    };
    // A point on the punch list: failed or deferred now, or earlier and since mended.
    struct PunchRow
    {
        QString address;
        QString name;
        CheckoutResult result = CheckoutResult::Untested; // the latest
        QString remark; // of the latest failure or deferral (the reason, what was wrong)
        QString owner;
        Message state; // open, or closed when and by whom
        bool closed = false;
    };
    // CSV line ends: LF, or CRLF for programs on Windows that want them (CsvFile writes both).
    using LineEnds = CsvFile::LineEnd;

    // Project, customer, PLC model, OS version, station, the test dates, when the report was
    // made, and who recorded the results (with how many each).
    std::vector<Field> fields;
    std::vector<Row> rows;
    std::vector<PunchRow> punch;
    Message summary;
    // For every page's running header and the signature block.
    QString project;
    QString customer;
    QString documentId;
    QString revision;
    QString engineer;  // who recorded the most results (the plan's engineer when none)
    QString made;      // when the report was made, local with its UTC offset
    CheckoutInfo info; // the signatories' printed names and companies

    // A time as the report prints it: local, with its UTC offset ("2026-12-07 09:00:00 +08:00"),
    // so a report read in another time zone still says when.
    static QString timeText(const QDateTime &time);

    // `date`: when the report is made (now when invalid).
    static CheckoutReport of(const CheckoutPlan &plan, const QDateTime &date = {});
    // The column titles of the rows, in order, and of the punch list.
    static std::vector<Message> columns();
    static std::vector<Message> punchColumns();

    // CSV: "# label: value" lines, a header line, one line per point, "# summary". UTF-8 with a
    // byte order mark, so that Excel reads it as UTF-8 (our readers skip it).
    QByteArray toCsv(const TextFunction &text = {}, LineEnds ends = LineEnds::Lf) const;
    // The punch list alone, the same way.
    QByteArray punchCsv(const TextFunction &text = {}, LineEnds ends = LineEnds::Lf) const;
};

} // namespace Fatek
