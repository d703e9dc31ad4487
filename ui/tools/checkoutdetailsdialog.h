#pragma once

#include "core/commission/checkoutplan.h"

#include <QDialog>

class QLineEdit;

namespace Fatek {

// I/O Checkout > Details…: what the report prints on every page and in its signature block that
// the plan's fields do not hold: the document's id and revision, the engineer's company, the
// witness (name, company) and who signs for the customer.
class CheckoutDetailsDialog : public QDialog
{
    Q_OBJECT

public:
    CheckoutDetailsDialog(const CheckoutInfo &info, QWidget *parent = nullptr);

    // `info` as given, with the fields edited here.
    CheckoutInfo info() const;

private:
    CheckoutInfo m_info;
    QLineEdit *m_documentId;
    QLineEdit *m_revision;
    QLineEdit *m_engineerCompany;
    QLineEdit *m_witness;
    QLineEdit *m_witnessCompany;
    QLineEdit *m_customerSignatory;
};

} // namespace Fatek
