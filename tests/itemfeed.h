#pragma once

#include "core/watch/itemassembler.h"
#include "ui/watch/watchtablemodel.h"

namespace TestUtil {

// What a direct link (SessionLink) does for a table, without a session: the table's items as
// poll entries, and each batch of element values joined into item values by the ItemAssembler,
// as the session would deliver them.
struct ItemFeed
{
    Fatek::WatchTableModel &model;
    Fatek::ItemAssembler assembler;

    QList<Fatek::WatchEntry> entries(int intervalMs)
    {
        assembler.setItems(model.watchItems(intervalMs));
        return assembler.pollEntries();
    }
    void apply(const QList<Fatek::WatchValue> &values)
    {
        model.applyValues(assembler.assemble(values));
    }
    void queue(const QList<Fatek::WatchValue> &values)
    {
        model.queueValues(assembler.assemble(values));
    }
};

} // namespace TestUtil
