#include "historystore.h"

#include "historymessages.h"
#include "sqlitehistorystore.h"

#ifdef FATEK_HAVE_POSTGRES
#include "postgreshistorystore.h"
#endif

namespace Fatek {

namespace {

bool isPostgresUrl(const QString &location)
{
    return location.startsWith(QLatin1String("postgresql://"), Qt::CaseInsensitive)
           || location.startsWith(QLatin1String("postgres://"), Qt::CaseInsensitive);
}

#ifndef FATEK_HAVE_POSTGRES
// The URL as a message may show it: "user:password@" loses its password.
std::string withoutPassword(const QString &url)
{
    QString shown = url;
    const qsizetype scheme = shown.indexOf(QLatin1String("://")) + 3;
    const qsizetype at = shown.indexOf(QLatin1Char('@'), scheme);
    if (at > 0) {
        const qsizetype colon = shown.indexOf(QLatin1Char(':'), scheme);
        if (colon > 0 && colon < at)
            shown.remove(colon, at - colon);
    }
    return shown.toStdString();
}
#endif

} // namespace

Result<std::unique_ptr<HistoryStore>> HistoryStore::open(const QString &location, Mode mode)
{
    if (isPostgresUrl(location)) {
#ifdef FATEK_HAVE_POSTGRES
        return PostgresHistoryStore::open(location, mode);
#else
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::HistoryNoPostgres>(withoutPassword(location)));
#endif
    }
    return SqliteHistoryStore::open(location, mode);
}

bool HistoryStore::hasPostgres()
{
#ifdef FATEK_HAVE_POSTGRES
    return true;
#else
    return false;
#endif
}

} // namespace Fatek
