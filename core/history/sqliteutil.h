#pragma once

// What the SQLite store's two sources share (sqlitehistorystore.cpp, sqlitehistoryretention.cpp):
// statement ownership and the file's name in messages. Internal to core/history.

#include "core/protocol/result.h"

#include <QDir>
#include <QString>

#include <sqlite3.h>

#include <memory>
#include <string>

namespace Fatek::SqliteUtil {

struct StmtDeleter
{
    void operator()(sqlite3_stmt *stmt) const { sqlite3_finalize(stmt); }
};
using Stmt = std::unique_ptr<sqlite3_stmt, StmtDeleter>;

// A kept statement, reset and unbound when the call that used it ends.
class StmtUse
{
public:
    explicit StmtUse(sqlite3_stmt *stmt)
        : m_stmt(stmt)
    {}
    ~StmtUse()
    {
        sqlite3_reset(m_stmt);
        sqlite3_clear_bindings(m_stmt);
    }
    StmtUse(const StmtUse &) = delete;
    StmtUse &operator=(const StmtUse &) = delete;

private:
    sqlite3_stmt *m_stmt;
};

inline bool isBusy(int rc)
{
    return (rc & 0xff) == SQLITE_BUSY || (rc & 0xff) == SQLITE_LOCKED;
}

inline std::string reasonOf(sqlite3 *db)
{
    return sqlite3_errmsg(db);
}

inline std::string fileOf(const QString &path)
{
    return QDir::toNativeSeparators(path).toStdString();
}

inline Result<sqlite3_stmt *> prepare(sqlite3 *db, const char *sql, Stmt &owner)
{
    sqlite3_stmt *raw = nullptr;
    const int rc = sqlite3_prepare_v2(db, sql, -1, &raw, nullptr);
    owner.reset(raw);
    if (rc != SQLITE_OK)
        return makeError(ErrorKind::InvalidRequest, Message::text(reasonOf(db)));
    return raw;
}

} // namespace Fatek::SqliteUtil
