#pragma once
// Running a third-party library where its crash cannot take the process down.
//
// runIsolated forks; the child runs `work`, which streams its result through a
// ReplyWriter into a pipe, and leaves with _exit; the parent reads the reply
// with `read` as it arrives (so a result larger than a pipe buffer never
// blocks), in bounded pieces, then reaps the child. The reply is a sequence of
// frames (a kind byte, a 64-bit length, the bytes): data, the end, or an error.
// An exception the child's work throws comes back as the same type with the
// same message (FormatError, InputError; anything else as std::runtime_error).
//
// While the child is inside the library it wraps its calls in a LibraryCall
// and names the file it is reading with noteSubject; both land in a small
// shared anonymous mapping the parent reads after the child is gone. A child
// that dies inside a LibraryCall (a signal, an exit without its end frame, a
// reply cut short) becomes a LibraryFailure naming that file: the file is
// damaged or not supported. A child that dies anywhere else is isotrack's own
// bug and becomes an IsolatedCrash, which no loader catches, so fuzzers and
// tests still see it.
//
// The fork rule. A forked child holds only the thread that forked; a lock that
// another thread of the parent held at that moment stays locked in the child
// for ever. So the child's work may use only what no other thread can be
// holding: the C library (glibc makes malloc and stdio safe across fork), the
// file system, and library state set up before the fork (GDCM's dictionaries
// are loaded in the parent first). It must not run parallelFor or anything on
// the WorkerPool (its threads do not exist in the child), nor take a mutex of
// isotrack's. isolated runs are serialised by a mutex of their own in the
// parent, so that no child inherits another's pipe.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "isotrack/errors.h"

namespace isotrack::detail {

// The child of runIsolated died outside a LibraryCall: a bug in isotrack.
class IsolatedCrash : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The child's side of the pipe.
class ReplyWriter {
public:
    explicit ReplyWriter(int fd) : fd_(fd) {}
    void write(const void* data, std::size_t bytes);

private:
    int fd_;
};

// The parent's side: read() fills exactly `bytes` or throws (the child's own
// error, LibraryFailure, IsolatedCrash, or FormatError for a reply over the
// limit).
class ReplyReader {
public:
    virtual ~ReplyReader() = default;
    virtual void read(void* out, std::size_t bytes) = 0;
};

struct IsolatedRun {
    std::string library;  // "the DICOM library", for messages
    std::string subject;  // the file named when the child noted none
    std::uint64_t maxReplyBytes = 0;
};

// Runs `work` in a child and `read` on its reply here. `read` must consume the
// whole reply; a child that sends more, or more than maxReplyBytes, is refused.
void runIsolated(const IsolatedRun& run, const std::function<void(ReplyWriter&)>& work,
                 const std::function<void(ReplyReader&)>& read);

// In a child of runIsolated: the file the library is about to read. Elsewhere
// nothing.
void noteSubject(const std::string& path);

// In a child of runIsolated, marks a call into the library: a death inside it is
// the library's (LibraryFailure), and the fatal signals (abort, segmentation
// fault, bus error, illegal instruction, arithmetic) take their default action,
// so that no crash handler (a sanitizer's, a fuzzer's) reports them in the
// child; the library's stderr goes to /dev/null, so that an assertion's text
// does not add a line to isotrack's one-line error. Elsewhere nothing.
class LibraryCall {
public:
    LibraryCall();
    ~LibraryCall();
    LibraryCall(const LibraryCall&) = delete;
    LibraryCall& operator=(const LibraryCall&) = delete;
};

}  // namespace isotrack::detail
