#include "checkoutdetailsdialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QVBoxLayout>

namespace Fatek {

CheckoutDetailsDialog::CheckoutDetailsDialog(const CheckoutInfo &info, QWidget *parent)
    : QDialog(parent)
    , m_info(info)
{
    setObjectName(QStringLiteral("checkoutDetailsDialog"));
    setWindowTitle(tr("Checkout Details"));
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    const auto field = [this, form](const QString &label, const char *name, const QString &text) {
        auto *edit = new QLineEdit(text, this);
        edit->setObjectName(QLatin1String(name));
        edit->setMinimumWidth(260);
        form->addRow(label, edit);
        return edit;
    };
    m_documentId = field(tr("Document ID:"), "documentId", info.documentId);
    m_revision = field(tr("Revision:"), "revision", info.revision);
    m_engineerCompany = field(tr("Engineer's company:"), "engineerCompany", info.engineerCompany);
    m_witness = field(tr("Witness:"), "witness", info.witness);
    m_witnessCompany = field(tr("Witness's company:"), "witnessCompany", info.witnessCompany);
    m_customerSignatory
        = field(tr("Signs for the customer:"), "customerSignatory", info.customerSignatory);
    layout->addLayout(form);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->setObjectName(QStringLiteral("buttons"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

CheckoutInfo CheckoutDetailsDialog::info() const
{
    CheckoutInfo info = m_info;
    info.documentId = m_documentId->text().trimmed();
    info.revision = m_revision->text().trimmed();
    info.engineerCompany = m_engineerCompany->text().trimmed();
    info.witness = m_witness->text().trimmed();
    info.witnessCompany = m_witnessCompany->text().trimmed();
    info.customerSignatory = m_customerSignatory->text().trimmed();
    return info;
}

} // namespace Fatek
