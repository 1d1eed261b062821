#pragma once
// The ownership rule every GL object type follows: one non-zero handle, freed by
// the destructor; copies are deleted; a move hands the handle over and zeroes
// the source, so exactly one owner ever frees it.
#include <utility>

namespace isotrack::gl {

template <void (*Destroy)(unsigned)>
class UniqueHandle {
public:
    UniqueHandle() = default;
    explicit UniqueHandle(unsigned id) : id_(id) {}
    ~UniqueHandle() { reset(); }

    UniqueHandle(const UniqueHandle&) = delete;
    UniqueHandle& operator=(const UniqueHandle&) = delete;
    UniqueHandle(UniqueHandle&& other) noexcept : id_(std::exchange(other.id_, 0u)) {}
    UniqueHandle& operator=(UniqueHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0u);
        }
        return *this;
    }

    unsigned id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Destroy(std::exchange(id_, 0u));
    }

private:
    unsigned id_ = 0;
};

}  // namespace isotrack::gl
