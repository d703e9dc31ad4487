#pragma once

#include "core/plant/plctarget.h"

#include <QString>

#include <functional>

class QWidget;

namespace Fatek {

// Answers "are you sure?" questions. Tests install an automatic answer so no modal dialog
// ever blocks them; otherwise a QMessageBox asks the user.
using Confirmer = std::function<bool(const QString &question)>;

class ToolConfirmation
{
public:
    // Uses `override` when set, else asks with a Yes/No message box (default: No).
    static bool ask(QWidget *parent, const QString &title, const QString &question,
                    const Confirmer &override);
    // "station 1 on “Line 3 (TCP 10.0.0.5:500)”": how every question names its target.
    static QString target(quint8 station, const QString &connectionName);
    static QString target(const PlcTarget &target)
    {
        return ToolConfirmation::target(target.station(), target.connectionName());
    }
};

} // namespace Fatek
