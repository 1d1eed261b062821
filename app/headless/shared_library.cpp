#include "headless/shared_library.h"

#include <dlfcn.h>

namespace isotrack::headless {

SharedLibrary::SharedLibrary(std::initializer_list<const char*> names) {
    for (const char* candidate : names) {
        handle_ = dlopen(candidate, RTLD_NOW | RTLD_LOCAL);
        if (handle_ != nullptr) {
            name_ = candidate;
            return;
        }
        const char* message = dlerror();
        error_ = message != nullptr ? message : std::string(candidate) + ": cannot be opened";
    }
}

void* SharedLibrary::symbol(const char* symbol) const { return handle_ != nullptr ? dlsym(handle_, symbol) : nullptr; }

}  // namespace isotrack::headless
