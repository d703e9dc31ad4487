#include "toolconfirmation.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QGuiApplication>
#include <QMessageBox>

namespace Fatek {

bool ToolConfirmation::ask(QWidget *parent, const QString &title, const QString &question,
                           const Confirmer &override)
{
    if (override)
        return override(question);
    QMessageBox box(QMessageBox::Question, title, question, QMessageBox::Yes | QMessageBox::No,
                    parent);
    box.setDefaultButton(QMessageBox::No);
    // A message box is as wide as its question: a short question cut its title ("Enable all
    // f...ATEK Studio"). Room for the title beside the window's icon and buttons, as the window
    // system writes it (with the application's name).
    const QString shown
        = QGuiApplication::applicationDisplayName().isEmpty()
              ? title
              : title + QStringLiteral(" — ") + QGuiApplication::applicationDisplayName();
    if (auto *grid = qobject_cast<QGridLayout *>(box.layout()))
        grid->addItem(new QSpacerItem(box.fontMetrics().horizontalAdvance(shown) + 150, 0,
                                      QSizePolicy::Minimum, QSizePolicy::Minimum),
                      grid->rowCount(), 0, 1, grid->columnCount());
    return box.exec() == QMessageBox::Yes;
}

QString ToolConfirmation::target(quint8 station, const QString &connectionName)
{
    //: How every question names its target: station 1 on “Line 3 (TCP 10.0.0.5:500)”.
    return QCoreApplication::translate("Fatek::ToolConfirmation", "station %1 on \u201c%2\u201d")
        .arg(station)
        .arg(connectionName);
}

} // namespace Fatek
