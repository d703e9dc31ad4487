#include "toolconfirmation.h"

#include <QCoreApplication>
#include <QMessageBox>

namespace Fatek {

bool ToolConfirmation::ask(QWidget *parent, const QString &title, const QString &question,
                           const Confirmer &override)
{
    if (override)
        return override(question);
    return QMessageBox::question(parent, title, question, QMessageBox::Yes | QMessageBox::No,
                                 QMessageBox::No)
           == QMessageBox::Yes;
}

QString ToolConfirmation::target(quint8 station, const QString &connectionName)
{
    //: How every question names its target: station 1 on “Line 3 (TCP 10.0.0.5:500)”.
    return QCoreApplication::translate("Fatek::ToolConfirmation", "station %1 on \u201c%2\u201d")
        .arg(station)
        .arg(connectionName);
}

} // namespace Fatek
