#pragma once
// The panel's status line: the last message for the user. Outside a script
// session a message shown is also printed on stderr; a script session keeps
// stderr for its own errors.
#include <cstdio>
#include <string>

namespace isotrack::viewer {

class StatusLine {
public:
    void setQuiet(bool quiet) { quiet_ = quiet; }
    // Shows `message`, and prints it unless quiet.
    void show(const std::string& message) {
        text_ = message;
        if (!quiet_) std::fprintf(stderr, "isotrack: %s\n", message.c_str());
    }
    // Shows `message` only (its details were printed already).
    void set(const std::string& message) { text_ = message; }
    const std::string& text() const { return text_; }

private:
    std::string text_;
    bool quiet_ = false;
};

}  // namespace isotrack::viewer
