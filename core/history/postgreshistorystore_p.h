#pragma once

// What the two source files of PostgresHistoryStore share (postgreshistorystore.cpp, the store;
// postgreshistoryretention.cpp, its retention): libpq and the retry of a call on a lost
// connection. Included by those two only.
#include "postgreshistorystore.h"

#include <libpq-fe.h>

namespace Fatek {

template<typename T, typename Op>
Result<T> PostgresHistoryStore::retried(Failure id, Op op) const
{
    const bool wasLost = PQstatus(m_conn) != CONNECTION_OK;
    if (Status up = connected(id); !up)
        return up.error();
    Result<T> result = op();
    // Lost during this call on a connection that looked fine (the server restarted since the
    // last call): once more on a new one. A failure right after a reset is the answer.
    if (result || wasLost || PQstatus(m_conn) == CONNECTION_OK)
        return result;
    if (Status up = connected(id); !up)
        return up.error();
    return op();
}

} // namespace Fatek
