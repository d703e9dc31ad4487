// Watch list loaders on arbitrary bytes: the JSON loader, the CSV import and the range syntax.
// The first byte picks the loader. Whatever the JSON loader accepts is valid and saves to a file
// that loads back to the same tables; whatever the CSV import accepts is a valid watch row.
#include "core/watch/watchlist.h"

#include <cstdlib>

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const QByteArray bytes(reinterpret_cast<const char *>(data + 1),
                           static_cast<qsizetype>(size - 1));
    switch (data[0] % 3) {
    case 0: {
        const auto file = WatchList::load(bytes);
        if (!file)
            return 0;
        if (!WatchList::validate(*file).ok())
            std::abort();
        const auto again = WatchList::load(WatchList::save(*file));
        if (!again || *again != *file)
            std::abort();
        break;
    }
    case 1: {
        const auto rows = WatchList::importCsv(bytes);
        if (!rows)
            return 0;
        for (const WatchItemSpec &row : *rows) {
            if (!WatchList::validateEntry(row).ok())
                std::abort();
        }
        break;
    }
    default: {
        const auto addresses = WatchList::expandRange(QString::fromUtf8(bytes));
        if (addresses && (addresses->isEmpty() || addresses->size() > WatchList::MaxRangeItems))
            std::abort();
        break;
    }
    }
    return 0;
}
