#include "faultconfig.h"

namespace Fatek {

int FaultConfig::wireTimeMs(qsizetype bytes) const
{
    if (baud <= 0 || bytes <= 0)
        return 0;
    const qint64 bits = static_cast<qint64>(bytes) * 10;
    return static_cast<int>((bits * 1000 + baud - 1)
                            / baud); // rounded up: never faster than the line
}

bool FaultConfig::anyActive() const
{
    return latencyMs > 0 || jitterMs > 0 || turnaroundMs > 0 || baud > 0 || dropRate > 0.0
           || corruptRate > 0.0 || garbageBytes > 0 || chunkSize > 0 || closeEverySeconds > 0
           || wrongStationRate > 0.0 || (spikeRate > 0.0 && spikeMs > 0);
}

QString FaultConfig::describe() const
{
    QStringList parts;
    if (latencyMs > 0)
        parts << QStringLiteral("latency=%1ms").arg(latencyMs);
    if (jitterMs > 0)
        parts << QStringLiteral("jitter=%1ms").arg(jitterMs);
    if (turnaroundMs > 0)
        parts << QStringLiteral("turnaround=%1ms").arg(turnaroundMs);
    if (baud > 0)
        parts << QStringLiteral("baud=%1").arg(baud);
    if (dropRate > 0.0)
        parts << QStringLiteral("drop=%1").arg(dropRate);
    if (corruptRate > 0.0)
        parts << QStringLiteral("corrupt=%1").arg(corruptRate);
    if (garbageBytes > 0)
        parts << QStringLiteral("garbage=%1").arg(garbageBytes);
    if (chunkSize > 0)
        parts << QStringLiteral("chunk=%1/%2ms").arg(chunkSize).arg(chunkDelayMs);
    if (closeEverySeconds > 0)
        parts << QStringLiteral("close-every=%1s").arg(closeEverySeconds);
    if (wrongStationRate > 0.0)
        parts << QStringLiteral("wrong-station=%1").arg(wrongStationRate);
    if (spikeRate > 0.0 && spikeMs > 0)
        parts << QStringLiteral("spike=%1/%2ms").arg(spikeRate).arg(spikeMs);
    if (parts.isEmpty())
        return QStringLiteral("none");
    parts << QStringLiteral("seed=%1").arg(seed);
    return parts.join(QLatin1Char(' '));
}

} // namespace Fatek
