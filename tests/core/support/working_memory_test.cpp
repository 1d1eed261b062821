// Work that keeps a few bytes per sample is refused before it allocates when
// they do not fit: the snap table's sample states and the contour tree's
// build, on views of reserved, never-touched address space; and
// availableMemoryBytes honours the process's address-space limit (ulimit -v).
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <string>

#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/mapped_file.h"
#include "isotrack/volume.h"
#include "support/working_memory.h"

using namespace isotrack;

namespace {

// Address space for `bytes` of samples, reading as zeros, never committed.
class Reserved {
public:
    explicit Reserved(std::size_t bytes) : bytes_(bytes) {
        base_ = mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        REQUIRE(base_ != MAP_FAILED);
    }
    ~Reserved() { munmap(base_, bytes_); }
    Reserved(const Reserved&) = delete;
    Reserved& operator=(const Reserved&) = delete;
    const void* data() const { return base_; }

private:
    void* base_;
    std::size_t bytes_;
};

// Lowers the soft address-space limit to what the process uses now plus
// `spare` bytes, and puts it back on leaving.
class AddressLimit {
public:
    explicit AddressLimit(std::uint64_t spare) {
        REQUIRE(getrlimit(RLIMIT_AS, &before_) == 0);
        std::uint64_t pages = 0;
        FILE* statm = std::fopen("/proc/self/statm", "r");
        REQUIRE(statm != nullptr);
        REQUIRE(std::fscanf(statm, "%lu", &pages) == 1);
        std::fclose(statm);
        rlimit lower = before_;
        lower.rlim_cur = rlim_t(pages * std::uint64_t(sysconf(_SC_PAGESIZE)) + spare);
        REQUIRE(setrlimit(RLIMIT_AS, &lower) == 0);
    }
    ~AddressLimit() { setrlimit(RLIMIT_AS, &before_); }
    AddressLimit(const AddressLimit&) = delete;
    AddressLimit& operator=(const AddressLimit&) = delete;

private:
    rlimit before_{};
};

}  // namespace

TEST_CASE("requireWorkingMemory refuses work that does not fit, naming it and the sizes", "[working-memory]") {
    const Reserved samples(std::size_t(1) << 20);
    const Volume volume = Volume::view({128, 128, 64}, ScalarType::UInt8, samples.data());  // 2^20 samples
    CHECK_NOTHROW(detail::requireWorkingMemory(volume, 3, "the states", std::uint64_t(3) << 20));
    CHECK_THROWS_AS(detail::requireWorkingMemory(volume, 3, "the states", (std::uint64_t(3) << 20) - 1),
                    WorkingMemoryError);
    try {
        detail::requireWorkingMemory(volume, 3, "the states", std::uint64_t(2) << 20);
        FAIL("3 MiB of states fit in 2 MiB");
    } catch (const WorkingMemoryError& e) {
        CHECK(std::string(e.what()) ==
              "the states, 3 bytes a sample: 128 x 128 x 64 samples need 3.0 MiB, more than the 2.0 MiB of memory "
              "available");
    }
}

// The address-space limit cases lower RLIMIT_AS to what the process maps now:
// under AddressSanitizer, whose allocator maps as it goes beside terabytes of
// shadow, that limit would fail the sanitizer itself, so they run in the
// normal build only (tests/cli/mapped_volumes.sh checks the same through
// `ulimit -v`).
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
TEST_CASE("availableMemoryBytes stays within the address-space limit", "[working-memory]") {
    const std::uint64_t spare = std::uint64_t(64) << 20;
    const AddressLimit limit(spare);
    const std::uint64_t available = availableMemoryBytes();
    CHECK(available <= spare);
    CHECK(available > spare / 2);  // what reading /proc took is small
}

TEST_CASE("the snap table and the contour tree refuse volumes whose working arrays do not fit", "[working-memory]") {
    // 1290^3 one-byte samples (2.1 GB of address space), just under the
    // contour tree's 2^31: its build needs 51.5 GB, the snap states 6.4 GB;
    // the limit leaves them 256 MiB. Nothing is read or allocated: each
    // refuses before its first sample.
    const Dims dims{1290, 1290, 1290};
    const Reserved samples{std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2])};
    const Volume volume = Volume::view(dims, ScalarType::UInt8, samples.data());
    const AddressLimit limit(std::uint64_t(256) << 20);
    ExtractRequest snap;
    snap.table = TableKind::Snap;
    snap.iso = 0.5;
    CHECK_THROWS_MATCHES(extract(volume, snap), WorkingMemoryError,
                         Catch::Matchers::Predicate<WorkingMemoryError>([](const WorkingMemoryError& e) {
                             return std::string(e.what()).rfind(
                                        "the snap table's sample states, 3 bytes a sample: "
                                        "1290 x 1290 x 1290 samples need 6.0 GiB",
                                        0) == 0;
                         }));
    CHECK_THROWS_MATCHES(computeContourTree(volume, 2), WorkingMemoryError,
                         Catch::Matchers::Predicate<WorkingMemoryError>([](const WorkingMemoryError& e) {
                             return std::string(e.what()).rfind(
                                        "the contour tree's build, 24 bytes a sample: "
                                        "1290 x 1290 x 1290 samples need 48.0 GiB",
                                        0) == 0;
                         }));
}
#endif
