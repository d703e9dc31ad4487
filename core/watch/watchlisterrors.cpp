#include "watchlisterrors.h"

#include "watchlist.h"

#include <QStringList>

namespace Fatek::WatchList::Errors {

ProtocolError fileError(const QString &message)
{
    return makeError(ErrorKind::InvalidRequest, message.toStdString());
}

QString lowerFirst(const QString &text)
{
    if (text.size() >= 2 && text[0].isUpper() && text[1].isLower())
        return text[0].toLower() + text.mid(1);
    return text;
}

ProtocolError atPlace(const QString &place, const ProtocolError &error)
{
    ProtocolError e = error;
    e.message = (place + QStringLiteral(": ") + lowerFirst(QString::fromStdString(error.message)))
                    .toStdString();
    return e;
}

QString knownFormats()
{
    QStringList names;
    for (DisplayFormat f : ValueFormat::allFormats())
        names.append(ValueFormat::name(f));
    return names.join(QStringLiteral(", "));
}

QString tablePlace(qsizetype table)
{
    return QStringLiteral("table %1").arg(table + 1);
}

ProtocolError tooManyItems(qsizetype count)
{
    return fileError(QStringLiteral("%1 items are more than one table holds (at most %2)")
                         .arg(count)
                         .arg(MaxTableItems));
}

QString itemPlace(qsizetype table, qsizetype item)
{
    return QStringLiteral("table %1, item %2").arg(table + 1).arg(item + 1);
}

QString linePlace(int line)
{
    return QStringLiteral("line %1").arg(line);
}

} // namespace Fatek::WatchList::Errors
