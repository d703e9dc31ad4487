#include "connectionspanel.h"

#include "connectionlistmodel.h"
#include "connectionmanager.h"

#include <QHeaderView>
#include <QItemSelectionModel>
#include <QTableView>
#include <QVBoxLayout>

namespace Fatek {

ConnectionsPanel::ConnectionsPanel(ConnectionManager *manager, QWidget *parent)
    : QWidget(parent)
    , m_manager(manager)
    , m_model(new ConnectionListModel(manager, this))
    , m_view(new QTableView(this))
{
    m_view->setObjectName(QStringLiteral("connectionsView"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_view->verticalHeader()->hide();
    // The link description takes the spare width; the numbers stay compact.
    m_view->horizontalHeader()->setStretchLastSection(false);
    m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setSectionResizeMode(ConnectionListModel::LinkColumn,
                                                     QHeaderView::Stretch);
    m_view->setWordWrap(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);

    connect(m_view->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this] { Q_EMIT currentConnectionChanged(currentConnection()); });
    // A new connection becomes current; so does the next one when the current one closes.
    connect(manager, &ConnectionManager::connectionAdded, this,
            [this](Connection *c) { setCurrentConnection(c); });
    connect(manager, &ConnectionManager::connectionRemoved, this, [this] {
        if (!currentConnection() && !m_manager->connections().isEmpty())
            setCurrentConnection(m_manager->connections().constFirst());
        Q_EMIT currentConnectionChanged(currentConnection());
    });
    connect(manager, &ConnectionManager::connectionChanged, this, [this](Connection *c) {
        if (c == currentConnection())
            m_view->viewport()->update();
    });
}

Connection *ConnectionsPanel::currentConnection() const
{
    const QModelIndex index = m_view->selectionModel()->currentIndex();
    return index.isValid() ? m_model->connectionAt(index.row()) : nullptr;
}

void ConnectionsPanel::setCurrentConnection(Connection *connection)
{
    const int row = m_manager->indexOf(connection);
    if (row < 0)
        return;
    m_view->selectionModel()->setCurrentIndex(
        m_model->index(row, 0), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
}

} // namespace Fatek
