// A plugin library loaded at run time (nl_plugin_load): the one use of the platform's loader.
// POSIX (dlopen) is tested on Linux; the Windows branch (LoadLibraryW) is written but untested
// (docs/platforms.md).
#pragma once

#include <string>

namespace nl::platform {

class DynamicLibrary {
public:
    // Loads the library at `path` with all its symbols resolved now and kept to itself (RTLD_NOW |
    // RTLD_LOCAL: two plugins may define the same names). Throws nl::Error: Io with the loader's reason.
    explicit DynamicLibrary(const std::string& path);
    ~DynamicLibrary();
    DynamicLibrary(DynamicLibrary&& other) noexcept;
    DynamicLibrary& operator=(DynamicLibrary&& other) noexcept;
    DynamicLibrary(const DynamicLibrary&) = delete;
    DynamicLibrary& operator=(const DynamicLibrary&) = delete;

    // The address of the exported function `name`, or null when the library exports none.
    void* function(const char* name) const;

private:
    void* handle_ = nullptr;
};

}  // namespace nl::platform
