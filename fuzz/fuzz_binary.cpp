// Feeds arbitrary bytes through the binary deframers (in random chunk sizes) and every frame it yields
// through the slave-side and master-side decoders. Anything a decoder accepts must re-encode.
#include "binarycodec.h"
#include "binarydeframer.h"

#include <cstdlib>

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const BinaryCodec codec;
    BinaryDeframer queries(BinaryDeframer::Direction::Query);
    BinaryDeframer deframer(BinaryDeframer::Direction::Response);
    std::vector<DeframedItem> items;
    // First byte picks the chunk size so splits are explored too.
    const std::size_t chunk = std::size_t(data[0] % 17) + 1;
    for (std::size_t i = 1; i < size; i += chunk) {
        const auto piece = std::span(data + i, std::min(chunk, size - i));
        deframer.feed(piece, items);
        queries.feed(piece, items);
        if (deframer.bufferedBytes() > deframer.maxFrameSize()
            || queries.bufferedBytes() > queries.maxFrameSize())
            std::abort();
    }
    static const Request probes[] = {
        Request::briefStatus(1),
        Request::readRegisters(1, {ElementType::R, 12}, 3),
        Request::readRegisters(1, {ElementType::DR, 0}, 2),
        Request::readDiscretes(1, {ElementType::X, 0}, 8),
        Request::mixedRead(1, {{ElementType::R, 1}, {ElementType::Y, 9}, {ElementType::DWM, 0}}),
        Request::loopback(1, {'A', 'B'}),
        Request::detailStatus(1),
        Request::readRegisters(1, {ElementType::DF, 2}, 1),
    };
    for (const DeframedItem &item : items) {
        if (item.error)
            continue;
        const auto request = codec.decodeRequest(item.frame);
        if (request.ok()) {
            if (!codec.encodeRequest(*request).ok())
                std::abort(); // a decoded query must be valid
            (void)codec.encodeResponse(*request, Response{request->station, request->command, 0, {}, {}});
        }
        for (const Request &probe : probes)
            (void)codec.decodeResponse(item.frame, probe);
        (void)codec.summarize(item.frame);
        (void)codec.frameHeader(item.frame);
    }
    // Decoders must also survive frames the deframer would never produce.
    (void)codec.decodeRequest(std::span(data, size));
    (void)codec.summarize(std::span(data, size));
    return 0;
}
