#include "os/dynamic_library.h"

#include <utility>

#include "util/error.h"

#if defined(_WIN32)
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <filesystem>
#else
#include <dlfcn.h>
#endif

namespace nl::platform {

#if defined(_WIN32)  // untested (docs/platforms.md)

DynamicLibrary::DynamicLibrary(const std::string& path) {
    // The path is UTF-8 as everywhere in the C ABI; the wide call takes any file name.
    const std::wstring wide = std::filesystem::u8path(path).wstring();
    handle_ = LoadLibraryW(wide.c_str());
    if (!handle_)
        fail(ErrorCode::Io, "cannot load '", path, "': Windows error ", static_cast<unsigned long>(GetLastError()));
}

DynamicLibrary::~DynamicLibrary() {
    if (handle_) FreeLibrary(static_cast<HMODULE>(handle_));
}

void* DynamicLibrary::function(const char* name) const {
    return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(handle_), name));
}

#else

DynamicLibrary::DynamicLibrary(const std::string& path) {
    handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        fail(ErrorCode::Io, "cannot load '", path, "': ", why ? why : "unknown loader error");
    }
}

DynamicLibrary::~DynamicLibrary() {
    if (handle_) dlclose(handle_);
}

void* DynamicLibrary::function(const char* name) const { return dlsym(handle_, name); }

#endif

DynamicLibrary::DynamicLibrary(DynamicLibrary&& other) noexcept : handle_(std::exchange(other.handle_, nullptr)) {}

DynamicLibrary& DynamicLibrary::operator=(DynamicLibrary&& other) noexcept {
    std::swap(handle_, other.handle_);
    return *this;
}

}  // namespace nl::platform
