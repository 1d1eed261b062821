#pragma once
// A file's samples mapped read-only into memory, never copied: a volume bigger
// than memory costs address space, and only the pages an extraction touches are
// read from disk. A Volume over a MappedFile keeps it alive (isotrack/volume.h).
//
// Releasing: a pass that streams over the volume (marching cubes, every surface)
// lets the slices it has passed go (madvise MADV_DONTNEED), so that what stays
// resident is a few slabs, not the volume; a page released and touched again is
// simply read again.
//
// Faults: a page of a file that shrank or vanished after it was mapped cannot be
// read, and the kernel answers the access with SIGBUS. isotrack's handler maps
// zeros in place of that page and the rest of the mapping, marks the file as
// damaged and lets the access go on (streaming passes stop at their next batch); throwIfDamaged() then turns that into
// a FormatError naming the file, so a truncated file is a one-line error, never a crash. Extractions check it when they
// finish (Volume::throwIfDamaged); the zeros read meanwhile are discarded with the result.
#include <cstddef>
#include <cstdint>
#include <string>

namespace isotrack {

class MappedFile {
public:
    // Maps bytes [offset, offset + length) of `path`. FormatError "WHERE: ..." when
    // the file cannot be opened or mapped or is shorter than that.
    MappedFile(const std::string& path, std::uint64_t offset, std::uint64_t length, std::string where);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    const std::byte* data() const { return data_; }  // the byte at `offset`
    std::uint64_t size() const { return length_; }
    const std::string& where() const { return where_; }

    // Lets the pages holding bytes [begin, end) go from this process's memory.
    void release(std::uint64_t begin, std::uint64_t end) const;
    // Bytes of the mapping resident in this process now (pages it has touched
    // and not released), from /proc/self/smaps; 0 where that is not available.
    std::uint64_t residentBytes() const;
    // Whether a page could not be read (zeros were read in its place).
    bool damaged() const;
    // FormatError "WHERE: the file was truncated or removed while it was read".
    void throwIfDamaged() const;

    // The live mapping whose bytes hold `address`, else null: for front ends that
    // hand the samples on as raw memory (a numpy array) and check them afterwards.
    static const MappedFile* containing(const void* address);

private:
    std::byte* base_ = nullptr;  // page-aligned start of the mapping
    std::uint64_t mappedLength_ = 0;
    const std::byte* data_ = nullptr;
    std::uint64_t length_ = 0;
    std::string where_;
    int guardSlot_ = -1;
};

// Memory the system can give without swapping (Linux: MemAvailable), and no
// more than the process's limits leave (ulimit -v and -d: RLIMIT_AS, RLIMIT_DATA),
// in bytes.
std::uint64_t availableMemoryBytes();

}  // namespace isotrack
