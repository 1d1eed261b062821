// Read-only file mappings and the SIGBUS guard: see isotrack/mapped_file.h.
//
// The guard is a fixed table of the live mappings' address ranges, read by the
// signal handler without locks (atomics only; registration takes a mutex that
// the handler never touches). The handler replaces the faulting page with an
// anonymous page of zeros (mmap MAP_FIXED: a system call, safe in a handler on
// Linux), with the rest of the mapping after it, marks the mapping damaged and
// returns, so the access is retried and reads zeros. A SIGBUS outside every mapping goes to the handler that was
// there before, or kills the process as it would have.
#include "isotrack/mapped_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>

#include "isotrack/errors.h"

namespace isotrack {
namespace {

struct GuardSlot {
    std::atomic<std::uintptr_t> begin{0}, end{0};  // end == 0: free
    std::atomic<bool> damaged{false};
    const MappedFile* file = nullptr;  // under guardMutex only, never read by the handler
};

constexpr int kGuardSlots = 1024;
std::array<GuardSlot, kGuardSlots> guardSlots;
std::mutex guardMutex;
struct sigaction previousAction {};
bool handlerInstalled = false;

std::uintptr_t pageSize() {
    static const std::uintptr_t size = std::uintptr_t(sysconf(_SC_PAGESIZE));
    return size;
}

void onSigbus(int signal, siginfo_t* info, void* context) {
    const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
    for (GuardSlot& slot : guardSlots) {
        const std::uintptr_t end = slot.end.load(std::memory_order_acquire);
        if (end == 0 || address < slot.begin.load(std::memory_order_relaxed) || address >= end) continue;
        // Zeros from the faulting page to the end of the mapping in one call: a file
        // that shrank has lost its tail, and the rest of the pass then reads on
        // without a signal per page.
        const std::uintptr_t page = address & ~(pageSize() - 1);
        if (mmap(reinterpret_cast<void*>(page), end - page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1,
                 0) != MAP_FAILED) {
            slot.damaged.store(true, std::memory_order_release);
            return;
        }
        break;
    }
    // Not ours (or the page could not be replaced): what would have happened without us.
    if (previousAction.sa_flags & SA_SIGINFO) {
        if (previousAction.sa_sigaction) return previousAction.sa_sigaction(signal, info, context);
    } else if (previousAction.sa_handler != SIG_DFL && previousAction.sa_handler != SIG_IGN &&
               previousAction.sa_handler != nullptr) {
        return previousAction.sa_handler(signal);
    }
    ::signal(SIGBUS, SIG_DFL);
    raise(SIGBUS);
}

int registerGuard(const MappedFile* file, std::uintptr_t begin, std::uintptr_t end, const std::string& where) {
    const std::lock_guard<std::mutex> lock(guardMutex);
    if (!handlerInstalled) {
        struct sigaction action {};
        action.sa_sigaction = onSigbus;
        action.sa_flags = SA_SIGINFO | SA_NODEFER;
        sigemptyset(&action.sa_mask);
        if (sigaction(SIGBUS, &action, &previousAction) != 0)
            throw FormatError(where + ": cannot guard the mapped file: " + std::strerror(errno));
        handlerInstalled = true;
    }
    for (int i = 0; i < kGuardSlots; ++i) {
        GuardSlot& slot = guardSlots[std::size_t(i)];
        if (slot.end.load(std::memory_order_relaxed) != 0) continue;
        slot.damaged.store(false, std::memory_order_relaxed);
        slot.file = file;
        slot.begin.store(begin, std::memory_order_relaxed);
        slot.end.store(end, std::memory_order_release);
        return i;
    }
    throw FormatError(where + ": more than " + std::to_string(kGuardSlots) + " files are mapped at once");
}

void unregisterGuard(int slot) {
    if (slot < 0) return;
    const std::lock_guard<std::mutex> lock(guardMutex);
    guardSlots[std::size_t(slot)].end.store(0, std::memory_order_release);
}

}  // namespace

MappedFile::MappedFile(const std::string& path, std::uint64_t offset, std::uint64_t length, std::string where)
    : length_(length), where_(std::move(where)) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw FormatError(where_ + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    const bool statted = ::fstat(fd, &st) == 0;
    const int statError = errno;
    if (!statted || !S_ISREG(st.st_mode) || std::uint64_t(st.st_size) < offset ||
        std::uint64_t(st.st_size) - offset < length) {
        ::close(fd);
        if (!statted) throw FormatError(where_ + ": cannot read its size: " + std::strerror(statError));
        throw FormatError(where_ + ": " +
                          (S_ISREG(st.st_mode) ? "the file is shorter than its samples" : "not a regular file"));
    }
    const std::uint64_t pageOffset = offset & ~std::uint64_t(pageSize() - 1);
    mappedLength_ = length + (offset - pageOffset);
    void* base =
        mappedLength_ ? ::mmap(nullptr, mappedLength_, PROT_READ, MAP_SHARED, fd, off_t(pageOffset)) : MAP_FAILED;
    const int mapError = errno;
    ::close(fd);  // the mapping keeps the file
    if (mappedLength_ == 0) throw FormatError(where_ + ": no samples to map");
    if (base == MAP_FAILED) throw FormatError(where_ + ": cannot map the file: " + std::strerror(mapError));
    base_ = static_cast<std::byte*>(base);
    data_ = base_ + (offset - pageOffset);
    try {
        guardSlot_ = registerGuard(this, reinterpret_cast<std::uintptr_t>(base_),
                                   reinterpret_cast<std::uintptr_t>(base_) + mappedLength_, where_);
    } catch (...) {
        ::munmap(base_, mappedLength_);
        throw;
    }
}

MappedFile::~MappedFile() {
    unregisterGuard(guardSlot_);
    if (base_) ::munmap(base_, mappedLength_);
}

void MappedFile::release(std::uint64_t begin, std::uint64_t end) const {
    end = std::min(end, length_);
    if (begin >= end) return;
    const auto first = reinterpret_cast<std::uintptr_t>(data_ + begin) & ~(pageSize() - 1);
    const auto last = reinterpret_cast<std::uintptr_t>(data_ + end);
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);  // advice: failure costs memory only
}

std::uint64_t MappedFile::residentBytes() const {
    // The mapping's entries (a replaced page splits it into several) start inside
    // [base, base + length); each entry's "Rss:" line follows its address line.
    std::ifstream smaps("/proc/self/smaps");
    const auto base = reinterpret_cast<std::uintptr_t>(base_);
    std::string line;
    bool inside = false;
    std::uint64_t total = 0;
    while (std::getline(smaps, line)) {
        const auto dash = line.find('-');
        if (dash != std::string::npos && dash > 0 && line.find_first_not_of("0123456789abcdef") == dash) {
            const std::uintptr_t begin = std::stoull(line.substr(0, dash), nullptr, 16);
            inside = begin >= base && begin < base + mappedLength_;
        } else if (inside && line.rfind("Rss:", 0) == 0) {
            total += std::stoull(line.substr(4)) * 1024;
        }
    }
    return total;
}

bool MappedFile::damaged() const {
    return guardSlot_ >= 0 && guardSlots[std::size_t(guardSlot_)].damaged.load(std::memory_order_acquire);
}

void MappedFile::throwIfDamaged() const {
    if (damaged()) throw FormatError(where_ + ": the file was truncated or removed while it was read");
}

const MappedFile* MappedFile::containing(const void* address) {
    const auto at = reinterpret_cast<std::uintptr_t>(address);
    const std::lock_guard<std::mutex> lock(guardMutex);
    for (const GuardSlot& slot : guardSlots) {
        const std::uintptr_t end = slot.end.load(std::memory_order_acquire);
        if (end != 0 && at >= slot.begin.load(std::memory_order_relaxed) && at < end) return slot.file;
    }
    return nullptr;
}

std::uint64_t availableMemoryBytes() {
    std::uint64_t available = std::uint64_t(1) << 30;
    std::ifstream meminfo("/proc/meminfo");
    std::string key, unit;
    std::uint64_t kib = 0;
    bool found = false;
    while (!found && meminfo >> key >> kib >> unit) found = key == "MemAvailable:";
    if (found) {
        available = kib * 1024;
    } else if (const long pages = sysconf(_SC_AVPHYS_PAGES); pages > 0) {
        available = std::uint64_t(pages) * pageSize();
    }
    // What the process's limits leave (ulimit -v, ulimit -d): the address space
    // and the data segment in use are statm's first and sixth fields, in pages.
    std::uint64_t statm[6] = {};
    std::ifstream self("/proc/self/statm");
    for (std::uint64_t& field : statm) self >> field;
    const int resources[2] = {RLIMIT_AS, RLIMIT_DATA};
    const std::uint64_t used[2] = {statm[0] * pageSize(), statm[5] * pageSize()};
    for (int r = 0; r < 2; ++r) {
        rlimit limit{};
        if (getrlimit(resources[r], &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
        const auto cap = std::uint64_t(limit.rlim_cur);
        available = std::min(available, cap > used[r] ? cap - used[r] : 0);
    }
    return available;
}

}  // namespace isotrack
