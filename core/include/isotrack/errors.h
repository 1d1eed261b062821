#pragma once
// Typed errors thrown by the core. Messages are one line and name the file,
// the field and the offending value, so the command line can print them as-is.
#include <stdexcept>
#include <string>
#include <utility>

namespace isotrack {

// A file that cannot be read or whose contents are malformed.
class FormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A third-party library (GDCM, for DICOM) crashed on a file, in the child
// process isotrack runs it in: the file is damaged or not supported.
class LibraryFailure : public FormatError {
public:
    LibraryFailure(const std::string& message, std::string file) : FormatError(message), file_(std::move(file)) {}
    const std::string& file() const { return file_; }  // the file the library was reading

private:
    std::string file_;
};

// A long operation stopped part-way because its caller asked it to (see
// ContourTreeProgress::cancel); not an error to show.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

// A request the core cannot satisfy (unknown field name, bad size, no surface at a seed...).
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Work whose own arrays (a byte or more per sample) would not fit in the memory
// available, refused before anything is allocated. The message names what and
// the sizes, not the volume's file, which the caller adds.
class WorkingMemoryError : public InputError {
public:
    using InputError::InputError;
};

}  // namespace isotrack
