#pragma once

#include "checkoutplan.h"

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
    };

    // Project, customer, PLC model, OS version, station, the test dates, when the report was
    // made, and who recorded the results (with how many each).
    std::vector<Field> fields;
    std::vector<Row> rows;
    Message summary;
    // For every page's running header and the signature block.
    QString project;
    QString customer;
    QString engineer; // who recorded the most results (the plan's engineer when none)
    QString made;     // when the report was made, local with its UTC offset

    // A time as the report prints it: local, with its UTC offset ("2026-12-07 09:00:00 +08:00"),
    // so a report read in another time zone still says when.
    static QString timeText(const QDateTime &time);

    // `date`: when the report is made (now when invalid).
    static CheckoutReport of(const CheckoutPlan &plan, const QDateTime &date = {});
    // The column titles of the rows, in order.
    static std::vector<Message> columns();

    // CSV: "# label: value" lines, a header line, one line per point, "# summary" (UTF-8).
    QByteArray toCsv(const TextFunction &text = {}) const;
};

} // namespace Fatek
