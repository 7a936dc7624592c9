#include "text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

#include "sample_error.h"

namespace nl::samples {

std::string read_text_file(const std::string& path) {
    struct stat info {};
    if (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
        throw SampleError("cannot open '" + path + "': it is a directory");
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw SampleError("cannot open '" + path + "': " + std::strerror(errno));
    std::string text;
    char buffer[65536];
    size_t got = 0;
    while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, got);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) throw SampleError("cannot read '" + path + "'");
    return text;
}

void write_text_file(const std::string& path, const std::string& text) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw SampleError("cannot write '" + path + "': " + std::strerror(errno));
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    if (std::fclose(file) != 0 || !written) throw SampleError("cannot write '" + path + "'");
}

}  // namespace nl::samples
