#pragma once

#include "core/watch/valueformat.h"

#include <QStyledItemDelegate>

#include <functional>

namespace Fatek {

// Format column: a combo with the formats that fit the row's element, applied as soon as one is
// picked; other columns: default editors. An open editor is filled once and never refreshed by
// later model changes (polls). The view's model may be a proxy of the WatchTableModel.
class WatchDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    using QStyledItemDelegate::QStyledItemDelegate;

    // A picked format goes here instead of into the model (the table applies it to every
    // selected row); `index` is the view's.
    using FormatHandler = std::function<void(const QModelIndex &index, DisplayFormat format)>;
    void setFormatHandler(FormatHandler handler) { m_formatHandler = std::move(handler); }

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;

private:
    FormatHandler m_formatHandler;
};

} // namespace Fatek
