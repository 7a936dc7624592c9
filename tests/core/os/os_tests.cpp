// sdk/os/: the plugin loader against a real plugin module (the climb plugin) and a file that is
// not one; the lock's refusal to be taken again by its holder. The writer-preferring order is exercised
// by every level test and the soaks.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "core_errors.h"
#include "os/dynamic_library.h"
#include "os/shared_mutex.h"

namespace nl {
namespace {

TEST_CASE("platform: a plugin module loads and gives its entry function, and null for a name it lacks") {
    const platform::DynamicLibrary library(CLIMB_PLUGIN_PATH);
    CHECK(library.function("nl_plugin_entry") != nullptr);  // NL_PLUGIN_ENTRY_SYMBOL (plugin.h)
    CHECK(library.function("nl_no_such_function") == nullptr);
}

TEST_CASE("platform: a file that is not a library fails to load with Io, naming it") {
    const std::string path = (std::filesystem::temp_directory_path() / "navlink-not-a-library.so").string();
    std::FILE* file = std::fopen(path.c_str(), "w");
    REQUIRE(file);
    std::fputs("not a library\n", file);
    std::fclose(file);
    std::string message;
    CHECK(test::code_of([&] { platform::DynamicLibrary library(path); }, &message) == ErrorCode::Io);
    CHECK(message.find(path) != std::string::npos);
    std::filesystem::remove(path);
}

TEST_CASE("platform: a moved library is unloaded once, by its new owner") {
    platform::DynamicLibrary first(CLIMB_PLUGIN_PATH);
    platform::DynamicLibrary second = std::move(first);
    CHECK(second.function("nl_plugin_entry") != nullptr);
}

TEST_CASE("platform: a lock taken again by the thread that holds it is refused, named, and stays whole") {
    SharedMutex mutex("the things");
    // Each way of taking it again: glibc deadlocks on two of them and fails the third unseen.
    for (const bool outer_exclusive : {false, true}) {
        for (const bool inner_exclusive : {false, true}) {
            CAPTURE(outer_exclusive);
            CAPTURE(inner_exclusive);
            outer_exclusive ? mutex.lock() : mutex.lock_shared();
            CHECK(mutex.held_by_this_thread());
            std::string message;
            CHECK(test::code_of([&] { inner_exclusive ? mutex.lock() : mutex.lock_shared(); }, &message) ==
                  ErrorCode::Internal);
            CHECK(message.find("holds the lock of the things") != std::string::npos);
            CHECK(mutex.held_by_this_thread());  // the refusal let go of nothing
            outer_exclusive ? mutex.unlock() : mutex.unlock_shared();
            CHECK_FALSE(mutex.held_by_this_thread());
            // Whole: another thread takes it for writing, then this one again.
            std::thread([&] {
                mutex.lock();
                mutex.unlock();
            }).join();
            mutex.lock();
            mutex.unlock();
        }
    }
    // Two locks nest as before; each is refused only to its own holder.
    SharedMutex other("the others");
    std::shared_lock a(mutex);
    std::unique_lock b(other);
    CHECK(mutex.held_by_this_thread());
    CHECK(other.held_by_this_thread());
}

}  // namespace
}  // namespace nl
