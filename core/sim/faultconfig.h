#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>

namespace Fatek {

// Misbehaviour the simulator can be told to show, for reliability tests. All off by default.
// Random choices come from a generator seeded with `seed`, so a test sees the same faults each run.
struct FaultConfig
{
    int latencyMs = 0;             // added before every answer
    int jitterMs = 0;              // plus 0..jitterMs, random
    int turnaroundMs = 0;          // slave turnaround time, added before every answer
    int baud = 0;                  // > 0: answers wait the query's and their wire time, 10 bit/B
    double dropRate = 0.0;         // fraction of answers not sent (the request is still executed)
    double corruptRate = 0.0;      // fraction of answer bytes flipped
    int garbageBytes = 0;          // noise bytes sent before each answer (never a frame start byte)
    int chunkSize = 0;             // > 0: answers go out in pieces of this many bytes ...
    int chunkDelayMs = 0;          // ... this far apart
    int closeEverySeconds = 0;     // > 0: TCP connections are closed this long after they open
    double wrongStationRate = 0.0; // fraction of answers sent with another station number
    double spikeRate = 0.0;        // fraction of answers delayed by a further spikeMs ...
    int spikeMs = 0;               // ... (latency spikes: a busy PLC or network)
    std::uint32_t seed = 1;

    // Wire time of `bytes` at `baud` (10 bits per byte), 0 when line-speed emulation is off.
    int wireTimeMs(qsizetype bytes) const;
    bool anyActive() const;
    // "latency=50ms jitter=10ms drop=0.1" for logs; "none" when nothing is set.
    QString describe() const;
};

} // namespace Fatek
