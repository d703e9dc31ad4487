#include "alarmcenter.h"

#include "core/alarm/alarmengine.h"
#include "core/alarm/alarmjournalwriter.h"
#include "core/plant/plantconnection.h"
#include "ui/common/uitext.h"
#include "ui/connection/connectionmanager.h"
#include "ui/watch/watchtablemodel.h"
#include "ui/watch/watchtablewidget.h"

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

Status noSuchConnection(const QString &connection)
{
    return makeError(ErrorKind::InvalidRequest,
                     QStringLiteral("no connection %1").arg(connection).toStdString());
}

} // namespace

AlarmCenter::AlarmCenter(ConnectionManager *manager, const QString &journalPath, QObject *parent)
    : QObject(parent)
    , m_manager(manager)
    , m_journalPath(journalPath.isEmpty() ? defaultJournalPath() : journalPath)
{
    m_updateTimer.setSingleShot(true);
    m_updateTimer.setInterval(0);
    connect(&m_updateTimer, &QTimer::timeout, this, &AlarmCenter::update);
    m_countTimer.setSingleShot(true);
    m_countTimer.setInterval(0);
    connect(&m_countTimer, &QTimer::timeout, this, &AlarmCenter::recount);
    connect(manager, &ConnectionManager::connectionAdded, this, &AlarmCenter::onConnectionAdded);
    connect(manager, &ConnectionManager::connectionAboutToBeRemoved, this,
            &AlarmCenter::onConnectionRemoved);
    for (Connection *c : manager->connections())
        onConnectionAdded(c);
}

AlarmCenter::~AlarmCenter()
{
    // Detached before the plant connections go (the manager may be deleted first or later).
    for (Engine &e : m_engines) {
        e.engine->attach(nullptr);
        delete e.engine;
    }
}

AlarmJournalWriter *AlarmCenter::journal()
{
    if (!m_journal) {
        m_journal = new AlarmJournalWriter(m_journalPath, this);
        connect(m_journal, &AlarmJournalWriter::failed, this, [this](const Message &reason) {
            Q_EMIT journalFailed(tr("Alarm journal %1: %2").arg(m_journalPath, translated(reason)));
        });
    }
    return m_journal;
}

QString AlarmCenter::defaultJournalPath()
{
    const QString overridden = qEnvironmentVariable("FATEK_ALARM_JOURNAL");
    if (!overridden.isEmpty())
        return overridden;
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
           + QStringLiteral("/alarms.sqlite");
}

void AlarmCenter::addTable(WatchTableWidget *table)
{
    m_tables.append(table);
    connect(table, &WatchTableWidget::connectionChanged, this, &AlarmCenter::scheduleUpdate);
    // Rows, definitions and the interval; a load (setSpec) edits the rows too.
    connect(table, &WatchTableWidget::edited, this, &AlarmCenter::scheduleUpdate);
    connect(table->model(), &WatchTableModel::pollListChanged, this, &AlarmCenter::scheduleUpdate);
    connect(table, &QObject::destroyed, this, &AlarmCenter::scheduleUpdate);
    scheduleUpdate();
}

QList<AlarmEngine *> AlarmCenter::engines() const
{
    QList<AlarmEngine *> list;
    for (const Engine &e : m_engines)
        list.append(e.engine);
    return list;
}

AlarmEngine *AlarmCenter::engine(const QString &connection) const
{
    for (const Engine &e : m_engines) {
        if (e.engine->connection() == connection)
            return e.engine;
    }
    return nullptr;
}

AlarmCenter::Engine *AlarmCenter::entryOf(const QString &connection)
{
    for (Engine &e : m_engines) {
        if (e.engine->connection() == connection)
            return &e;
    }
    return nullptr;
}

QStringList AlarmCenter::connectionNames() const
{
    QStringList names;
    for (const Engine &e : m_engines)
        names.append(e.engine->connection());
    return names;
}

int AlarmCenter::unackedCount() const
{
    int count = 0;
    for (const Engine &e : m_engines)
        count += e.engine->unackedCount();
    return count;
}

Status AlarmCenter::acknowledge(const QString &connection, const QString &alarmId,
                                const QString &comment)
{
    AlarmEngine *e = engine(connection);
    return e ? e->acknowledge(alarmId, {}, comment) : noSuchConnection(connection);
}

Status AlarmCenter::shelve(const QString &connection, const QString &alarmId, qint64 untilMs,
                           const QString &comment)
{
    AlarmEngine *e = engine(connection);
    return e ? e->shelve(alarmId, untilMs, {}, comment) : noSuchConnection(connection);
}

Status AlarmCenter::unshelve(const QString &connection, const QString &alarmId)
{
    AlarmEngine *e = engine(connection);
    return e ? e->unshelve(alarmId, {}) : noSuchConnection(connection);
}

void AlarmCenter::onConnectionAdded(Connection *connection)
{
    Engine entry;
    entry.connection = connection;
    entry.engine = new AlarmEngine(connection->name(), this);
    connect(entry.engine, &AlarmEngine::alarmEvent, this,
            [this](const AlarmEvent &event, const AlarmRecord &record) {
                Q_EMIT alarmEvent(event, record);
                countChanged();
            });
    const QString name = connection->name();
    connect(entry.engine, &AlarmEngine::alarmsReset, this, [this, name] {
        Q_EMIT alarmsReset(name);
        countChanged();
    });
    entry.engine->attach(connection->plant());
    m_engines.push_back(std::move(entry));
    scheduleUpdate();
}

void AlarmCenter::onConnectionRemoved(Connection *connection)
{
    const auto it = std::find_if(m_engines.begin(), m_engines.end(), [connection](const Engine &e) {
        return e.connection == connection;
    });
    if (it == m_engines.end())
        return;
    const QString name = it->engine->connection();
    it->engine->attach(nullptr);
    delete it->engine;
    m_engines.erase(it);
    Q_EMIT alarmsReset(name);
    countChanged();
}

void AlarmCenter::scheduleUpdate()
{
    m_updateTimer.start();
}

void AlarmCenter::updateNow()
{
    m_updateTimer.stop();
    update();
    m_countTimer.stop();
    recount();
}

void AlarmCenter::update()
{
    m_tables.removeIf([](const QPointer<WatchTableWidget> &t) { return t.isNull(); });
    for (Engine &e : m_engines) {
        QList<WatchedItem> items;
        for (const QPointer<WatchTableWidget> &table : std::as_const(m_tables)) {
            if (table->connection() != e.connection)
                continue;
            const QList<WatchedItem> rows = table->model()->watchItems(table->intervalMs());
            for (const WatchedItem &row : rows) {
                if (!row.spec.alarms.isEmpty())
                    items.append(row);
            }
        }
        if (sameItems(items, e.items))
            continue;
        e.items = items;
        e.engine->setItems(items);
        // The journal brings back the kept states of the alarms the engine knows: not before
        // the first definitions arrive.
        if (!e.journaled && !items.isEmpty()) {
            e.journaled = true;
            journal()->attach(e.engine);
        }
    }
    countChanged();
}

void AlarmCenter::recount()
{
    const int count = unackedCount();
    if (count == m_lastCount)
        return;
    m_lastCount = count;
    Q_EMIT unackedCountChanged(count);
}

} // namespace Fatek
