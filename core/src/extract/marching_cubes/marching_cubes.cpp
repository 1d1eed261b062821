// Exhaustive marching cubes (Lorensen & Cline 1987) over slabs of cells, in
// parallel chunks of slabs whose seams are stitched without welding.
//
// The volume is cut into chunks of slabs, run on separate threads. Each chunk is
// marched twice: a counting pass (classify, trim, count crossed edges and the
// table's triangles per cell), then, once every chunk's counts have given it its
// ranges of the final buffers (allocated once, at their final size), a writing
// pass into those ranges. Per slab between sample slices z and z+1:
//  1. classify: one above/below flag per sample of slice z+1 (the single rule
//     sample >= iso), and per row the span of x-edges where the flag changes;
//  2. trim: a row of cells can only hold surface where one of its four sample
//     rows changes, or where rows that are each constant disagree; everything
//     else is skipped without looking at its cells (after Flying Edges,
//     Schroeder et al. 2015);
//  3. triangulate: each cell's 8 flags index the table; each crossed cube edge is
//     mapped to its grid edge, whose vertex id lives in a per-slice cache, so a
//     crossed grid edge gets its vertex computed once, by the first cell that
//     needs it. Cache entries are never cleared: an entry is valid when it is at
//     least the vertex count at which its slice entered the slab window.
// The x- and y-edges on the slice between two chunks belong to the upper chunk;
// the lower chunk writes placeholders for them, resolved from the upper chunk's
// first slice by whichever of the two is written last, on its thread.
// Temporaries are a few slices of flags and ids per thread, kept from chunk to
// chunk, and the counting pass's classification (a bit per voxel at most).
//
// Labelled (for extractAllSurfaces), the writing pass also joins each cell
// piece's vertices in a union-find and tallies the piece; surface_labels.h
// describes it.
#include "isotrack/marching_cubes.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "extract/common/edge_vertex.h"
#include "extract/marching_cubes/edge_slots.h"
#include "extract/marching_cubes/labelled_march.h"
#include "extract/marching_cubes/march.h"
#include "extract/marching_cubes/surface_labels.h"
#include "extract/measure/surface_measure.h"
#include "extract/snap/snap_march.h"
#include "extract/trilinear/trilinear_march.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "support/huge_pages.h"
#include "support/parallel.h"
#include "support/slice_release.h"

namespace isotrack {
namespace {

using detail::EdgeSlots;
using detail::edgeSlots;
constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
using detail::kSeamBit;  // placeholder: a vertex on the next chunk's first slice

struct RowSpan {
    int lo, hi;                // x-edges [lo, hi) hold every change of flag along the row
    std::uint8_t first, last;  // flags of the row's first and last samples
};

// Slabs [zBegin, zEnd) of the volume. A first pass counts the chunk's vertices
// and triangles; the second writes them straight into their ranges of the
// final mesh, with placeholders for the vertices on slice zEnd unless last.
struct Chunk {
    int zBegin = 0, zEnd = 0;
    bool last = false;
    std::size_t vertexCount = 0, triangleCount = 0;
    std::size_t vertexBase = 0, indexBase = 0;
    std::size_t vertexCursor = 0, indexCursor = 0;  // written so far, relative to the bases
    std::vector<std::size_t> seamIndices;           // positions in the final indices holding placeholders
    std::vector<std::uint32_t> borderVertices;      // labelled: the vertices on the volume's border
    std::vector<std::uint32_t> firstSliceIds;       // x- and y-edge ids of slice zBegin
    // The counting pass's classification, kept for the writing pass so that it
    // does not stream the samples again: per slice zBegin..zEnd, each row's span
    // and, for rows that change, their flags packed 8 to a byte. Slices crossed so
    // densely that computing vertices reads most of their samples anyway are
    // classified again instead (kept[slice] == 0).
    std::vector<std::uint8_t> kept;
    std::vector<RowSpan> spans;
    Buffer<std::uint8_t> flagBits;
};

// Flags are read 8 at a time as 64-bit words, byte i of a word being flag i.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the exhaustive pass reads flags as little-endian words");

// Flags packed 8 to a byte, bit i being flag i, and back.
std::uint8_t packFlags(const std::uint8_t* flags) {
    std::uint64_t word;
    std::memcpy(&word, flags, 8);
    return static_cast<std::uint8_t>((word * 0x0102040810204080ull) >> 56);
}

const std::array<std::uint64_t, 256>& flagExpansion() {
    static const std::array<std::uint64_t, 256> table = [] {
        std::array<std::uint64_t, 256> t{};
        for (unsigned v = 0; v < 256; ++v) {
            for (unsigned i = 0; i < 8; ++i) t[v] |= std::uint64_t(v >> i & 1u) << (8 * i);
        }
        return t;
    }();
    return table;
}

template <class T>
class ChunkMarcher {
public:
    // With labels.parent, the writing pass labels surfaces in it (surface_labels.h).
    ChunkMarcher(const Volume& volume, const detail::SampleGrid<T>& grid,
                 const std::array<CaseContinuation, 256>& table, const EdgeSlots& slots,
                 const detail::SurfaceLabels& labels, Mesh& mesh, ExtractProgress* progress)
        : volume_(volume),
          progress_(progress),
          grid_(grid),
          table_(table),
          slots_(slots),
          labels_(labels),
          mesh_(mesh),
          nx_(grid.nx()),
          ny_(grid.ny()),
          nz_(grid.nz()),
          sliceSize_(std::size_t(grid.nx()) * std::size_t(grid.ny())),
          rowBytes_(std::size_t(grid.nx() + 7) / 8) {
        for (int s = 0; s < 2; ++s) {
            flags_[s].assign(sliceSize_ + 8, 0);  // rows are packed and unpacked 8 flags at a time
            spans_[s].assign(std::size_t(ny_), RowSpan{});
        }
        columns_.assign(std::size_t(nx_) + 16, 0);  // nextActiveCell reads 9 bytes at a time
        for (int c = 0; c < 256; ++c) {
            const CaseContinuation& cased = table_[std::size_t(c)];
            triangleCount_[std::size_t(c)] = cased.pieceCount == 0
                                                 ? 0
                                                 : cased.pieces[cased.pieceCount - 1].firstTriangle +
                                                       cased.pieces[cased.pieceCount - 1].triangleCount;
        }
    }

    // Counts the chunk's vertices (the crossed edges it owns: every crossed edge is
    // used by a cell) and triangles, so its buffers are allocated once, at their
    // final size, instead of growing by copies.
    void count(Chunk& chunk) {
        chunk_ = &chunk;
        std::size_t vertices = 0, triangles = 0;
        const std::size_t slices = std::size_t(chunk_->zEnd - chunk_->zBegin + 1);
        chunk_->kept.assign(slices, 0);
        chunk_->spans.resize(slices * std::size_t(ny_));
        chunk_->flagBits.resize(slices * std::size_t(ny_) * rowBytes_);
        detail::SliceRelease release(volume_, chunk_->zBegin);
        classifySlice(chunk_->zBegin, 0);
        const std::size_t first = planarCrossings(0);
        keepSlice(chunk_->zBegin, 0, first);
        vertices += first;
        for (int z = chunk_->zBegin; z < chunk_->zEnd; ++z) {
            const int bottom = (z - chunk_->zBegin) & 1, top = bottom ^ 1;
            classifySlice(z + 1, top);
            release.passed(z + 1);  // counting reads only the flags of slices classified
            const std::size_t crossings = planarCrossings(top);
            keepSlice(z + 1, top, crossings);
            if (z + 1 < chunk_->zEnd || chunk_->last) vertices += crossings;
            vertices += verticalCrossings(bottom, top);
            for (int y = 0; y + 1 < ny_; ++y) triangles += rowTriangles(y, bottom, top);
            slabDone();
        }
        release.finish(chunk_->zEnd + 1);
        chunk_->vertexCount = vertices;
        chunk_->triangleCount = triangles;
    }

    // Writes the chunk into mesh_, whose buffers already have their final size.
    // A marcher writes its chunks in order (parallelForWithState hands them out so): the
    // ids its caches hold from earlier chunks are below this one's first, so
    // invalid here, and the caches need no clearing between chunks.
    void run(Chunk& chunk) {
        chunk_ = &chunk;
        if (vertical_.empty()) {
            for (auto& planar : planar_)
                planar.assign(2 * sliceSize_, kNoVertex);  // vertex id caches, for writing only
            vertical_.assign(sliceSize_, kNoVertex);
        }
        detail::SliceRelease release(volume_, chunk_->zBegin);
        restoreSlice(chunk_->zBegin, 0);
        threshold_[0] = static_cast<std::uint32_t>(chunk_->vertexBase);
        for (int z = chunk_->zBegin; z < chunk_->zEnd; ++z) {
            release.passed(z - 1);  // gradients reach one slice below the slab
            const int bottom = (z - chunk_->zBegin) & 1, top = bottom ^ 1;
            restoreSlice(z + 1, top);
            threshold_[top] = static_cast<std::uint32_t>(chunk_->vertexBase + chunk_->vertexCursor);
            verticalThreshold_ = threshold_[top];
            // Only a seam slab (the last of a chunk but the last) meets the next chunk's slice.
            if (!chunk_->last && z + 1 == chunk_->zEnd) {
                for (int y = 0; y + 1 < ny_; ++y) marchRow<true>(y, z, bottom, top);
            } else {
                for (int y = 0; y + 1 < ny_; ++y) marchRow<false>(y, z, bottom, top);
            }
            if (z == chunk_->zBegin) chunk_->firstSliceIds = planar_[bottom];
            slabDone();
        }
        release.finish(chunk_->zEnd + 2);
        if (chunk_->vertexCursor != chunk_->vertexCount || chunk_->indexCursor != 3 * chunk_->triangleCount) {
            throw std::logic_error("marching cubes: a chunk wrote other counts than it counted");
        }
        chunk_->kept = {};
        chunk_->spans = {};
        chunk_->flagBits = {};
    }

private:
    const Volume& volume_;
    ExtractProgress* const progress_;

    void slabDone() {
        if (progress_) progress_->slabsDone.fetch_add(1, std::memory_order_relaxed);
    }

    void classifySlice(int z, int slot) {
        std::uint8_t* flags = flags_[slot].data();
        grid_.classify(grid_.index(0, 0, z), sliceSize_, flags);
        for (int y = 0; y < ny_; ++y) {
            const std::uint8_t* row = flags + std::size_t(nx_) * std::size_t(y);
            const std::uint8_t first = row[0], last = row[nx_ - 1];
            // The first and last changes of flag, found with the C library's vectorised scans.
            const void* change = std::memchr(row, first ^ 1, std::size_t(nx_));
            if (!change) {
                spans_[slot][std::size_t(y)] = {nx_, 0, first, last};
                continue;
            }
            const int lo = int(static_cast<const std::uint8_t*>(change) - row) - 1;
            const int hi = int(static_cast<const std::uint8_t*>(memrchr(row, last ^ 1, std::size_t(nx_))) - row) + 1;
            spans_[slot][std::size_t(y)] = {lo, hi, first, last};
        }
    }

    // Keeps slice z's classification (in `slot`) in the chunk: spans, and packed flags of the rows that change.
    void keepSlice(int z, int slot, std::size_t crossings) {
        if (crossings * 8 > sliceSize_) return;  // dense: classified again
        chunk_->kept[std::size_t(z - chunk_->zBegin)] = 1;
        const std::size_t slice = std::size_t(z - chunk_->zBegin) * std::size_t(ny_);
        std::copy(spans_[slot].begin(), spans_[slot].end(), chunk_->spans.begin() + std::ptrdiff_t(slice));
        const std::uint8_t* flags = flags_[slot].data();
        for (int y = 0; y < ny_; ++y) {
            if (spans_[slot][std::size_t(y)].lo >= spans_[slot][std::size_t(y)].hi)
                continue;  // constant: its first flag says all
            const std::uint8_t* row = flags + std::size_t(nx_) * std::size_t(y);
            std::uint8_t* bits = chunk_->flagBits.data() + (slice + std::size_t(y)) * rowBytes_;
            for (std::size_t b = 0; b < rowBytes_; ++b) bits[b] = packFlags(row + 8 * b);
        }
    }

    // classifySlice for the writing pass, from what the counting pass kept.
    void restoreSlice(int z, int slot) {
        if (!chunk_->kept[std::size_t(z - chunk_->zBegin)]) {
            classifySlice(z, slot);
            return;
        }
        const std::size_t slice = std::size_t(z - chunk_->zBegin) * std::size_t(ny_);
        std::copy(chunk_->spans.begin() + std::ptrdiff_t(slice), chunk_->spans.begin() + std::ptrdiff_t(slice) + ny_,
                  spans_[slot].begin());
        const std::array<std::uint64_t, 256>& expand = flagExpansion();
        std::uint8_t* flags = flags_[slot].data();
        for (int y = 0; y < ny_; ++y) {
            const RowSpan& span = spans_[slot][std::size_t(y)];
            std::uint8_t* row = flags + std::size_t(nx_) * std::size_t(y);
            if (span.lo >= span.hi) {
                std::memset(row, span.first, std::size_t(nx_));
                continue;
            }
            const std::uint8_t* bits = chunk_->flagBits.data() + (slice + std::size_t(y)) * rowBytes_;
            // The last byte may spill past the row; the next row (or the padding) is written after.
            for (std::size_t b = 0; b < rowBytes_; ++b) std::memcpy(row + 8 * b, &expand[bits[b]], 8);
        }
    }

    // The cells [begin, end) of row y that can hold surface (trimming), with
    // columns_ filled for them. False when the row is empty.
    bool rowRange(int y, int bottom, int top, int& begin, int& end) {
        const RowSpan* rows[4] = {&spans_[bottom][std::size_t(y)], &spans_[bottom][std::size_t(y) + 1],
                                  &spans_[top][std::size_t(y)], &spans_[top][std::size_t(y) + 1]};
        int lo = nx_, hi = 0;
        bool firstsAgree = true, lastsAgree = true;
        for (const RowSpan* r : rows) {
            lo = std::min(lo, r->lo);
            hi = std::max(hi, r->hi);
            firstsAgree &= r->first == rows[0]->first;
            lastsAgree &= r->last == rows[0]->last;
        }
        begin = firstsAgree ? lo : 0;
        end = lastsAgree ? hi : nx_ - 1;
        if (begin >= end) return false;
        const std::size_t row = std::size_t(nx_) * std::size_t(y);
        const std::uint8_t* lo0 = flags_[bottom].data() + row;
        const std::uint8_t* lo1 = lo0 + nx_;
        const std::uint8_t* hi0 = flags_[top].data() + row;
        const std::uint8_t* hi1 = hi0 + nx_;
        std::uint8_t* columns = columns_.data();
        // 8 cells per step, as words of 0/1 bytes (no carries); the last step may
        // write past `end` into columns_'s padding and read into flags_'s.
        for (int x = begin; x <= end; x += 8) {
            std::uint64_t a, b, c, d;
            std::memcpy(&a, lo0 + x, 8);
            std::memcpy(&b, lo1 + x, 8);
            std::memcpy(&c, hi0 + x, 8);
            std::memcpy(&d, hi1 + x, 8);
            const std::uint64_t word = a | b << 1 | c << 2 | d << 3;
            std::memcpy(columns + x, &word, 8);
        }
        return true;
    }

    // The first cell x' in [x, end) whose corners disagree, or end; 8 cells per
    // step. A cell is empty when its two columns of four flags are equal and
    // either all below (0) or all above (15).
    static int nextActiveCell(const std::uint8_t* columns, int x, int end) {
        constexpr std::uint64_t kOnes = 0x0101010101010101ull, kMiddleBits = 0x0E0E0E0E0E0E0E0Eull;
        for (; x < end; x += 8) {
            std::uint64_t left, right;
            std::memcpy(&left, columns + x, 8);
            std::memcpy(&right, columns + x + 1, 8);
            // Per byte (values 0..15, so no carries): b + 1 has none of bits 1-3 set only for 0 and 15.
            const std::uint64_t active = ((left + kOnes) & kMiddleBits) | (left ^ right);
            if (active != 0) return std::min(end, x + __builtin_ctzll(active) / 8);
        }
        return end;
    }

    std::size_t rowTriangles(int y, int bottom, int top) {
        int begin, end;
        if (!rowRange(y, bottom, top, begin, end)) return 0;
        std::size_t triangles = 0;
        const std::uint8_t* columns = columns_.data();
        for (int x = nextActiveCell(columns, begin, end); x < end; x = nextActiveCell(columns, x + 1, end)) {
            triangles += triangleCount_[slots_.configOfColumns[columns[x] | columns[x + 1] << 4]];
        }
        return triangles;
    }

    // The number of places where two runs of 0/1 flags differ. A word's XOR has
    // a 1 in each byte that differs; up to 255 words are summed bytewise (no
    // byte carries), then the bytes are added up: a few instructions per 8 flags,
    // where counting byte by byte widened every byte to 64 bits.
    static std::size_t differences(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
        constexpr std::uint64_t kEvenBytes = 0x00FF00FF00FF00FFull, kShorts = 0x0001000100010001ull;
        std::size_t count = 0, i = 0;
        const std::size_t words = n & ~std::size_t(7);
        while (i < words) {
            const std::size_t end = std::min(words, i + 8 * 255);
            std::uint64_t sum = 0;
            for (; i < end; i += 8) {
                std::uint64_t x, y;
                std::memcpy(&x, a + i, 8);
                std::memcpy(&y, b + i, 8);
                sum += x ^ y;
            }
            const std::uint64_t pairs = (sum & kEvenBytes) + (sum >> 8 & kEvenBytes);  // four 16-bit sums
            count += std::size_t((pairs * kShorts) >> 48);
        }
        for (; i < n; ++i) count += a[i] != b[i];
        return count;
    }

    // The number of samples where two rows differ; rows without a change of flag are compared by their first flag.
    std::size_t rowDifferences(const std::uint8_t* a, const RowSpan& spanA, const std::uint8_t* b,
                               const RowSpan& spanB) const {
        if (spanA.lo >= spanA.hi && spanB.lo >= spanB.hi) return spanA.first != spanB.first ? std::size_t(nx_) : 0;
        return differences(a, b, std::size_t(nx_));
    }

    // Crossed z-edges between the slices in `bottom` and `top`.
    std::size_t verticalCrossings(int bottom, int top) const {
        std::size_t count = 0;
        for (int y = 0; y < ny_; ++y) {
            const std::size_t row = std::size_t(nx_) * std::size_t(y);
            count += rowDifferences(flags_[bottom].data() + row, spans_[bottom][std::size_t(y)],
                                    flags_[top].data() + row, spans_[top][std::size_t(y)]);
        }
        return count;
    }

    // Crossed x- and y-edges of the slice in `slot`.
    std::size_t planarCrossings(int slot) const {
        const std::uint8_t* flags = flags_[slot].data();
        std::size_t count = 0;
        for (int y = 0; y < ny_; ++y) {
            const std::uint8_t* row = flags + std::size_t(nx_) * std::size_t(y);
            const RowSpan& span = spans_[slot][std::size_t(y)];
            if (span.lo < span.hi)
                count += differences(row + span.lo, row + span.lo + 1, std::size_t(span.hi - span.lo));
            if (y + 1 < ny_) count += rowDifferences(row, span, row + nx_, spans_[slot][std::size_t(y) + 1]);
        }
        return count;
    }

    template <bool SeamSlab>
    void marchRow(int y, int z, int bottom, int top) {
        int begin, end;
        if (!rowRange(y, bottom, top, begin, end)) return;
        const std::size_t row = std::size_t(nx_) * std::size_t(y);
        const std::uint8_t* columns = columns_.data();
        // Only a cell on the volume's border makes vertices on it.
        const bool borderRow = y == 0 || y + 2 == ny_ || z == 0 || z + 2 == nz_;
        for (int x = nextActiveCell(columns, begin, end); x < end; x = nextActiveCell(columns, x + 1, end)) {
            const unsigned config = slots_.configOfColumns[columns[x] | columns[x + 1] << 4];
            const bool onBorder = borderRow || x == 0 || x + 2 == nx_;
            std::array<std::uint32_t, 12> ids;
            const std::size_t cell = row + std::size_t(x);
            for (unsigned mask = slots_.crossed[config]; mask != 0; mask &= mask - 1) {
                const int e = __builtin_ctz(mask);
                ids[e] = vertexOnEdge<SeamSlab>(x, y, z, cell, e, bottom, top, onBorder);
            }
            const CaseContinuation& cased = table_[config];
            if (labels_.parent)
                labels_.unitePieces(config, cased, ids,
                                    unsigned(x > 0) | unsigned(y > 0) << 1 | unsigned(z > chunk_->zBegin) << 2);
            const int triangles = triangleCount_[config];
            const std::size_t at = chunk_->indexBase + chunk_->indexCursor;
            std::uint32_t* out = mesh_.indices.data() + at;
            // Placeholders for the next chunk's slice come only in a seam slab.
            for (int t = 0; t < triangles; ++t) {
                const auto& tri = cased.triangles[t];
                for (int k = 0; k < 3; ++k) out[3 * t + k] = ids[tri[k]];
            }
            if (SeamSlab) {
                for (int c = 0; c < 3 * triangles; ++c) {
                    if (out[c] & kSeamBit) chunk_->seamIndices.push_back(at + std::size_t(c));
                }
            }
            chunk_->indexCursor += 3 * std::size_t(triangles);
        }
    }

    template <bool SeamSlab>
    std::uint32_t vertexOnEdge(int x, int y, int z, std::size_t cell, int edge, int bottom, int top, bool onBorder) {
        const int axis = slots_.axis[edge];
        const std::size_t at = cell + slots_.offset[edge];
        std::uint32_t* slot;
        std::uint32_t threshold;
        if (axis == 2) {
            slot = &vertical_[at];
            threshold = verticalThreshold_;
        } else {
            const bool upper = slots_.origin[edge][2] != 0;
            const int s = upper ? top : bottom;
            if (SeamSlab && upper) return kSeamBit | static_cast<std::uint32_t>(std::size_t(axis) * sliceSize_ + at);
            slot = &planar_[s][std::size_t(axis) * sliceSize_ + at];
            threshold = threshold_[s];
        }
        if (*slot != kNoVertex && *slot >= threshold) return *slot;
        const std::size_t id = chunk_->vertexBase + chunk_->vertexCursor++;
        *slot = static_cast<std::uint32_t>(id);
        const auto& o = slots_.origin[edge];
        const GridEdge gridEdge{x + o[0], y + o[1], z + o[2], axis};
        if (labels_.parent) {
            labels_.addVertex(*slot);
            if (onBorder && detail::edgeOnVolumeBorder(gridEdge, Dims{nx_, ny_, nz_}))
                chunk_->borderVertices.push_back(*slot);
        }
        grid_.edgeVertex(gridEdge.x, gridEdge.y, gridEdge.z, axis, mesh_.vertices[id]);
        mesh_.vertexEdges[id] = gridEdge;
        return *slot;
    }

    const detail::SampleGrid<T>& grid_;
    const std::array<CaseContinuation, 256>& table_;
    const EdgeSlots& slots_;
    const detail::SurfaceLabels labels_;
    Chunk* chunk_ = nullptr;  // the chunk being marched
    Mesh& mesh_;
    const int nx_, ny_, nz_;
    const std::size_t sliceSize_, rowBytes_;
    std::array<std::vector<std::uint8_t>, 2> flags_;
    std::array<std::vector<RowSpan>, 2> spans_;
    std::array<std::vector<std::uint32_t>, 2> planar_;  // x then y edges of a slice, ping-pong
    std::vector<std::uint32_t> vertical_;               // z edges of the current slab
    std::vector<std::uint8_t> columns_;                 // per x, the four flags of the cell row's corners
    std::array<std::uint8_t, 256> triangleCount_{};
    std::array<std::uint32_t, 2> threshold_{};
    std::uint32_t verticalThreshold_ = 0;
};

// Gives each chunk its ranges of the final buffers and sizes them once.
void allocate(std::vector<Chunk>& chunks, Mesh& mesh) {
    std::size_t vertices = 0, triangles = 0;
    for (Chunk& chunk : chunks) {
        chunk.vertexBase = vertices;
        chunk.indexBase = 3 * triangles;
        vertices += chunk.vertexCount;
        triangles += chunk.triangleCount;
    }
    if (vertices >= kSeamBit) throw std::length_error("marching cubes: more than 2^31 vertices");
    detail::resizeOnHugePages(mesh.vertices, vertices);
    detail::resizeOnHugePages(mesh.vertexEdges, vertices);
    detail::resizeOnHugePages(mesh.indices, 3 * triangles);
}

// Resolves the placeholders chunk c left for chunk c + 1's first slice, once both are written.
void resolveSeam(std::vector<Chunk>& chunks, std::size_t c, Mesh& mesh) {
    const std::vector<std::uint32_t>& next = chunks[c + 1].firstSliceIds;
    for (std::size_t at : chunks[c].seamIndices) mesh.indices[at] = next[mesh.indices[at] & ~kSeamBit];
}

// The exhaustive pass on `threads` threads; labels surfaces in *parent and tallies
// cell pieces in *tally (both resized to one entry per vertex) when given.
std::vector<Chunk> march(const Volume& volume, double iso, TableKind table, int threads, Mesh& mesh,
                         Buffer<std::uint32_t>* parent, Buffer<std::uint8_t>* tally, ExtractProgress* progress) {
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return {};
    const int slabs = n[2] - 1;
    threads = std::max(1, threads);
    // Several chunks per thread even out surfaces that crowd one part of the volume.
    const int chunkCount = threads == 1 ? 1 : std::min(slabs, threads * 4);
    std::vector<Chunk> chunks(static_cast<std::size_t>(chunkCount));
    for (int c = 0; c < chunkCount; ++c) {
        chunks[std::size_t(c)].zBegin = int(std::int64_t(slabs) * c / chunkCount);
        chunks[std::size_t(c)].zEnd = int(std::int64_t(slabs) * (c + 1) / chunkCount);
        chunks[std::size_t(c)].last = c + 1 == chunkCount;
    }
    if (progress) progress->slabsTotal.fetch_add(2 * std::uint64_t(slabs), std::memory_order_relaxed);
    const auto& continuation = continuationTable(table);
    const EdgeSlots slots = edgeSlots(n[0]);
    visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const detail::SampleGrid<T> grid(volume, samples, iso);
        // A marcher per thread, its slices of flags and ids reused from chunk to chunk.
        detail::parallelForWithState(
            chunkCount, threads,
            [&] { return ChunkMarcher<T>(volume, grid, continuation, slots, detail::SurfaceLabels{}, mesh, progress); },
            [&](ChunkMarcher<T>& marcher, int c) { marcher.count(chunks[std::size_t(c)]); });
        allocate(chunks, mesh);
        detail::SurfaceLabels labels;
        if (parent) {
            detail::resizeOnHugePages(*parent, mesh.vertices.size());
            detail::resizeOnHugePages(*tally, mesh.vertices.size());
            labels = {&detail::pieceUnions(table), parent->data(), tally->data()};
        }
        // A seam is resolved, and joined when labelling, by whichever of its two
        // chunks is written last, on its thread, while other chunks are marched.
        std::vector<std::atomic<int>> written(chunks.size());
        std::mutex joining;
        auto chunkWritten = [&](std::size_t seam) {
            if (written[seam].fetch_add(1) != 1) return;
            resolveSeam(chunks, seam, mesh);
            if (labels.parent) {
                const std::lock_guard<std::mutex> lock(joining);
                detail::stitchSeam(chunks[seam].seamIndices, mesh, labels.parent);
            }
        };
        detail::parallelForWithState(
            chunkCount, threads,
            [&] { return ChunkMarcher<T>(volume, grid, continuation, slots, labels, mesh, progress); },
            [&](ChunkMarcher<T>& marcher, int index) {
                const std::size_t c = std::size_t(index);
                marcher.run(chunks[c]);
                if (c > 0) chunkWritten(c - 1);
                if (c + 1 < chunks.size()) chunkWritten(c);
            });
    });
    return chunks;
}

}  // namespace

Mesh marchingCubes(const Volume& volume, double iso, TableKind table, int threads) {
    return detail::marchingCubes(volume, iso, table, threads, nullptr);
}

namespace detail {

Mesh marchingCubes(const Volume& volume, double iso, TableKind table, int threads, ExtractProgress* progress) {
    Mesh mesh;
    if (table == TableKind::Trilinear)
        mesh = marchTrilinear(volume, iso, threads);
    else if (table == TableKind::Snap)
        mesh = marchSnap(volume, iso, threads);
    else
        march(volume, iso, table, threads, mesh, nullptr, nullptr, progress);
    volume.throwIfDamaged();  // a mapped file that shrank meanwhile read as zeros
    return mesh;
}

LabelledMesh marchLabelled(const Volume& volume, double iso, TableKind table, int threads, ExtractProgress* progress) {
    LabelledMesh out;
    std::vector<Chunk> chunks = march(volume, iso, table, threads, out.mesh, &out.parent, &out.tally, progress);
    for (Chunk& chunk : chunks) {
        out.chunks.push_back({chunk.vertexBase, chunk.vertexBase + chunk.vertexCount, chunk.indexBase / 3,
                              chunk.indexBase / 3 + chunk.triangleCount, std::move(chunk.borderVertices)});
    }
    return out;
}

}  // namespace detail

}  // namespace isotrack
