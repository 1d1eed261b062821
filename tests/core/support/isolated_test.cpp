// Work run in a forked child (support/isolated.h): results of any size come
// back whole, errors keep their type and message, and a child that dies becomes
// a LibraryFailure (inside a LibraryCall) or an IsolatedCrash (outside one).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "support/isolated.h"

using namespace isotrack;
using detail::ReplyReader;
using detail::ReplyWriter;

namespace {

const detail::IsolatedRun kRun{"the test library", "input.dat", 64 << 20};

// The bytes `work` sends, read back `piece` bytes at a time.
std::vector<std::uint8_t> roundTrip(const std::function<void(ReplyWriter&)>& work, std::size_t bytes, std::size_t piece,
                                    const detail::IsolatedRun& run = kRun) {
    std::vector<std::uint8_t> got(bytes);
    detail::runIsolated(run, work, [&](ReplyReader& in) {
        for (std::size_t at = 0; at < bytes; at += piece) in.read(got.data() + at, std::min(piece, bytes - at));
    });
    return got;
}

std::vector<std::uint8_t> pattern(std::size_t n) {
    std::vector<std::uint8_t> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = std::uint8_t(k * 2654435761u >> 13);
    return v;
}

}  // namespace

TEST_CASE("an isolated result many times a pipe buffer comes back byte for byte", "[core][isolated]") {
    const std::vector<std::uint8_t> sent = pattern(9 << 20);  // a pipe holds 64 KiB
    const auto work = [&](ReplyWriter& out) {
        out.write(sent.data(), 1000);  // frames of any size...
        out.write(sent.data() + 1000, sent.size() - 1000);
    };
    CHECK(roundTrip(work, sent.size(), 3 << 20) == sent);  // ...read in pieces of another
    CHECK(roundTrip(work, sent.size(), 777) == sent);
}

TEST_CASE("an isolated error keeps its type and message", "[core][isolated]") {
    const auto read = [](ReplyReader& in) {
        char c;
        in.read(&c, 1);
    };
    CHECK_THROWS_MATCHES(detail::runIsolated(
                             kRun, [](ReplyWriter&) { throw FormatError("a.dcm: bad length"); }, read),
                         FormatError, Catch::Message("a.dcm: bad length"));
    CHECK_THROWS_MATCHES(detail::runIsolated(
                             kRun, [](ReplyWriter&) { throw InputError("no series \"3\""); }, read),
                         InputError, Catch::Message("no series \"3\""));
    CHECK_THROWS_MATCHES(detail::runIsolated(
                             kRun, [](ReplyWriter&) { throw std::logic_error("odd"); }, read),
                         std::runtime_error, Catch::Message("odd"));
    // After some data, too.
    const auto late = [](ReplyWriter& out) {
        out.write("ab", 2);
        throw InputError("late");
    };
    CHECK_THROWS_MATCHES(detail::runIsolated(kRun, late,
                                             [](ReplyReader& in) {
                                                 char c[4];
                                                 in.read(c, 4);
                                             }),
                         InputError, Catch::Message("late"));
}

TEST_CASE("a child that dies inside the library is a LibraryFailure naming the file", "[core][isolated]") {
    const auto read = [](ReplyReader& in) {
        char c;
        in.read(&c, 1);
    };
    const auto dies = [](int signal) {
        return [signal](ReplyWriter&) {
            detail::noteSubject("slices/0042.dcm");
            const detail::LibraryCall call;
            if (signal == SIGABRT) std::abort();
            std::raise(signal);
        };
    };
    CHECK_THROWS_MATCHES(detail::runIsolated(kRun, dies(SIGABRT), read), LibraryFailure,
                         Catch::Message("slices/0042.dcm: the test library failed on it (it crashed: Aborted); the "
                                        "file is damaged or not supported"));
    CHECK_THROWS_MATCHES(detail::runIsolated(kRun, dies(SIGSEGV), read), LibraryFailure,
                         Catch::Message("slices/0042.dcm: the test library failed on it (it crashed: Segmentation "
                                        "fault); the file is damaged or not supported"));
}

TEST_CASE("a child that dies outside the library is an IsolatedCrash, not a FormatError", "[core][isolated]") {
    const auto work = [](ReplyWriter&) {
        { const detail::LibraryCall call; }
        std::signal(SIGSEGV, SIG_DFL);  // Catch's own handler would report a failure from the child
        std::raise(SIGSEGV);
    };
    bool crash = false;
    try {
        detail::runIsolated(kRun, work, [](ReplyReader& in) {
            char c;
            in.read(&c, 1);
        });
    } catch (const FormatError&) {
    } catch (const detail::IsolatedCrash& e) {
        crash = true;
        // (under a sanitizer its handler reports the fault and exits instead)
        CHECK_THAT(e.what(), Catch::StartsWith("input.dat: isotrack's reader failed in its child process ("));
    }
    CHECK(crash);
}

TEST_CASE("a reply cut short, or longer than allowed, is an error", "[core][isolated]") {
    const auto cut = [](ReplyWriter& out) {
        const detail::LibraryCall call;
        out.write("abc", 3);
        ::_exit(0);
    };
    const auto readTen = [](ReplyReader& in) {
        char c[10];
        in.read(c, 10);
    };
    CHECK_THROWS_MATCHES(detail::runIsolated(kRun, cut, readTen), LibraryFailure,
                         Catch::Message("input.dat: the test library failed on it (its reply was cut short); the "
                                        "file is damaged or not supported"));
    const detail::IsolatedRun small{"the test library", "input.dat", 1000};
    const std::vector<std::uint8_t> big = pattern(5000);
    const auto work = [&](ReplyWriter& out) { out.write(big.data(), big.size()); };
    CHECK_THROWS_WITH(roundTrip(work, big.size(), 100, small),
                      "input.dat: the test library: its reply exceeds 1000 bytes");
    // More than the reader takes.
    CHECK_THROWS_WITH(roundTrip(work, 10, 10), "input.dat: the test library: its reply holds more than was read");
}

TEST_CASE("isolated runs leave no child behind and can run again and again", "[core][isolated]") {
    for (int k = 0; k < 20; ++k) {
        const std::vector<std::uint8_t> sent = pattern(std::size_t(k) * 1000 + 1);
        CHECK(roundTrip([&](ReplyWriter& out) { out.write(sent.data(), sent.size()); }, sent.size(), 4096) == sent);
    }
    CHECK(::waitpid(-1, nullptr, WNOHANG) < 0);  // no child left to reap
}
