#pragma once

#include "core/protocol/addressrange.h"
#include "core/protocol/plcstatus.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace Fatek {

// Which discretes the forcing tools scan: ranges typed in AddressRange's grammar ("X0-255, Y0-255
// M 0 - 999"), of X Y M S T C only, or every point a PLC has.
class DiscreteScan
{
    Q_DECLARE_TR_FUNCTIONS(Fatek::DiscreteScan)

public:
    // Several ranges, separated by commas, semicolons or blanks; one of another type is an error.
    static Result<QList<AddressRange>> parse(const QString &text);
    // "X0-255, Y0-255, M0-2001" for a list.
    static QString listText(const QList<AddressRange> &ranges);

    // What a scan covers when the PLC's sizes are unknown: X/Y 0-255, M 0-1023, S/T/C 0-255.
    static QList<AddressRange> defaults();
    // Every X Y M S T C point the PLC has, from the sizes of its detail status (53). Kinds whose
    // size the answer does not carry keep their default range and are listed in `unreported`.
    static QList<AddressRange> wholePlc(const DetailStatus &status,
                                        QList<ElementType> *unreported = nullptr);
};

} // namespace Fatek
