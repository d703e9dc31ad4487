// Binary deframers (both directions) and codec on arbitrary bytes.
#include "core/protocol/binarycodec.h"
#include "core/protocol/binarydeframer.h"
#include "decoderfuzz.h"

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::span<const std::uint8_t> input(data, size);
    BinaryDeframer queries(BinaryDeframer::Direction::Query);
    BinaryDeframer responses(BinaryDeframer::Direction::Response);
    std::vector<DeframedItem> items;
    feedInChunks(input, {&queries, &responses}, items);
    static const std::vector<Request> probes
        = {Request::briefStatus(1),
           Request::readRegisters(1, {ElementType::R, 12}, 3),
           Request::readRegisters(1, {ElementType::DR, 0}, 2),
           Request::readDiscretes(1, {ElementType::X, 0}, 8),
           Request::mixedRead(1, {{ElementType::R, 1}, {ElementType::Y, 9}, {ElementType::DWM, 0}}),
           Request::loopback(1, {'A', 'B'}),
           Request::detailStatus(1),
           Request::readRegisters(1, {ElementType::DF, 2}, 1)};
    fuzzDecoders(BinaryCodec(), items, input, probes);
    return 0;
}
