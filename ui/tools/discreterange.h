#pragma once

#include "address.h"

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
};

} // namespace Fatek
