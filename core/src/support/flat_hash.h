#pragma once
// An open-addressing hash map from 64-bit keys to 32-bit values, for the sets
// and maps whose size follows a tracked surface rather than the volume.
// Linear probing over a power-of-two table; the all-ones key is reserved.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace isotrack::detail {

class FlatHashMap {
public:
    static constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();

    FlatHashMap() : FlatHashMap(16) {}
    explicit FlatHashMap(std::size_t expected) { rehash(capacityFor(expected)); }

    // Returns the value slot for `key`, inserting `value` first if the key is new.
    // `inserted` tells which happened.
    std::uint32_t& findOrInsert(std::uint64_t key, std::uint32_t value, bool& inserted) {
        if ((size_ + 1) * 4 > keys_.size() * 3) rehash(keys_.size() * 2);
        std::size_t i = slot(key);
        while (keys_[i] != kEmpty) {
            if (keys_[i] == key) {
                inserted = false;
                return values_[i];
            }
            i = (i + 1) & mask_;
        }
        keys_[i] = key;
        values_[i] = value;
        ++size_;
        inserted = true;
        return values_[i];
    }

    // True when `key` was not yet present (and is now).
    bool insert(std::uint64_t key) {
        bool inserted = false;
        findOrInsert(key, 0, inserted);
        return inserted;
    }

    const std::uint32_t* find(std::uint64_t key) const {
        for (std::size_t i = slot(key); keys_[i] != kEmpty; i = (i + 1) & mask_) {
            if (keys_[i] == key) return &values_[i];
        }
        return nullptr;
    }

    std::size_t size() const { return size_; }
    std::size_t byteSize() const { return keys_.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t)); }

    void clear() {
        std::fill(keys_.begin(), keys_.end(), kEmpty);
        size_ = 0;
    }

private:
    static std::size_t capacityFor(std::size_t expected) {
        std::size_t capacity = 16;
        while (capacity * 3 < expected * 4) capacity *= 2;
        return capacity;
    }

    std::size_t slot(std::uint64_t key) const {
        // splitmix64's finaliser spreads neighbouring grid indices over the table.
        key ^= key >> 30;
        key *= 0xbf58476d1ce4e5b9ull;
        key ^= key >> 27;
        key *= 0x94d049bb133111ebull;
        key ^= key >> 31;
        return static_cast<std::size_t>(key) & mask_;
    }

    void rehash(std::size_t capacity) {
        std::vector<std::uint64_t> oldKeys(capacity, kEmpty);
        std::vector<std::uint32_t> oldValues(capacity);
        oldKeys.swap(keys_);
        oldValues.swap(values_);
        mask_ = capacity - 1;
        size_ = 0;
        for (std::size_t i = 0; i < oldKeys.size(); ++i) {
            if (oldKeys[i] == kEmpty) continue;
            std::size_t j = slot(oldKeys[i]);
            while (keys_[j] != kEmpty) j = (j + 1) & mask_;
            keys_[j] = oldKeys[i];
            values_[j] = oldValues[i];
            ++size_;
        }
    }

    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> values_;
    std::size_t mask_ = 0;
    std::size_t size_ = 0;
};

}  // namespace isotrack::detail
