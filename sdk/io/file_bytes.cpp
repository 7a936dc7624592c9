#include "io/file_bytes.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <thread>

#include "util/error.h"

namespace nl {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

std::string read_file_bytes(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) fail(ErrorCode::NotFound, "cannot open '", path, "': no such file");
    if (std::filesystem::is_directory(status)) fail(ErrorCode::Io, "cannot read '", path, "': it is a directory");
    const File file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) fail(ErrorCode::Io, "cannot open '", path, "': ", std::strerror(errno));
    std::string bytes;
    char buffer[1 << 16];
    size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) bytes.append(buffer, count);
    if (std::ferror(file.get())) fail(ErrorCode::Io, "cannot read '", path, "': ", std::strerror(errno));
    return bytes;
}

void write_file_bytes(const std::string& path, std::string_view bytes) {
    if (path.empty()) fail(ErrorCode::InvalidArgument, "the path is empty");
    // Beside the file, named for this write alone: two writes of one path never share it.
    static std::atomic<uint64_t> writes{0};
    const std::string partial = concat(path, ".partial-", std::hash<std::thread::id>{}(std::this_thread::get_id()), "-",
                                       writes.fetch_add(1));
    {
        File file(std::fopen(partial.c_str(), "wb"), &std::fclose);
        if (!file) fail(ErrorCode::Io, "cannot write '", path, "': ", std::strerror(errno));
        bool written = std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
        written = std::fclose(file.release()) == 0 && written;  // a failed close may be the failed write
        if (!written) {
            const int why = errno;
            std::remove(partial.c_str());
            fail(ErrorCode::Io, "cannot write '", path, "': ", std::strerror(why));
        }
    }
    // std::filesystem::rename replaces an existing file on every platform; std::rename does not on
    // Windows, where the second save of a file would fail.
    std::error_code renamed;
    std::filesystem::rename(partial, path, renamed);
    if (renamed) {
        std::remove(partial.c_str());
        fail(ErrorCode::Io, "cannot write '", path, "': ", renamed.message());
    }
}

}  // namespace nl
