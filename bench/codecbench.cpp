// Figure 5: codec speed (a sanity figure): frames encoded and decoded per second, master side,
// for a 46 read of 32 registers and a 48 mixed read of 20 elements.
#include "bench.h"

#include "core/protocol/binarycodec.h"
#include "core/protocol/faconcodec.h"

#include <QElapsedTimer>

namespace Fatek::Bench {

namespace {

// Runs `body` in batches until `seconds` have passed; returns calls per second.
template<typename F>
double perSecond(double seconds, F body)
{
    QElapsedTimer clock;
    clock.start();
    std::uint64_t calls = 0;
    while (clock.nsecsElapsed() < static_cast<qint64>(seconds * 1e9)) {
        for (int i = 0; i < 256; ++i)
            body();
        calls += 256;
    }
    return static_cast<double>(calls) * 1e9 / static_cast<double>(clock.nsecsElapsed());
}

} // namespace

void runCodec(const Options &options, Report &report)
{
    const double seconds = options.quick ? 0.05 : 0.5;
    constexpr double floor = 100000; // frames/s: far above any link, a sanity floor only
    double worst = 1e12;
    std::vector<Address> mixed;
    for (std::uint32_t i = 0; i < 5; ++i) {
        mixed.push_back({ElementType::R, 100 + 7 * i});
        mixed.push_back({ElementType::DR, 1000 + 10 * i});
        mixed.push_back({ElementType::M, 30 + 3 * i});
        mixed.push_back({ElementType::Y, i});
    }
    const std::vector<std::pair<QString, Request>> requests{
        {QStringLiteral("46 x 32 R"), Request::readRegisters(1, {ElementType::R, 0}, 32)},
        {QStringLiteral("48 x 20 mixed"), Request::mixedRead(1, mixed)},
    };
    FaconCodec facon;
    BinaryCodec binary;
    for (const Codec *codec :
         {static_cast<const Codec *>(&facon), static_cast<const Codec *>(&binary)}) {
        const QString proto = QString::fromUtf8(protocolName(codec->protocol()).data());
        for (const auto &entry : requests) {
            // Not a structured binding: clang before 16 cannot capture one in a lambda.
            const auto &name = entry.first;
            const auto &request = entry.second;
            Response response;
            response.station = request.station;
            response.command = request.command;
            for (std::uint32_t i = 0; i < request.expectedValueCount(); ++i)
                response.values.push_back(i % 2);
            const Bytes answer = codec->encodeResponse(request, response);
            std::size_t sink = 0;
            const double encode
                = perSecond(seconds, [&] { sink += codec->encodeRequest(request).value().size(); });
            bool decodedOk = true;
            const double decode = perSecond(seconds, [&] {
                const Result<Response> r = codec->decodeResponse(answer, request);
                decodedOk = decodedOk && r && r.value().values == response.values;
                sink += r ? r.value().values.size() : 0;
            });
            worst = std::min({worst, encode, decode});
            if (!decodedOk)
                worst = 0;
            report.row(QStringLiteral("codec %1 %2: encode query / s").arg(proto, name),
                       fmt(encode, 0), {}, {}, QStringLiteral("sanity >= 1e5"));
            report.row(QStringLiteral("codec %1 %2: decode answer / s").arg(proto, name),
                       fmt(decode, 0), QStringLiteral("%1-byte answer").arg(answer.size()), {},
                       QStringLiteral("sanity >= 1e5"));
            if (sink == 0)
                worst = 0;
        }
    }
    report.result(QStringLiteral("codec_frames_per_s_min"), worst, QStringLiteral(">=100000"),
                  worst >= floor);
}

} // namespace Fatek::Bench
