// Temporary file, fsync, rename: see isotrack/safe_write.h.
#include "isotrack/safe_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "isotrack/errors.h"

namespace isotrack {

namespace {

namespace fs = std::filesystem;

std::atomic<long long> faultBudget{-1};  // bytes left before an injected failure; -1: none
std::atomic<int> faultError{0};

// Bytes of a write of `want` that the injected fault lets through; sets errno when it bites.
std::size_t allowedBytes(std::size_t want) {
    const long long left = faultBudget.load();
    if (left < 0) return want;
    if (std::size_t(left) >= want) {
        faultBudget -= (long long)(want);
        return want;
    }
    faultBudget = 0;
    return std::size_t(left);
}

// The mode a new file would get (0666 less the umask), or the target's when it exists.
mode_t modeFor(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return st.st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

}  // namespace

SafeWriter::SafeWriter(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (fs::is_directory(path_, ec)) throw FormatError(path_ + ": cannot open: " + std::strerror(EISDIR));
    const fs::path target(path_);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::string pattern = (folder / ("." + target.filename().string() + ".tmp.XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    fd_ = ::mkstemp(name.data());
    if (fd_ < 0)
        throw FormatError(path_ + ": cannot open: " + std::strerror(errno) + " (creating a temporary file in " +
                          folder.string() + ")");
    tempPath_ = name.data();
    if (::fchmod(fd_, modeFor(path_)) != 0) fail(errno);
}

SafeWriter::~SafeWriter() { discard(); }

void SafeWriter::discard() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!tempPath_.empty()) ::unlink(tempPath_.c_str());
    tempPath_.clear();
}

void SafeWriter::fail(int error) {
    discard();
    throw FormatError(path_ + ": cannot write: " + std::strerror(error) + " (the previous file, if any, is unchanged)");
}

void SafeWriter::write(const void* data, std::size_t bytes) {
    if (fd_ < 0) throw FormatError(path_ + ": cannot write: the file is already closed");
    const auto* p = static_cast<const char*>(data);
    while (bytes > 0) {
        const std::size_t allowed = allowedBytes(bytes);
        if (allowed == 0) fail(faultError.load());
        const ssize_t n = ::write(fd_, p, allowed);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(errno);
        }
        p += n;
        bytes -= std::size_t(n);
    }
}

void SafeWriter::commit() {
    if (fd_ < 0) throw FormatError(path_ + ": cannot write: the file is already closed");
    if (::fsync(fd_) != 0) fail(errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(errno);
    if (::rename(tempPath_.c_str(), path_.c_str()) != 0) fail(errno);
    tempPath_.clear();
    // The rename itself reaches the disk with the folder; a file system that cannot
    // sync a folder still has the complete file under its name.
    const fs::path target(path_);
    const std::string folder = target.has_parent_path() ? target.parent_path().string() : ".";
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

void writeFileSafely(const std::string& path, const std::string& contents) {
    SafeWriter writer(path);
    writer.write(contents);
    writer.commit();
}

namespace testing {

void failWritesAfter(long long bytes, int error) {
    faultError = error;
    faultBudget = bytes < 0 ? -1 : bytes;
}

}  // namespace testing

}  // namespace isotrack
