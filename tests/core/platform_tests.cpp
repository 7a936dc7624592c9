// sdk/platform/: the plugin loader against a real plugin module (the climb plugin) and a file that is
// not one. The writer-preferring lock is exercised by every level test and the soaks.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "core_errors.h"
#include "platform/dynamic_library.h"

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

}  // namespace
}  // namespace nl
