// IoCheckoutDialog and its plan: imported from a plan CSV or the main window's names, and its
// info (the fields, the report's details) applied and saved.
#include "checkoutdetailsdialog.h"
#include "checkouttablemodel.h"
#include "core/commission/checkoutfile.h"
#include "core/commission/checkoutrunner.h"
#include "core/commission/commissionmessages.h"
#include "iocheckoutdialog.h"
#include "ui/common/symbolnames.h"
#include "ui/common/uitext.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QMenu>

namespace Fatek {

QMenu *IoCheckoutDialog::importMenu()
{
    auto *menu = new QMenu(this);
    menu->setObjectName(QStringLiteral("importMenu"));
    QAction *csv = menu->addAction(tr("Plan CSV…"), this, [this] {
        const QString path = m_frame->chooseFile(
            {false, tr("Import Checkout Plan"), tr("Checkout plans (*.csv)"), {}});
        if (!path.isEmpty())
            importPlan(path);
    });
    csv->setObjectName(QStringLiteral("importCsvAction"));
    QAction *names = menu->addAction(tr("Imported Names…"), this, [this] {
        const std::optional<QString> prefix = m_frame->askText(
            tr("Import Checkout Plan"), tr("The names that start with (empty: every name):"));
        if (prefix)
            importNames(prefix->trimmed());
    });
    names->setObjectName(QStringLiteral("importNamesAction"));
    return menu;
}

bool IoCheckoutDialog::importPlan(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        showMessage(translated(msg<MsgId::CheckoutFileCannotRead>(
                        QDir::toNativeSeparators(path).toStdString(),
                        Message::text(file.errorString().toStdString()))),
                    true);
        return false;
    }
    auto plan = CheckoutPlan::fromCsv(QString::fromUtf8(file.readAll()));
    if (!plan) {
        showMessage(translated(plan.error().message), true);
        return false;
    }
    const int count = static_cast<int>(plan->points.size());
    loadPlan(std::move(plan.value()),
             tr("Imported %1: %n point(s).", nullptr, count).arg(QDir::toNativeSeparators(path)));
    return true;
}

bool IoCheckoutDialog::importNames(const QString &prefix)
{
    if (!m_symbols || m_symbols->table().isEmpty()) {
        showMessage(tr("No names are imported: File > Import Names and Comments… in the main "
                       "window first."),
                    true);
        return false;
    }
    auto plan = CheckoutPlan::fromSymbols(m_symbols->table(), prefix);
    if (!plan) {
        showMessage(translated(plan.error().message), true);
        return false;
    }
    const int count = static_cast<int>(plan->points.size());
    loadPlan(std::move(plan.value()),
             tr("A plan of %n point(s) from the imported names.", nullptr, count));
    return true;
}

void IoCheckoutDialog::loadPlan(CheckoutPlan plan, const QString &done, bool imported)
{
    stop();
    if (!plan.info.created.isValid())
        plan.info.created = QDateTime::currentDateTimeUtc();
    // An imported plan is not the typed ranges' (those stay the way to type one).
    if (imported)
        m_ranges->clear();
    m_runner->setPlan(std::move(plan));
    m_runner->setFilePath({}); // Start asks where it is saved
    m_model->planReset();
    m_loaded = true;
    applyInfo();
    if (!done.isEmpty())
        showMessage(done, false);
    updateControls();
}

CheckoutInfo IoCheckoutDialog::infoFromFields() const
{
    CheckoutInfo info = m_runner->plan().info;
    info.project = m_project->text();
    info.customer = m_customer->text();
    info.engineer = m_engineer->text();
    info.documentId = m_details.documentId;
    info.revision = m_details.revision;
    info.engineerCompany = m_details.engineerCompany;
    info.witness = m_details.witness;
    info.witnessCompany = m_details.witnessCompany;
    info.customerSignatory = m_details.customerSignatory;
    if (m_frame->target().isDirect())
        info.station = m_frame->target().station();
    return info;
}

void IoCheckoutDialog::applyInfo()
{
    if (!m_loaded || m_runner->isRunning())
        return;
    const CheckoutInfo info = infoFromFields();
    if (info == m_runner->plan().info)
        return;
    CheckoutPlan plan = m_runner->plan();
    plan.info = info;
    const int current = m_runner->currentPoint();
    m_runner->setPlan(std::move(plan));
    m_runner->setCurrentPoint(current);
    if (m_runner->filePath().isEmpty())
        return;
    if (const Status s = CheckoutFile::saveToFile(m_runner->plan(), m_runner->filePath()); !s)
        showMessage(translated(s.error().message), true);
}

void IoCheckoutDialog::editDetails()
{
    CheckoutDetailsDialog details(m_loaded ? m_runner->plan().info : m_details, this);
    if (details.exec() != QDialog::Accepted)
        return;
    m_details = details.info();
    applyInfo();
    showMessage(tr("The report's details are set."), false);
}

} // namespace Fatek
