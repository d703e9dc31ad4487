#pragma once

#include "core/sim/modelprofile.h"
#include "core/sim/simserver.h"
#include "core/sim/simulatedplc.h"

#include <QString>
#include <QtGlobal>

// A simulated FBs in RUN on a free loopback TCP port (port 0 when it could not listen, said).
struct RunningFbs
{
    Fatek::SimulatedPlc plc{Fatek::ModelProfile::fbs()};
    Fatek::SimServer server{&plc};
    quint16 port = 0;

    RunningFbs()
    {
        plc.setRunning(true);
        QString error;
        if (server.listenTcp(0, &error))
            port = server.tcpPort();
        else
            qWarning("cannot listen: %s", qPrintable(error));
    }
};
