// A library run in a forked child: see isolated.h.
#include "support/isolated.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <new>

// A sanitizer's hook run before it exits on a report; libFuzzer uses it to save
// the input. The child clears it: its parent reports what matters.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace isotrack::detail {

namespace {

enum Frame : std::uint8_t { kData = 'D', kEnd = 'E', kFormat = 'F', kInput = 'I', kOther = 'X' };

// What the child tells its parent outside the pipe; MAP_SHARED, so writes in
// the child are seen by the parent even when the child dies.
struct Notes {
    volatile int libraryDepth;
    char subject[4096];
};

Notes* childNotes = nullptr;  // set in the child only
int savedStderr = -1;         // the child's stderr, while a LibraryCall sends it to /dev/null

constexpr std::array<int, 6> kFatalSignals{SIGABRT, SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGTRAP};
std::array<struct sigaction, kFatalSignals.size()> savedActions;

void writeAll(int fd, const void* data, std::size_t bytes) {
    const char* p = static_cast<const char*>(data);
    while (bytes > 0) {
        const ssize_t n = ::write(fd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ::_exit(3);  // the parent stopped reading
        p += n;
        bytes -= std::size_t(n);
    }
}

void writeFrame(int fd, Frame kind, const void* data, std::uint64_t bytes) {
    unsigned char head[9];
    head[0] = kind;
    std::memcpy(head + 1, &bytes, 8);
    writeAll(fd, head, sizeof head);
    writeAll(fd, data, bytes);
}

[[noreturn]] void childMain(int fd, const std::function<void(ReplyWriter&)>& work) {
#ifdef __linux__
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive a parent that was killed
#endif
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(nullptr);
    Frame kind = kEnd;
    std::string message;
    try {
        ReplyWriter writer(fd);
        work(writer);
    } catch (const FormatError& e) {
        kind = kFormat, message = e.what();
    } catch (const InputError& e) {
        kind = kInput, message = e.what();
    } catch (const std::exception& e) {
        kind = kOther, message = e.what();
    } catch (...) {
        kind = kOther, message = "an unknown exception";
    }
    writeFrame(fd, kind, message.data(), message.size());
    ::_exit(0);  // no atexit handlers, no stdio flushes: they belong to the parent
}

// Reads frames from the child; remembers why it stopped when the reply ends early.
class PipeReader : public ReplyReader {
public:
    PipeReader(int fd, std::uint64_t limit, std::string prefix) : fd_(fd), limit_(limit), prefix_(std::move(prefix)) {}

    void read(void* out, std::size_t bytes) override {
        char* p = static_cast<char*>(out);
        while (bytes > 0) {
            if (left_ == 0) nextFrame(false);
            const std::size_t n = std::size_t(std::min<std::uint64_t>(left_, bytes));
            readRaw(p, n);
            p += n, bytes -= n, left_ -= n;
        }
    }
    // After `read` is done: the end frame, or the child's error.
    void finish() {
        if (left_ != 0) throw FormatError(prefix_ + "its reply holds more than was read");
        nextFrame(true);
    }
    bool cut() const { return cut_; }
    Frame errorKind() const { return errorKind_; }
    const std::string& errorMessage() const { return errorMessage_; }

    struct Stopped {};  // the reply ended early or carried an error; see the fields

private:
    void readRaw(void* out, std::size_t bytes) {
        char* p = static_cast<char*>(out);
        while (bytes > 0) {
            const ssize_t n = ::read(fd_, p, bytes);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                cut_ = true;
                throw Stopped{};
            }
            p += n, bytes -= std::size_t(n);
        }
    }
    void nextFrame(bool endExpected) {
        unsigned char head[9];
        readRaw(head, sizeof head);
        std::uint64_t length = 0;
        std::memcpy(&length, head + 1, 8);
        if (length > limit_ - std::min(limit_, total_))
            throw FormatError(prefix_ + "its reply exceeds " + std::to_string(limit_) + " bytes");
        total_ += length;
        if (head[0] == kData) {
            if (endExpected) throw FormatError(prefix_ + "its reply holds more than was read");
            left_ = length;
            return;
        }
        if (head[0] != kEnd && head[0] != kFormat && head[0] != kInput && head[0] != kOther)
            throw FormatError(prefix_ + "its reply is garbled");
        std::string message(std::size_t(length), '\0');
        readRaw(message.data(), message.size());
        if (head[0] == kEnd && endExpected) return;
        errorKind_ = Frame(head[0]);
        errorMessage_ = message;
        throw Stopped{};
    }

    int fd_;
    std::uint64_t limit_, total_ = 0, left_ = 0;
    std::string prefix_;
    bool cut_ = false;
    Frame errorKind_ = kEnd;
    std::string errorMessage_;
};

// How the child ended, in words: "it crashed: Aborted".
std::string howItEnded(int status, bool cut) {
    if (WIFSIGNALED(status)) {
        const char* name = ::strsignal(WTERMSIG(status));
        return std::string("it crashed: ") + (name ? name : "signal " + std::to_string(WTERMSIG(status)));
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        return "it exited with status " + std::to_string(WEXITSTATUS(status));
    return cut ? "its reply was cut short" : "it ended without replying";
}

int reap(pid_t pid, bool kill) {
    if (kill) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

[[noreturn]] void rethrowChildError(Frame kind, const std::string& message) {
    if (kind == kFormat) throw FormatError(message);
    if (kind == kInput) throw InputError(message);
    throw std::runtime_error(message);
}

}  // namespace

void ReplyWriter::write(const void* data, std::size_t bytes) {
    if (bytes > 0) writeFrame(fd_, kData, data, bytes);
}

void noteSubject(const std::string& path) {
    if (!childNotes) return;
    const std::size_t n = std::min(path.size(), sizeof childNotes->subject - 1);
    std::memcpy(childNotes->subject, path.data(), n);
    childNotes->subject[n] = '\0';
}

LibraryCall::LibraryCall() {
    if (!childNotes) return;
    if (childNotes->libraryDepth++ > 0) return;
    // The library's own last words (an assertion's text) would be a second line.
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
        savedStderr = ::dup(2);
        ::dup2(null, 2);
        ::close(null);
    }
    struct sigaction plain {};
    plain.sa_handler = SIG_DFL;
    sigemptyset(&plain.sa_mask);
    for (std::size_t s = 0; s < kFatalSignals.size(); ++s) ::sigaction(kFatalSignals[s], &plain, &savedActions[s]);
}

LibraryCall::~LibraryCall() {
    if (!childNotes) return;
    if (--childNotes->libraryDepth > 0) return;
    for (std::size_t s = 0; s < kFatalSignals.size(); ++s) ::sigaction(kFatalSignals[s], &savedActions[s], nullptr);
    if (savedStderr >= 0) {
        ::dup2(savedStderr, 2);
        ::close(savedStderr);
        savedStderr = -1;
    }
}

void runIsolated(const IsolatedRun& run, const std::function<void(ReplyWriter&)>& work,
                 const std::function<void(ReplyReader&)>& read) {
    static std::mutex oneAtATime;
    const std::lock_guard<std::mutex> lock(oneAtATime);
    void* shared = ::mmap(nullptr, sizeof(Notes), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED)
        throw FormatError(run.subject + ": cannot map memory for " + run.library + ": " + std::strerror(errno));
    Notes* notes = new (shared) Notes{};
    struct Unmap {
        void* p;
        ~Unmap() { ::munmap(p, sizeof(Notes)); }
    } unmap{shared};
    int fds[2];
    if (::pipe(fds) != 0)
        throw FormatError(run.subject + ": cannot open a pipe for " + run.library + ": " + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int error = errno;
        ::close(fds[0]), ::close(fds[1]);
        throw FormatError(run.subject + ": cannot start a process for " + run.library + ": " + std::strerror(error));
    }
    if (pid == 0) {
        ::close(fds[0]);
        childNotes = notes;
        childMain(fds[1], work);
    }
    ::close(fds[1]);
    PipeReader reader(fds[0], run.maxReplyBytes, run.subject + ": " + run.library + ": ");
    bool stopped = false;
    try {
        read(reader);
        reader.finish();
    } catch (const PipeReader::Stopped&) {
        stopped = true;
    } catch (...) {
        ::close(fds[0]);
        reap(pid, true);
        throw;
    }
    ::close(fds[0]);
    const int status = reap(pid, false);  // it has replied, or closed its end, or died
    if (!stopped && WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    if (stopped && !reader.cut() && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        rethrowChildError(reader.errorKind(), reader.errorMessage());
    const std::string subject = notes->subject[0] ? std::string(notes->subject) : run.subject;
    const std::string how = howItEnded(status, reader.cut());
    if (notes->libraryDepth > 0)
        throw LibraryFailure(
            subject + ": " + run.library + " failed on it (" + how + "); the file is damaged or not supported",
            subject);
    throw IsolatedCrash(subject + ": isotrack's reader failed in its child process (" + how + ")");
}

}  // namespace isotrack::detail
