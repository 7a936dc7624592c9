// Files read and written whole (sdk/io/file_bytes.h) and the navmesh file's bounded read: links are
// written through, special files are refused without being replaced or read for ever, and a stream
// is read no further than the navmesh file's header says it goes.
#include <doctest/doctest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "core_errors.h"
#include "io/file_bytes.h"
#include "io/navmesh_file.h"
#include "navmesh/navmesh_builder.h"

namespace nl {
namespace {

namespace fs = std::filesystem;

struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() / ("navlink-file-bytes-" + std::to_string(::getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    std::string operator/(const char* name) const { return (path / name).string(); }
};

// A small valid navmesh file: one square.
std::string square_file() {
    NavMeshInput in;
    for (const auto& [x, z] : {std::pair{0.0f, 0.0f}, {0.0f, 4.0f}, {4.0f, 4.0f}, {4.0f, 0.0f}}) {
        in.indices.push_back(uint32_t(in.vertices.size()));
        in.vertices.emplace_back(x, 0.0f, z);
    }
    in.polygon_sizes.push_back(4);
    const std::vector<uint8_t> bytes = write_navmesh_file(*build_navmesh(in), {}, NavMeshProvenance{}, false);
    return std::string(bytes.begin(), bytes.end());
}

TEST_CASE("a write through a symbolic link writes the file it leads to, and the link stays") {
    TempFolder tmp;
    write_file_bytes(tmp / "real.nlnav", "old");
    fs::create_symlink("real.nlnav", tmp / "link.nlnav");         // relative, as ln -s makes it
    fs::create_symlink(tmp / "link.nlnav", tmp / "chain.nlnav");  // absolute, to another link
    write_file_bytes(tmp / "chain.nlnav", "new bytes");
    CHECK(fs::is_symlink(tmp / "chain.nlnav"));
    CHECK(fs::is_symlink(tmp / "link.nlnav"));
    CHECK(read_file_bytes(tmp / "real.nlnav") == "new bytes");
    // A link to nothing yet: the file is made where it leads.
    fs::create_symlink("later.nlnav", tmp / "dangling.nlnav");
    write_file_bytes(tmp / "dangling.nlnav", "made");
    CHECK(fs::is_symlink(tmp / "dangling.nlnav"));
    CHECK(read_file_bytes(tmp / "later.nlnav") == "made");
    // A loop of links is refused.
    fs::create_symlink("loop-b", tmp / "loop-a");
    fs::create_symlink("loop-a", tmp / "loop-b");
    std::string message;
    CHECK(test::code_of([&] { write_file_bytes(tmp / "loop-a", "x"); }, &message) == ErrorCode::Io);
    CHECK(message.find("symbolic links") != std::string::npos);
}

TEST_CASE("a device is neither replaced by a write nor read for ever") {
    REQUIRE(fs::is_character_file("/dev/null"));
    std::string message;
    CHECK(test::code_of([&] { write_file_bytes("/dev/null", "x"); }, &message) == ErrorCode::Io);
    CHECK(message.find("character device") != std::string::npos);
    CHECK(fs::is_character_file("/dev/null"));  // still the device
    TempFolder tmp;
    fs::create_symlink("/dev/null", tmp / "null.nlnav");
    CHECK(test::code_of([&] { write_file_bytes(tmp / "null.nlnav", "x"); }, &message) == ErrorCode::Io);
    CHECK(message.find("/dev/null") != std::string::npos);
    CHECK(fs::is_character_file("/dev/null"));

    CHECK(test::code_of([&] { read_navmesh_file_bytes("/dev/zero"); }, &message) == ErrorCode::Io);
    CHECK(message.find("character device") != std::string::npos);
    CHECK(test::code_of([&] { read_file_bytes("/dev/zero"); }) == ErrorCode::Io);
    CHECK(test::code_of([&] { read_file_bytes(tmp.path.string()); }, &message) == ErrorCode::Io);
    CHECK(message.find("a directory") != std::string::npos);
}

TEST_CASE("a navmesh file is read from a pipe no further than its header says, whatever follows") {
    // SIGPIPE would end the test when the reader closes the pipe on the endless writer.
    const auto previous = std::signal(SIGPIPE, SIG_IGN);
    TempFolder tmp;
    const std::string file = square_file();
    const std::string pipe = tmp / "stream.nlnav";
    // `prefix`, then bytes for ever if `endless`, until the reader closes the pipe. What the read
    // gives, or its failure's message.
    auto read_from_writer = [&](const std::string& prefix, bool endless, std::string& message) {
        message.clear();
        REQUIRE(::mkfifo(pipe.c_str(), 0600) == 0);
        std::thread writer([&] {
            // Opened without waiting (ENXIO until the reader has it open), for at most 30 s: a reader
            // that never opens the pipe fails the test instead of hanging it.
            int fd = -1;
            for (int tries = 0; fd < 0 && tries < 30000; ++tries) {
                fd = ::open(pipe.c_str(), O_WRONLY | O_NONBLOCK);
                if (fd < 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            if (fd < 0) return;
            ::fcntl(fd, F_SETFL, 0);  // blocking writes from here on
            auto write_all = [&](const std::string& bytes) {
                return ::write(fd, bytes.data(), bytes.size()) == ssize_t(bytes.size());
            };
            bool open = write_all(prefix);
            const std::string more(4096, 'x');
            while (open && endless) open = write_all(more);
            ::close(fd);
        });
        std::string bytes;
        try {
            bytes = read_navmesh_file_bytes(pipe);
        } catch (const Error& e) {
            message = e.what();
        }
        writer.join();
        fs::remove(pipe);
        return bytes;
    };
    std::string message;
    // The file alone: all of it, and it reads back.
    const std::string whole = read_from_writer(file, false, message);
    CHECK(message.empty());
    CHECK(whole == file);
    CHECK(
        read_navmesh_file(reinterpret_cast<const uint8_t*>(whole.data()), whole.size()).navmesh.polygon_sizes.size() ==
        1);
    // The file, then bytes without end: refused once one byte past it is read.
    read_from_writer(file, true, message);
    CHECK(message.find("goes on past the " + std::to_string(file.size()) + " bytes its header says") !=
          std::string::npos);
    // A header that says the file is larger than any navmesh file, then bytes without end: refused
    // before anything past the header is read.
    std::string forged = file.substr(0, kNavMeshFileHeaderBytes);
    const uint64_t huge = uint64_t(1) << 40;
    std::memcpy(&forged[16], &huge, sizeof huge);  // the file size (little-endian on every tested platform)
    read_from_writer(forged, true, message);
    CHECK(message.find("says it holds " + std::to_string(huge) + " bytes, more than") != std::string::npos);
    // Not a navmesh file at all, without end: the header's bytes alone, which its reader refuses.
    const std::string other = read_from_writer("not a navmesh file, and more", true, message);
    CHECK(message.empty());
    CHECK(other.size() == kNavMeshFileHeaderBytes);
    CHECK(test::code_of([&] { read_navmesh_file(reinterpret_cast<const uint8_t*>(other.data()), other.size()); }) ==
          ErrorCode::VersionMismatch);
    std::signal(SIGPIPE, previous);
}

}  // namespace
}  // namespace nl
