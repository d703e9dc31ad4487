// The simulator's query side on arbitrary bytes: SimConnection splits the stream into frames of
// either protocol, the slave-side decoder turns them into requests and SimulatedPlc executes them,
// as SimServer does. Whatever the simulator answers must be an answer its own master-side decoder
// reads back (an error answer decodes to the PLC error, a good one to values).
#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"
#include "core/sim/simconnection.h"
#include "core/sim/simulatedplc.h"

#include <cstdlib>

using namespace Fatek;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    // One PLC for the whole run (its memory is large); cleared so each input starts alike (clear()
    // only undoes what the previous input wrote: the per-input cost stays small). The first byte
    // picks the model, so memory limits of each profile are explored.
    static SimulatedPlc fbs(ModelProfile::fbs());
    static SimulatedPlc mSeries(ModelProfile::mSeries());
    SimulatedPlc &plc = (data[0] & 1) ? mSeries : fbs;
    plc.clear();
    plc.setRunning((data[0] & 2) != 0);
    static const FaconCodec facon;
    static const BinaryCodec binary;

    SimConnection connection(QStringLiteral("fuzz"), [](const QByteArray &) {});
    const QByteArray bytes(reinterpret_cast<const char *>(data + 1),
                           static_cast<qsizetype>(size - 1));
    for (SimConnection::Item &item : connection.feed(bytes)) {
        if (item.item.error)
            continue;
        const Codec &codec = item.protocol == Protocol::Facon ? static_cast<const Codec &>(facon)
                                                              : static_cast<const Codec &>(binary);
        const Bytes &frame = item.item.frame;
        const auto header = codec.frameHeader(frame);
        if (!header)
            continue;
        const auto request = codec.decodeRequest(frame);
        if (!request) {
            if (request.error().plcCode != 0)
                (void)codec.encodeErrorResponse(*header,
                                                static_cast<std::uint8_t>(request.error().plcCode));
            continue;
        }
        const Response response = plc.execute(*request, item.protocol);
        const Bytes answer = codec.encodeResponse(*request, response);
        if (request->station == Limits::broadcastStation)
            continue;
        // The answer the simulator would send must be readable by the master side: values when
        // it executed, the PLC error it reported otherwise.
        const auto decoded = codec.decodeResponse(answer, *request);
        if (response.errorCode == 0 && !decoded.ok())
            std::abort();
        if (response.errorCode != 0
            && (decoded.ok() || decoded.error().kind != ErrorKind::PlcError))
            std::abort();
    }
    return 0;
}
