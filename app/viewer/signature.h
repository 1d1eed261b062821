#pragma once
// A signature of what a frame would draw (Scene::signature, ViewCache).
#include <cstddef>
#include <cstdint>

namespace isotrack::viewer {

// FNV-1a over the bytes of plain values, for signatures.
class Signature {
public:
    template <class T>
    Signature& add(const T& value) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
        for (std::size_t i = 0; i < sizeof(T); ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
        return *this;
    }
    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace isotrack::viewer
