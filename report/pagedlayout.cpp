#include "pagedlayout.h"

#include <QPainter>

namespace Fatek {

int PagedLayout::addHeader(qreal height, Paint paint)
{
    m_headers.push_back({height, std::move(paint)});
    return static_cast<int>(m_headers.size()) - 1;
}

void PagedLayout::add(Block block)
{
    m_blocks.push_back(std::move(block));
}

qreal PagedLayout::runHeight(std::size_t first, std::size_t last, int active) const
{
    qreal height = 0;
    for (std::size_t i = first; i < last; ++i) {
        const Block &b = m_blocks[i];
        if (b.header >= 0 && b.header != active)
            height += m_headers[static_cast<std::size_t>(b.header)].height;
        active = b.header;
        height += b.height;
    }
    return height;
}

void PagedLayout::newPage(int &active, qreal &y)
{
    m_pages.emplace_back();
    active = -1;
    y = m_body.top();
}

void PagedLayout::place(std::size_t index, int &active, qreal &y)
{
    const Block &b = m_blocks[index];
    if (b.header >= 0 && b.header != active) {
        const Header &h = m_headers[static_cast<std::size_t>(b.header)];
        m_pages.back().push_back({&h.paint, QRectF(m_body.left(), y, m_body.width(), h.height)});
        y += h.height;
    }
    active = b.header;
    m_pages.back().push_back({&b.paint, QRectF(m_body.left(), y, m_body.width(), b.height)});
    m_blockPage[index] = pageCount() - 1;
    y += b.height;
}

void PagedLayout::paginate()
{
    m_pages.clear();
    m_blockPage.assign(m_blocks.size(), 0);
    int active = -1;
    qreal y = 0;
    newPage(active, y);
    std::size_t i = 0;
    while (i < m_blocks.size()) {
        // The run of blocks that must share a page: this one and those tied to it.
        std::size_t end = i + 1;
        while (end < m_blocks.size() && m_blocks[end - 1].keepWithNext)
            ++end;
        const bool pageEmpty = m_pages.back().empty();
        if (m_blocks[i].pageBreakBefore && !pageEmpty) {
            newPage(active, y);
        } else if (!pageEmpty && y + runHeight(i, end, active) > m_body.bottom()) {
            newPage(active, y);
        }
        // A run taller than a whole page is placed block by block (each still whole).
        for (std::size_t k = i; k < end; ++k) {
            if (!m_pages.back().empty() && y + runHeight(k, k + 1, active) > m_body.bottom())
                newPage(active, y);
            place(k, active, y);
        }
        i = end;
    }
}

void PagedLayout::paintPage(QPainter &painter, int index) const
{
    for (const Placed &p : m_pages[static_cast<std::size_t>(index)]) {
        painter.save();
        (*p.paint)(painter, p.rect);
        painter.restore();
    }
}

} // namespace Fatek
