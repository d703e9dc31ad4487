#pragma once

#include "address.h"
#include "plcstatus.h"

#include <QList>
#include <QString>

namespace Fatek {

// A run of consecutive discretes ("Y0-255"), as the forcing tools scan them.
struct DiscreteRange
{
    Address start{ElementType::X, 0};
    quint32 count = 1;

    Address last() const { return start.advanced(count - 1); }
    // "Y0-255", or "Y7" for one point.
    QString toString() const;

    // One range: "Y0-255", "y0..255", "M100", "X16-X31". Only X Y M S T C are accepted.
    static Result<DiscreteRange> parse(const QString &text);
    // Several, separated by commas, semicolons or spaces: "X0-255, Y0-255 M0-999".
    static Result<QList<DiscreteRange>> parseList(const QString &text);
    // "X0-255, Y0-255, M0-2001" for a list.
    static QString listText(const QList<DiscreteRange> &ranges);

    // What a scan covers when the PLC's sizes are unknown: X/Y 0-255, M 0-1023, S/T/C 0-255.
    static QList<DiscreteRange> defaults();
    // Every X Y M S T C point the PLC has, from the sizes of its detail status (53). Kinds whose
    // size the answer does not carry keep their default range and are listed in `unreported`.
    static QList<DiscreteRange> wholePlc(const DetailStatus &status,
                                         QList<ElementType> *unreported = nullptr);
};

} // namespace Fatek
