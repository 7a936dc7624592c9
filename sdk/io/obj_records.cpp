#include "io/obj_records.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "util/error.h"
#include "util/excerpt.h"

namespace nl {
namespace {

// Calls read(line, number) for every line of `text`. A line ends at \n, \r\n or a lone \r: the
// endings tinyobjloader's safeGetline knows.
template <typename Read>
void for_each_line(std::string_view text, Read&& read) {
    size_t number = 0;
    size_t begin = 0;
    while (begin < text.size()) {
        size_t end = text.find_first_of("\r\n", begin);
        if (end == std::string_view::npos) end = text.size();
        read(text.substr(begin, end - begin), ++number);
        begin = end + 1;
        if (end < text.size() && text[end] == '\r' && begin < text.size() && text[begin] == '\n') ++begin;
    }
}

// Words separated by spaces and tabs (tinyobjloader's separators), up to a '#' comment.
std::vector<std::string_view> tokens_of(std::string_view line) {
    line = line.substr(0, line.find('#'));
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

// The kinds of vertex data a face corner refers to, "position/texture/normal".
enum Kind { kPosition, kTexture, kNormal, kKinds };
constexpr const char* kKindNames[kKinds] = {"vertex", "texture coordinate", "normal"};

class RecordWriter {
public:
    explicit RecordWriter(const std::string& name) : name_(name) {}

    void read(std::string_view line, size_t number) {
        line_ = number;
        const auto tokens = tokens_of(line);
        if (tokens.empty()) return;
        if (tokens[0] == "v")
            vertex(tokens);
        else if (tokens[0] == "vt")
            ++count_[kTexture];
        else if (tokens[0] == "vn")
            ++count_[kNormal];
        else if (tokens[0] == "f")
            face(tokens);
        else if (tokens[0] == "o" || tokens[0] == "g")
            group(tokens);
    }

    std::string finish() {
        // Positive indices may point forward, to data listed later: checked once all of it is known.
        for (int kind = 0; kind < kKinds; ++kind) {
            if (largest_[kind].index > count_[kind])
                fail(ErrorCode::Parse, name_, ":", largest_[kind].line, ": ", kKindNames[kind], " index ",
                     largest_[kind].index, " is past the last one (", count_[kind], ")");
        }
        return std::move(out_);
    }

private:
    void vertex(const std::vector<std::string_view>& tokens) {
        if (tokens.size() < 4) fail(ErrorCode::Parse, name_, ":", line_, ": a vertex needs x y z");
        out_ += 'v';
        for (size_t k = 1; k <= 3; ++k) {
            float value = 0.0f;
            const auto [end, ec] = std::from_chars(tokens[k].data(), tokens[k].data() + tokens[k].size(), value);
            if (ec != std::errc() || end != tokens[k].data() + tokens[k].size() || !std::isfinite(value))
                fail(ErrorCode::Parse, name_, ":", line_, ": ", quoted_excerpt(tokens[k]), " is not a finite number");
            // Written back shortest-exact, in a form tinyobjloader's own number parser reads.
            char text[32];
            out_ += ' ';
            out_.append(text, std::to_chars(text, text + sizeof text, value).ptr);
        }
        out_ += '\n';
        ++count_[kPosition];
    }

    void face(const std::vector<std::string_view>& tokens) {
        if (tokens.size() < 4) fail(ErrorCode::Parse, name_, ":", line_, ": a face needs 3 vertices or more");
        out_ += 'f';
        for (size_t k = 1; k < tokens.size(); ++k) {
            out_ += ' ';
            out_ += std::to_string(corner_position(tokens[k]));
        }
        out_ += '\n';
    }

    // "v", "v/vt", "v//vn" or "v/vt/vn": every index is checked, the position's is returned.
    int64_t corner_position(std::string_view corner) {
        std::string_view parts[kKinds];
        size_t count = 0;
        for (std::string_view rest = corner;; ++count) {
            if (count == kKinds)
                fail(ErrorCode::Parse, name_, ":", line_, ": ", quoted_excerpt(corner), " is not a face corner");
            const size_t slash = rest.find('/');
            parts[count] = rest.substr(0, slash);
            if (slash == std::string_view::npos) break;
            rest = rest.substr(slash + 1);
        }
        ++count;
        int64_t position = 0;
        for (size_t kind = 0; kind < count; ++kind) {
            // Only the texture coordinate of "v//vn" may be left out.
            if (parts[kind].empty() && kind == kTexture && count == kKinds) continue;
            const int64_t index = checked_index(parts[kind], Kind(kind), corner);
            if (kind == kPosition) position = index;
        }
        return position;
    }

    // A face corner's index of `kind`: a whole number that is not 0, not before the first of its
    // kind so far (negative indices count back from there) and small enough for tinyobjloader's int.
    int64_t checked_index(std::string_view part, Kind kind, std::string_view corner) {
        int64_t index = 0;
        const auto [at, ec] = std::from_chars(part.data(), part.data() + part.size(), index);
        if (ec != std::errc() || at != part.data() + part.size())
            fail(ErrorCode::Parse, name_, ":", line_, ": ", quoted_excerpt(corner), " is not a ", kKindNames[kind],
                 " index");
        if (index == 0 || index < -count_[kind] || index > std::numeric_limits<int32_t>::max())
            fail(ErrorCode::Parse, name_, ":", line_, ": ", kKindNames[kind], " index ", index, " is out of range");
        if (index > largest_[kind].index) largest_[kind] = Largest{index, line_};
        return index;
    }

    void group(const std::vector<std::string_view>& tokens) {
        if (tokens.size() < 2) return;
        out_ += tokens[0];
        for (size_t k = 1; k < tokens.size(); ++k) {
            out_ += ' ';
            // Control bytes end a line or a string for tinyobjloader; a name does without them.
            for (const char c : tokens[k])
                if (static_cast<unsigned char>(c) >= 0x20) out_ += c;
        }
        out_ += '\n';
    }

    struct Largest {
        int64_t index = 0;
        size_t line = 0;
    };

    const std::string& name_;
    std::string out_;
    size_t line_ = 0;
    int64_t count_[kKinds] = {};
    Largest largest_[kKinds];
};

}  // namespace

std::string checked_obj_records(std::string_view text, const std::string& name) {
    RecordWriter writer(name);
    for_each_line(text, [&](std::string_view line, size_t number) { writer.read(line, number); });
    return writer.finish();
}

}  // namespace nl
