#pragma once
// A shared library opened at run time, so that isotrack starts (and says what is
// missing) on machines without it. Closed only at exit: GL drivers keep threads
// and atexit handlers that must not outlive their code.
#include <initializer_list>
#include <string>

namespace isotrack::headless {

class SharedLibrary {
public:
    // Opens the first of `names` that loads; ok() is false when none does, and
    // error() then holds the loader's last message.
    explicit SharedLibrary(std::initializer_list<const char*> names);
    SharedLibrary(const SharedLibrary&) = delete;
    SharedLibrary& operator=(const SharedLibrary&) = delete;

    bool ok() const { return handle_ != nullptr; }
    const std::string& error() const { return error_; }
    const std::string& name() const { return name_; }

    // The address of `symbol`, or nullptr.
    void* symbol(const char* symbol) const;

private:
    void* handle_ = nullptr;
    std::string name_, error_;
};

}  // namespace isotrack::headless
