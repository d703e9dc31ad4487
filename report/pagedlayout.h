#pragma once

#include <QRectF>

#include <functional>
#include <vector>

class QPainter;

namespace Fatek {

// Blocks of known height placed on pages, as a signed document needs them: a block is never
// split across pages (a table row stays whole), a block tied to the next or the previous one
// moves with it (a heading with its first row, the signatures with the last row), and a table's
// column header is repeated at the top of every page its rows continue on. The caller measures
// and paints; this only decides where. Page decoration (running header, "page N of M") is the
// caller's, once pageCount() is known.
class PagedLayout
{
public:
    using Paint = std::function<void(QPainter &painter, const QRectF &rect)>;

    struct Block
    {
        qreal height = 0;
        Paint paint;
        int header = -1;           // a table header (addHeader) shown above this block
        bool keepWithNext = false; // on the same page as the block after it
        bool pageBreakBefore = false;
    };

    // `body`: the part of every page blocks go in (between running header and footer).
    explicit PagedLayout(const QRectF &body)
        : m_body(body)
    {}

    // A header repeated above the blocks that name it; returns its id.
    int addHeader(qreal height, Paint paint);
    void add(Block block);

    // Places every block; call once, after the last add().
    void paginate();
    int pageCount() const { return static_cast<int>(m_pages.size()); }
    // Paints page `index` (0-based) at its places.
    void paintPage(QPainter &painter, int index) const;

    // Where each block went (tests): its page, in add() order.
    std::vector<int> blockPages() const { return m_blockPage; }

private:
    struct Placed
    {
        const Paint *paint;
        QRectF rect;
    };
    struct Header
    {
        qreal height;
        Paint paint;
    };

    // The height blocks [first, last) take on a page whose current table header is `active`.
    qreal runHeight(std::size_t first, std::size_t last, int active) const;
    void place(std::size_t index, int &active, qreal &y);
    void newPage(int &active, qreal &y);

    QRectF m_body;
    std::vector<Header> m_headers;
    std::vector<Block> m_blocks;
    std::vector<std::vector<Placed>> m_pages;
    std::vector<int> m_blockPage;
};

} // namespace Fatek
