// The samples in ascending order for the contour tree: a stable LSD radix sort
// of unsigned keys that order the values as SampleOrder does (NaN lowest, -0
// with +0), so equal values stay in index order.
//
// Samples of up to 4 bytes are sorted as (key, index) pairs of 8 bytes, read
// and written in sequence: 8-bit digits for keys of 8 and 16 bits, 11-bit
// digits (3 passes) for 32. One read of the values counts the digits of every
// pass; a pass where one digit holds every key is skipped. Each pass scatters
// on up to `threads` threads, each thread a contiguous part (its keys go after
// those of the parts before it in every bucket, which keeps the sort stable),
// and counts the next pass's digits by the part of its output they land in,
// which is that pass's input. The pairs go back and forth between the two
// blocks of SortedSamples, 16 bytes a sample; the last pass writes only the
// indices, into the first half of `sorted`. 8-byte samples are sorted by
// index through their keys, 16 bits a pass.
#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <type_traits>
#include <utility>

#include "extract/contour_tree/contour_tree_build.h"

namespace isotrack::detail {
namespace {

// An unsigned key in the order of the values; NaN is 0, below every number.
template <class T>
auto sortKey(T v) {
    if constexpr (std::is_floating_point_v<T>) {
        using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
        if (std::isnan(v)) return U(0);
        if (v == T(0)) v = T(0);  // -0 sorts with +0
        U bits;
        std::memcpy(&bits, &v, sizeof bits);
        const U sign = U(1) << (8 * sizeof(U) - 1);
        return (bits & sign) ? U(~bits) : U(bits | sign);
    } else {
        using U = std::make_unsigned_t<T>;
        return U(U(v) ^ (std::is_signed_v<T> ? U(U(1) << (8 * sizeof(T) - 1)) : U(0)));
    }
}

template <class T>
SortedSamples radixSort(const T* values, std::uint32_t n, const BuildProgress& progress) {
    constexpr int kKeyBits = 8 * sizeof(T), kDigitBits = kKeyBits < 16 ? kKeyBits : 16;
    constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
    SortedSamples out{Pages(8 * std::size_t(n)), Pages(8 * std::size_t(n)), n};
    Slice<std::uint32_t> order = out.order(), spare = sliceOf<std::uint32_t>(out.sorted, 4 * std::size_t(n), n);
    std::vector<std::uint32_t> count(kBuckets);
    progress.setTotal(std::uint64_t(n) * (kKeyBits / kDigitBits));  // a pass a digit, one sample each
    for (int shift = 0; shift < kKeyBits; shift += kDigitBits) {
        if (shift > 0) progress.count(n);
        const bool first = shift == 0;
        const std::uint32_t* in = first ? nullptr : order.begin();
        std::uint32_t* to = first ? order.begin() : spare.begin();
        auto digit = [&](std::uint32_t s) { return std::size_t(sortKey(values[s]) >> shift) & (kBuckets - 1); };
        progress.check();
        std::fill(count.begin(), count.end(), 0u);
        for (std::uint32_t i = 0; i < n; ++i) ++count[digit(first ? i : in[i])];
        if (count[digit(first ? 0 : in[0])] == n) {  // one digit for all: nothing moves
            if (first) std::iota(order.begin(), order.end(), 0u);
            continue;
        }
        std::uint32_t sum = 0;
        for (std::uint32_t& c : count) sum += std::exchange(c, sum);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t s = first ? i : in[i];
            to[count[digit(s)]++] = s;
        }
        if (!first) std::swap(order, spare);
    }
    progress.count(n);
    if (order.begin() != out.order().begin()) std::copy(order.begin(), order.end(), out.order().begin());
    return out;
}

// Parts of [0, n) for the threads: part p is [bound[p], bound[p + 1]) with
// bound[p] = ceil(n p / parts), so position i is in part floor(i parts / n),
// found without a division: a table by i's high bits gives the part where
// i's block starts, and a block, no longer than a part, crosses one bound at most.
class Parts {
public:
    Parts(std::uint32_t n, int parts) : bound_(std::size_t(parts) + 1) {
        for (int p = 0; p <= parts; ++p) {
            bound_[std::size_t(p)] =
                std::uint32_t((std::uint64_t(n) * std::uint64_t(p) + std::uint64_t(parts) - 1) / std::uint64_t(parts));
        }
        while (shift_ < 31 && (std::uint64_t(2) << shift_) <= std::max<std::uint64_t>(1, n / std::uint32_t(parts))) {
            ++shift_;
        }
        start_.resize(std::size_t(n >> shift_) + 1);
        for (std::size_t b = 0; b < start_.size(); ++b) start_[b] = std::uint16_t(find(std::uint32_t(b << shift_)));
    }
    int count() const { return int(bound_.size()) - 1; }
    std::uint32_t begin(int p) const { return bound_[std::size_t(p)]; }
    std::uint32_t end(int p) const { return bound_[std::size_t(p) + 1]; }
    int of(std::uint32_t i) const {
        const int p = start_[i >> shift_];
        return i >= bound_[std::size_t(p) + 1] ? p + 1 : p;
    }

private:
    int find(std::uint32_t i) const {
        int p = 0;
        while (p + 1 < count() && i >= bound_[std::size_t(p) + 1]) ++p;
        return p;
    }
    std::vector<std::uint32_t> bound_;
    std::vector<std::uint16_t> start_;
    int shift_ = 0;
};

// Runs part(p, begin, end) for the parts, on a thread each (kept threads,
// parallel.h), a stride of samples at a time, each counted as done: a cancel
// stops them between strides, and Cancelled, as any part's exception, reaches
// the calling thread.
template <class Part>
void inParts(const Parts& parts, const BuildProgress& progress, Part&& part) {
    parallelFor(parts.count(), parts.count(), [&](int p) {
        progress.inStrides(
            parts.begin(p), parts.end(p), [&](std::uint32_t begin, std::uint32_t end) { part(p, begin, end); }, true);
    });
}

template <class T>
SortedSamples radixSortPairs(const T* values, std::uint32_t n, int threads, const BuildProgress& progress) {
    constexpr int kKeyBits = 8 * sizeof(T), kDigitBits = kKeyBits <= 16 ? 8 : 11;
    constexpr int kPasses = (kKeyBits + kDigitBits - 1) / kDigitBits;
    constexpr std::uint32_t kBuckets = 1u << kDigitBits;
    const Parts parts(n, n < (1u << 16) ? 1 : std::max(1, std::min(threads, 1 << 15)));
    const auto np = std::size_t(parts.count());
    SortedSamples out{Pages(8 * std::size_t(n)), Pages(8 * std::size_t(n)), n};
    auto pairOf = [&](std::uint32_t i) { return std::uint64_t(sortKey(values[i])) << 32 | i; };
    auto digit = [](std::uint64_t pair, int pass) {
        return std::uint32_t(pair >> (32 + pass * kDigitBits)) & (kBuckets - 1);
    };
    // One read of the values counts the digits of every pass, by part (the
    // parts of the index order, which is the input of the first pass to move).
    std::vector<std::uint32_t> count(kPasses * np * kBuckets);
    auto counts = [&](int pass, std::size_t part) { return &count[(std::size_t(pass) * np + part) * kBuckets]; };
    progress.setTotal(std::uint64_t(n) * (1 + kPasses));  // the counting read and at most kPasses moves
    inParts(parts, progress, [&](int p, std::uint32_t begin, std::uint32_t end) {
        std::uint32_t* c[kPasses];
        for (int pass = 0; pass < kPasses; ++pass) c[pass] = counts(pass, std::size_t(p));
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint64_t pair = pairOf(i);
            for (int pass = 0; pass < kPasses; ++pass) ++c[pass][digit(pair, pass)];
        }
    });
    std::vector<int> moving;  // the passes where no one digit holds every key
    for (int pass = 0; pass < kPasses; ++pass) {
        bool one = false;
        for (std::uint32_t b = 0; b < kBuckets && !one; ++b) {
            std::uint32_t total = 0;
            for (std::size_t p = 0; p < np; ++p) total += counts(pass, p)[b];
            one = total == n;
        }
        if (!one) moving.push_back(pass);
    }
    progress.setTotal(std::uint64_t(n) * (1 + moving.size()));
    const Slice<std::uint32_t> order = out.order();
    if (moving.empty()) {
        std::iota(order.begin(), order.end(), 0u);
        return out;
    }
    // The pairs go back and forth between the blocks; the last pass writes only
    // the indices, into the first half of `sorted`. Each pass but the last also
    // counts the next one's digits, by the part of the output they land in
    // (next: by thread, then that part), which is the next pass's input.
    const std::size_t passes = moving.size();
    auto pairsOf = [&](std::size_t i) { return ((passes - 1 - i) % 2 ? out.spare : out.sorted).at<std::uint64_t>(0); };
    std::vector<std::uint32_t> next(np > 1 ? np * np * kBuckets : 0);
    for (std::size_t i = 0; i < passes; ++i) {
        const int pass = moving[i], following = i + 1 < passes ? moving[i + 1] : 0;
        const std::uint64_t* in = i == 0 ? nullptr : pairsOf(i - 1);
        std::uint32_t sum = 0;
        for (std::uint32_t b = 0; b < kBuckets; ++b) {
            for (std::size_t p = 0; p < np; ++p) sum += std::exchange(counts(pass, p)[b], sum);
        }
        std::fill(next.begin(), next.end(), 0u);
        inParts(parts, progress, [&](int p, std::uint32_t begin, std::uint32_t end) {
            std::uint32_t* c = counts(pass, std::size_t(p));
            auto scatter = [&](auto&& put) {
                if (in) {
                    for (std::uint32_t k = begin; k < end; ++k) put(in[k], c[digit(in[k], pass)]++);
                } else {
                    for (std::uint32_t k = begin; k < end; ++k) {
                        const std::uint64_t pair = pairOf(k);
                        put(pair, c[digit(pair, pass)]++);
                    }
                }
            };
            if (i + 1 == passes) {
                scatter([&](std::uint64_t pair, std::uint32_t at) { order[at] = std::uint32_t(pair); });
            } else if (np == 1) {  // the totals are the one part's counts already
                std::uint64_t* to = pairsOf(i);
                scatter([&](std::uint64_t pair, std::uint32_t at) { to[at] = pair; });
            } else {
                std::uint64_t* to = pairsOf(i);
                std::uint32_t* mine = &next[std::size_t(p) * np * kBuckets];
                scatter([&](std::uint64_t pair, std::uint32_t at) {
                    to[at] = pair;
                    ++mine[std::size_t(parts.of(at)) * kBuckets + digit(pair, following)];
                });
            }
        });
        if (i + 1 < passes && np > 1) {
            for (std::size_t q = 0; q < np; ++q) {
                std::uint32_t* c = counts(following, q);
                std::fill(c, c + kBuckets, 0u);
                for (std::size_t p = 0; p < np; ++p) {
                    const std::uint32_t* from = &next[(p * np + q) * kBuckets];
                    for (std::uint32_t b = 0; b < kBuckets; ++b) c[b] += from[b];
                }
            }
        }
    }
    return out;
}

}  // namespace

SortedSamples sortSamples(const Volume& volume, int threads, const BuildProgress& progress) {
    const auto n = std::uint32_t(volume.sampleCount());
    return visitSamples(volume, [&](const auto* values) {
        using T = std::remove_const_t<std::remove_pointer_t<decltype(values)>>;
        if constexpr (sizeof(T) <= 4) {
            return radixSortPairs(values, n, threads, progress);
        } else {
            return radixSort(values, n, progress);
        }
    });
}

}  // namespace isotrack::detail
