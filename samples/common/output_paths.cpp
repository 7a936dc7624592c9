#include "output_paths.h"

#include <filesystem>
#include <system_error>
#include <unistd.h>

#include "sample_error.h"

namespace nl::samples {
namespace {

namespace fs = std::filesystem;

void require_writable_folder(const fs::path& folder, const std::string& for_what) {
    std::error_code ec;
    if (!fs::exists(folder, ec))
        throw SampleError("cannot write '" + for_what + "': the folder '" + folder.string() + "' does not exist");
    if (!fs::is_directory(folder, ec))
        throw SampleError("cannot write '" + for_what + "': '" + folder.string() + "' is a file, not a folder");
    if (access(folder.c_str(), W_OK) != 0)
        throw SampleError("cannot write '" + for_what + "': the folder '" + folder.string() + "' is not writable");
}

}  // namespace

void check_writable_file(const std::string& path) {
    std::error_code ec;
    if (path.empty()) throw SampleError("an output path is empty");
    if (fs::is_directory(path, ec)) throw SampleError("cannot write '" + path + "': it is a folder");
    const fs::path folder = fs::path(path).parent_path();
    require_writable_folder(folder.empty() ? fs::path(".") : folder, path);
    if (access(path.c_str(), F_OK) == 0 && access(path.c_str(), W_OK) != 0)
        throw SampleError("cannot write '" + path + "': the file is not writable");
}

void prepare_output_folder(const std::string& dir) {
    std::error_code ec;
    if (dir.empty()) throw SampleError("--out-dir is empty");
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw SampleError("--out-dir '" + dir + "' is a file, not a folder");
    if (!fs::exists(dir, ec) && !fs::create_directories(dir, ec) && ec)
        throw SampleError("cannot make the folder '" + dir + "': " + ec.message());
    require_writable_folder(dir, dir);
}

}  // namespace nl::samples
