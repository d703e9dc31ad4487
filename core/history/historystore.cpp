#include "historystore.h"

#include "core/qtbridge/secrets.h"
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

} // namespace

Result<std::unique_ptr<HistoryStore>> HistoryStore::open(const QString &location, Mode mode)
{
    if (isPostgresUrl(location)) {
#ifdef FATEK_HAVE_POSTGRES
        return PostgresHistoryStore::open(location, mode);
#else
        return makeError(ErrorKind::InvalidRequest,
                         msg<MsgId::HistoryNoPostgres>(Secrets::maskUrl(location).toStdString()));
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
