#include "historycenter.h"

#include "core/history/historyrecorder.h"
#include "core/history/historystore.h"
#include "core/history/historywriter.h"
#include "core/plant/plantconnection.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace Fatek {

namespace {

bool sameItems(const QList<WatchedItem> &a, const QList<WatchedItem> &b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const WatchedItem &x, const WatchedItem &y) {
                          return x.intervalMs == y.intervalMs && x.spec == y.spec;
                      });
}

bool isDatabaseUrl(const QString &location)
{
    return location.startsWith(QLatin1String("postgresql://"))
           || location.startsWith(QLatin1String("postgres://"));
}

} // namespace

HistoryCenter::HistoryCenter(ConnectionManager *manager, const QString &location, QObject *parent)
    : QObject(parent)
    , m_manager(manager)
    , m_location(location.isEmpty() ? defaultLocation() : location)
{
    m_updateTimer.setSingleShot(true);
    m_updateTimer.setInterval(0);
    connect(&m_updateTimer, &QTimer::timeout, this, &HistoryCenter::update);
    connect(manager, &ConnectionManager::connectionAdded, this, &HistoryCenter::onConnectionAdded);
    connect(manager, &ConnectionManager::connectionAboutToBeRemoved, this,
            &HistoryCenter::onConnectionRemoved);
    for (Connection *c : manager->connections())
        onConnectionAdded(c);
}

HistoryCenter::~HistoryCenter()
{
    // The recorders leave the plant connections and keep their last samples before the writer
    // (a child, deleted after this body) writes what is pending and closes the store.
    for (Recorder &r : m_recorders) {
        if (r.recorder)
            r.recorder->attach(nullptr);
        delete r.recorder;
    }
    m_recorders.clear();
}

QString HistoryCenter::defaultLocation()
{
    const QString overridden = qEnvironmentVariable("FATEK_HISTORY");
    if (!overridden.isEmpty())
        return overridden;
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
           + QStringLiteral("/history.sqlite");
}

HistoryWriter *HistoryCenter::writer()
{
    if (!m_writer) {
        HistoryRetention retention;
        retention.maxAgeS = qint64(RetentionDays) * 24 * 3600;
        m_writer = new HistoryWriter(m_location, retention, this);
        connect(m_writer, &HistoryWriter::failed, this, [this](const Message &reason) {
            Q_EMIT statusMessage(tr("History: %1").arg(translated(reason)));
        });
        connect(m_writer, &HistoryWriter::recovered, this, [this] {
            Q_EMIT statusMessage(
                tr("History: %1 is written again.").arg(QDir::toNativeSeparators(m_location)));
        });
    }
    return m_writer;
}

HistoryWriter *HistoryCenter::readableWriter()
{
    if (m_writer || isDatabaseUrl(m_location) || QFileInfo::exists(m_location))
        return writer();
    return nullptr;
}

void HistoryCenter::addTable(WatchTableWidget *table)
{
    m_tables.append(table);
    connect(table, &WatchTableWidget::connectionChanged, this, &HistoryCenter::scheduleUpdate);
    // Rows, settings and the interval; a load (setSpec) edits the rows too.
    connect(table, &WatchTableWidget::edited, this, &HistoryCenter::scheduleUpdate);
    connect(table->model(), &WatchTableModel::pollListChanged, this,
            &HistoryCenter::scheduleUpdate);
    connect(table, &QObject::destroyed, this, &HistoryCenter::scheduleUpdate);
    scheduleUpdate();
}

HistoryRecorder *HistoryCenter::recorder(const QString &connection) const
{
    for (const Recorder &r : m_recorders) {
        if (r.recorder && r.connection && r.connection->name() == connection)
            return r.recorder;
    }
    return nullptr;
}

QString HistoryCenter::itemKey(const WatchItemSpec &spec)
{
    return WatchList::itemId(spec);
}

QString HistoryCenter::seriesKey(const WatchTableModel *model, const WatchItemSpec &spec) const
{
    for (const QPointer<WatchTableWidget> &table : m_tables) {
        if (table && table->model() == model) {
            if (!table->connection())
                return {};
            return table->connection()->name() + QLatin1Char('/') + itemKey(spec);
        }
    }
    return {};
}

void HistoryCenter::onConnectionAdded(Connection *connection)
{
    Recorder entry;
    entry.connection = connection;
    m_recorders.push_back(std::move(entry));
    scheduleUpdate();
}

void HistoryCenter::onConnectionRemoved(Connection *connection)
{
    const auto it
        = std::find_if(m_recorders.begin(), m_recorders.end(),
                       [connection](const Recorder &r) { return r.connection == connection; });
    if (it == m_recorders.end())
        return;
    if (it->recorder) {
        it->recorder->attach(nullptr);
        delete it->recorder; // its items' lines end there (Off samples)
    }
    m_recorders.erase(it);
}

void HistoryCenter::updateNow()
{
    m_updateTimer.stop();
    update();
}

void HistoryCenter::update()
{
    m_tables.removeIf([](const QPointer<WatchTableWidget> &t) { return t.isNull(); });
    for (Recorder &r : m_recorders) {
        if (!r.connection)
            continue;
        QList<WatchedItem> items;
        for (const QPointer<WatchTableWidget> &table : std::as_const(m_tables)) {
            if (table->connection() != r.connection)
                continue;
            const QList<WatchedItem> rows = table->model()->watchItems(table->intervalMs());
            for (const WatchedItem &row : rows) {
                if (row.spec.history)
                    items.append(row);
            }
        }
        if (sameItems(items, r.items))
            continue;
        r.items = items;
        if (!r.recorder) {
            if (items.isEmpty())
                continue;
            // The first recorded row of this connection: the store opens now.
            r.recorder = new HistoryRecorder(r.connection->name(), writer(), this);
            r.recorder->setItems(items);
            r.recorder->attach(r.connection->plant());
            continue;
        }
        r.recorder->setItems(items);
    }
}

} // namespace Fatek
