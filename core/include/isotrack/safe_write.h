#pragma once
// Writing a file so that it is either the old file or the whole new one.
//
// The bytes go to a temporary file beside the target (same folder, so the same
// file system), which is flushed, fsync'ed and then renamed over the target. On
// any failure the temporary is removed, the target is left byte-identical and a
// FormatError names the target and the cause ("No space left on device").
// A file that is not committed (an exception on the way) is discarded.
#include <cstddef>
#include <cstdint>
#include <string>

namespace isotrack {

class SafeWriter {
public:
    // Creates the temporary file; a FormatError when the folder is not writable
    // or `path` is a directory.
    explicit SafeWriter(std::string path);
    ~SafeWriter();
    SafeWriter(const SafeWriter&) = delete;
    SafeWriter& operator=(const SafeWriter&) = delete;

    void write(const void* data, std::size_t bytes);
    void write(const std::string& bytes) { write(bytes.data(), bytes.size()); }
    // Flushes, fsyncs, closes and renames over the target. Once only.
    void commit();

    const std::string& path() const { return path_; }

private:
    [[noreturn]] void fail(int error);
    void discard() noexcept;

    std::string path_;
    std::string tempPath_;
    int fd_ = -1;
};

// The whole file in one call.
void writeFileSafely(const std::string& path, const std::string& contents);

namespace testing {
// Makes SafeWriter fail with `error` (errno, e.g. ENOSPC) once `bytes` more bytes
// have been written, as a full disk does; a negative count turns it off.
void failWritesAfter(long long bytes, int error);
}  // namespace testing

}  // namespace isotrack
