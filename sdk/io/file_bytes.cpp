#include "io/file_bytes.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <thread>

#include <sys/stat.h>

#include "util/error.h"

namespace nl {
namespace {

namespace fs = std::filesystem;
using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

const char* kind_of(fs::file_type type) {
    switch (type) {
        case fs::file_type::directory: return "a directory";
        case fs::file_type::block: return "a block device";
        case fs::file_type::character: return "a character device";
        case fs::file_type::socket: return "a socket";
        case fs::file_type::fifo: return "a pipe";
        default: return "a special file";
    }
}

void refuse_unless_readable(const std::string& path, fs::file_type type) {
    if (type != fs::file_type::regular && type != fs::file_type::fifo)
        fail(ErrorCode::Io, "cannot read '", path, "': it is ", kind_of(type), ", not a file");
}

// Opens `path` for reading: a regular file or a pipe (links followed; a pipe waits for its writer).
// Checked before it is opened (a device is never opened) and again on what was opened (the path may
// have been replaced in between).
File open_for_reading(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) fail(ErrorCode::NotFound, "cannot open '", path, "': no such file");
    refuse_unless_readable(path, status.type());
    File file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) fail(ErrorCode::Io, "cannot open '", path, "': ", std::strerror(errno));
    struct stat opened {};
    if (::fstat(::fileno(file.get()), &opened) != 0)
        fail(ErrorCode::Io, "cannot read '", path, "': ", std::strerror(errno));
    refuse_unless_readable(path, S_ISREG(opened.st_mode)    ? fs::file_type::regular
                                 : S_ISFIFO(opened.st_mode) ? fs::file_type::fifo
                                 : S_ISDIR(opened.st_mode)  ? fs::file_type::directory
                                 : S_ISCHR(opened.st_mode)  ? fs::file_type::character
                                 : S_ISBLK(opened.st_mode)  ? fs::file_type::block
                                                            : fs::file_type::socket);
    return file;
}

// Appends up to `limit` more bytes of `file` to `bytes`; returns whether the file ended.
bool read_into(std::FILE* file, const std::string& path, std::string& bytes, uint64_t limit) {
    char buffer[1 << 16];
    while (limit > 0) {
        const size_t count = std::fread(buffer, 1, static_cast<size_t>(std::min<uint64_t>(sizeof buffer, limit)), file);
        bytes.append(buffer, count);
        limit -= count;
        if (count == 0) break;
    }
    if (std::ferror(file)) fail(ErrorCode::Io, "cannot read '", path, "': ", std::strerror(errno));
    return std::feof(file) != 0;
}

// The path a write replaces: `path`, or the file at the end of the chain of symbolic links at it.
fs::path write_target(const std::string& path) {
    fs::path target = path;
    for (int hops = 0;; ++hops) {
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(target, ec);
        if (!fs::is_symlink(status)) {
            if (fs::exists(status) && !fs::is_regular_file(status))
                fail(ErrorCode::Io, "cannot write '", path,
                     "': ", target == fs::path(path) ? "it" : concat("the link leads to ", target.string(), ", which"),
                     " is ", kind_of(status.type()),
                     ", not a file (NavLink writes a file beside it and renames it over)");
            return target;
        }
        if (hops == 40) fail(ErrorCode::Io, "cannot write '", path, "': too many levels of symbolic links");
        const fs::path next = fs::read_symlink(target, ec);
        if (ec) fail(ErrorCode::Io, "cannot write '", path, "': ", ec.message());
        target = next.is_absolute() ? next : target.parent_path() / next;
    }
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
    const File file = open_for_reading(path);
    std::string bytes;
    read_into(file.get(), path, bytes, UINT64_MAX);
    return bytes;
}

std::string read_file_bytes_up_to_declared(const std::string& path, size_t header_bytes, uint64_t max_bytes,
                                           FunctionRef<uint64_t(std::string_view header)> declared, const char* what) {
    const File file = open_for_reading(path);
    std::string bytes;
    if (read_into(file.get(), path, bytes, header_bytes)) return bytes;
    const uint64_t total = declared(bytes);
    if (total <= bytes.size()) return bytes;  // not of the format (its parser says so), or all read
    if (total > max_bytes)
        fail(ErrorCode::Parse, what, ": '", path, "' says it holds ", total, " bytes, more than ", max_bytes,
             " (corrupted)");
    if (read_into(file.get(), path, bytes, total - bytes.size())) return bytes;
    std::string more;
    read_into(file.get(), path, more, 1);
    if (!more.empty())
        fail(ErrorCode::Parse, what, ": '", path, "' goes on past the ", total, " bytes its header says it holds");
    return bytes;
}

void write_file_bytes(const std::string& path, std::string_view bytes) {
    if (path.empty()) fail(ErrorCode::InvalidArgument, "the path is empty");
    const fs::path target = write_target(path);
    // Beside the file, named for this write alone: two writes of one path never share it.
    static std::atomic<uint64_t> writes{0};
    const std::string partial =
        concat(target.string(), ".partial-", std::hash<std::thread::id>{}(std::this_thread::get_id()), "-",
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
    fs::rename(partial, target, renamed);
    if (renamed) {
        std::remove(partial.c_str());
        fail(ErrorCode::Io, "cannot write '", path, "': ", renamed.message());
    }
}

}  // namespace nl
