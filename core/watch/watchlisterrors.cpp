#include "watchlisterrors.h"

#include "jsonkeys.h"
#include "watchlist.h"

#include <QStringList>

namespace Fatek::WatchList::Errors {

ProtocolError fileError(const QString &message)
{
    return makeError(ErrorKind::InvalidRequest, message.toStdString());
}

QString lowerFirst(const QString &text)
{
    return QString::fromStdString(Fatek::lowerFirst(text.toStdString()));
}

ProtocolError atPlace(const Message &place, const ProtocolError &error)
{
    ProtocolError e = error;
    e.message = msg<MsgId::AtPlace>(place, error.message);
    return e;
}

ProtocolError atPlace(const QString &place, const ProtocolError &error)
{
    return atPlace(Message::text(place.toStdString()), error);
}

QString knownFormats()
{
    QStringList names;
    for (DisplayFormat f : ValueFormat::allFormats())
        names.append(ValueFormat::name(f));
    return names.join(QStringLiteral(", "));
}

QString unknownKey(const QString &key, const QStringList &known)
{
    QString text = QStringLiteral("unknown key \"%1\" (known: %2)")
                       .arg(key, known.join(QStringLiteral(", ")));
    if (const QString near = JsonKeys::nearest(key, known); !near.isEmpty())
        text += QStringLiteral("; did you mean \"%1\"?").arg(near);
    return text;
}

Message tablePlace(qsizetype table)
{
    return msg<MsgId::PlaceTable>(table + 1);
}

ProtocolError tooManyItems(qsizetype count)
{
    return makeError(ErrorKind::InvalidRequest,
                     msg<MsgId::WatchListTooManyItems>(count, MaxTableItems));
}

Message itemPlace(qsizetype table, qsizetype item)
{
    return msg<MsgId::PlaceItem>(table + 1, item + 1);
}

Message linePlace(int line)
{
    return msg<MsgId::PlaceLine>(line);
}

} // namespace Fatek::WatchList::Errors
