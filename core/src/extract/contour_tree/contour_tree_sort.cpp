// The samples in ascending order for the contour tree: a stable LSD radix sort
// of unsigned keys that order the values as SampleOrder does (NaN lowest, -0
// with +0), so equal values stay in index order.
//
// Samples of up to 4 bytes are sorted as (key, index) pairs of 8 bytes, read
// and written in sequence: 8-bit digits for keys of 8 and 16 bits, 11-bit
// digits (3 passes) for 32. A pass where one digit holds every key is
// skipped. Each pass counts and scatters on up to `threads` threads, each
// thread a contiguous part (its keys go after those of the parts before it in
// every bucket, which keeps the sort stable). 16 bytes a sample at the peak,
// 20 while the order is copied out. 8-byte samples are sorted by index
// through their keys, 16 bits a pass.
#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <thread>
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
Buffer<std::uint32_t> radixSort(const T* values, std::uint32_t n) {
    constexpr int kKeyBits = 8 * sizeof(T), kDigitBits = kKeyBits < 16 ? kKeyBits : 16;
    constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
    Buffer<std::uint32_t> order(n), spare(kKeyBits > kDigitBits ? n : 0);
    std::vector<std::uint32_t> count(kBuckets);
    for (int shift = 0; shift < kKeyBits; shift += kDigitBits) {
        const bool first = shift == 0;
        const std::uint32_t* in = first ? nullptr : order.data();
        std::uint32_t* out = first ? order.data() : spare.data();
        auto digit = [&](std::uint32_t s) { return std::size_t(sortKey(values[s]) >> shift) & (kBuckets - 1); };
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
            out[count[digit(s)]++] = s;
        }
        if (!first) order.swap(spare);
    }
    return order;
}

// Runs part(p, begin, end) for the parts of [0, n), on a thread each.
template <class Part>
void inParts(std::uint32_t n, int parts, Part&& part) {
    std::vector<std::thread> helpers;
    auto bounds = [&](int p) { return std::uint32_t(std::uint64_t(n) * std::uint64_t(p) / std::uint64_t(parts)); };
    for (int p = 1; p < parts; ++p) helpers.emplace_back([&, p] { part(p, bounds(p), bounds(p + 1)); });
    part(0, 0u, bounds(1));
    for (std::thread& helper : helpers) helper.join();
}

template <class T>
Buffer<std::uint32_t> radixSortPairs(const T* values, std::uint32_t n, int threads) {
    constexpr int kKeyBits = 8 * sizeof(T), kDigitBits = kKeyBits <= 16 ? 8 : 11;
    constexpr std::uint32_t kBuckets = 1u << kDigitBits;
    const int parts = n < (1u << 16) ? 1 : std::max(1, threads);
    Buffer<std::uint64_t> pairs(n), spare(n);
    std::vector<std::uint32_t> count(std::size_t(parts) * kBuckets);
    bool inPairs = false;  // false: the input is still the values, in index order
    auto pairAt = [&](std::uint32_t i) { return inPairs ? pairs[i] : (std::uint64_t(sortKey(values[i])) << 32 | i); };
    for (int shift = 32; shift < 32 + kKeyBits; shift += kDigitBits) {
        auto digit = [&](std::uint64_t pair) { return std::uint32_t(pair >> shift) & (kBuckets - 1); };
        std::fill(count.begin(), count.end(), 0u);
        inParts(n, parts, [&](int p, std::uint32_t begin, std::uint32_t end) {
            std::uint32_t* c = &count[std::size_t(p) * kBuckets];
            for (std::uint32_t i = begin; i < end; ++i) ++c[digit(pairAt(i))];
        });
        std::uint32_t sum = 0;
        bool one = false;
        for (std::uint32_t b = 0; b < kBuckets; ++b) {
            std::uint32_t total = 0;
            for (int p = 0; p < parts; ++p) total += count[std::size_t(p) * kBuckets + b];
            one = one || total == n;
            for (int p = 0; p < parts; ++p) sum += std::exchange(count[std::size_t(p) * kBuckets + b], sum);
        }
        if (one && inPairs) continue;
        std::uint64_t* out = inPairs ? spare.data() : pairs.data();
        inParts(n, parts, [&](int p, std::uint32_t begin, std::uint32_t end) {
            std::uint32_t* c = &count[std::size_t(p) * kBuckets];
            for (std::uint32_t i = begin; i < end; ++i) {
                const std::uint64_t pair = pairAt(i);
                out[c[digit(pair)]++] = pair;
            }
        });
        if (inPairs) pairs.swap(spare);
        inPairs = true;
    }
    Buffer<std::uint64_t>().swap(spare);
    Buffer<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = std::uint32_t(pairs[i]);
    return order;
}

}  // namespace

Buffer<std::uint32_t> sortSamples(const Volume& volume, int threads) {
    const auto n = std::uint32_t(volume.sampleCount());
    return visitSamples(volume, [&](const auto* values) {
        using T = std::remove_const_t<std::remove_pointer_t<decltype(values)>>;
        if constexpr (sizeof(T) <= 4) {
            return radixSortPairs(values, n, threads);
        } else {
            return radixSort(values, n);
        }
    });
}

}  // namespace isotrack::detail
