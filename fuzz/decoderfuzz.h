#pragma once

// Shared body of the codec fuzzers: every frame a deframer yields goes through the slave-side and
// master-side decoders; a query the slave side accepts must re-encode as a valid request.
#include "core/protocol/codec.h"
#include "core/protocol/deframer.h"

#include <cstdlib>
#include <initializer_list>

namespace Fatek {

inline void fuzzDecoders(const Codec &codec, const std::vector<DeframedItem> &items,
                         std::span<const std::uint8_t> whole, std::span<const Request> probes)
{
    for (const DeframedItem &item : items) {
        if (item.error)
            continue;
        const auto request = codec.decodeRequest(item.frame);
        if (request.ok()) {
            if (!codec.encodeRequest(*request).ok())
                std::abort();
            (void)codec.encodeResponse(*request,
                                       Response{request->station, request->command, 0, {}, {}});
        }
        for (const Request &probe : probes)
            (void)codec.decodeResponse(item.frame, probe);
        (void)codec.summarize(item.frame);
        (void)codec.frameHeader(item.frame);
    }
    // Decoders must also survive frames a deframer would never produce.
    (void)codec.decodeRequest(whole);
    (void)codec.summarize(whole);
}

// Feeds data[1..] in chunks whose size the first byte picks, so splits are explored too.
inline void feedInChunks(std::span<const std::uint8_t> data,
                         std::initializer_list<Deframer *> deframers,
                         std::vector<DeframedItem> &items)
{
    const std::size_t chunk = std::size_t(data[0] % 17) + 1;
    for (std::size_t i = 1; i < data.size(); i += chunk) {
        const auto piece = data.subspan(i, std::min(chunk, data.size() - i));
        for (Deframer *d : deframers) {
            d->feed(piece, items);
            if (d->bufferedBytes() > d->maxFrameSize())
                std::abort();
        }
    }
}

} // namespace Fatek
