#include "io/json_input.h"

#include <utility>
#include <vector>

#include "util/error.h"
#include "util/excerpt.h"

namespace nl {
namespace {

using Json = nlohmann::json;

constexpr size_t kPathBytes = 100;
constexpr size_t kParserMessageBytes = 200;

std::string counted(size_t count, const char* noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// Builds the document as nlohmann's own DOM parser does, but refuses to open a container past
// kMaxJsonDepth and keeps the path of the value being read, so each refusal can name where it is.
class BoundedBuilder : public nlohmann::json_sax<Json> {
public:
    explicit BoundedBuilder(const std::string& what) : what_(what) {}
    Json take() { return std::move(root_); }

    bool null() override { return put(nullptr); }
    bool boolean(bool value) override { return put(value); }
    bool number_integer(number_integer_t value) override { return put(value); }
    bool number_unsigned(number_unsigned_t value) override { return put(value); }
    bool number_float(number_float_t value, const string_t&) override { return put(value); }
    bool string(string_t& value) override { return put(std::move(value)); }
    bool binary(binary_t& value) override { return put(Json::binary(std::move(value))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& key) override {
        open_.back().key = key;
        member_ = &(*open_.back().container)[key];  // a repeated key keeps its last value, as nlohmann's parser
        return true;
    }

    bool parse_error(std::size_t byte, const std::string& token, const Json::exception& e) override {
        // 406 is nlohmann's "number overflow": valid JSON, but no double holds it.
        if (e.id == 406)
            fail(ErrorCode::InvalidArgument, where(), " is ", cut_text(token, kExcerptBytes),
                 ", a number beyond the range of a double");
        // The parser's message ends with the token it last read, which may be a whole long string.
        fail(ErrorCode::Parse, what_, ": malformed JSON at byte ", byte, ": ", cut_text(e.what(), kParserMessageBytes));
    }

private:
    struct Open {
        Json* container;
        std::string key;  // of the member being read, in an object
    };

    // The slot the next value goes into.
    Json& slot() {
        if (open_.empty()) return root_;
        Json& top = *open_.back().container;
        if (top.is_array()) return top.emplace_back();
        return *member_;
    }
    template <typename Value>
    bool put(Value&& value) {
        slot() = Json(std::forward<Value>(value));
        return true;
    }
    bool open(Json&& empty) {
        if (open_.size() >= size_t(kMaxJsonDepth))
            fail(ErrorCode::InvalidArgument, where(), " nests deeper than ", kMaxJsonDepth,
                 " levels, the most NavLink reads");
        Json& container = slot();
        container = std::move(empty);
        open_.push_back(Open{&container, {}});
        return true;
    }
    bool close() {
        open_.pop_back();
        return true;
    }

    // "what: path" of the value being read (an array's next element, an object's current member).
    std::string where() const {
        std::string path;
        for (size_t level = 0; level < open_.size(); ++level) {
            const Open& o = open_[level];
            if (o.container->is_array()) {
                // Below the top the element being read is already in place; at the top it is next.
                const size_t index = o.container->size() - (level + 1 < open_.size() ? 1 : 0);
                path += "[" + std::to_string(index) + "]";
            } else {
                path += (path.empty() ? "" : ".") + o.key;
            }
        }
        return path.empty() ? what_ : what_ + ": " + cut_text(path, kPathBytes);
    }

    const std::string& what_;
    Json root_;
    std::vector<Open> open_;
    Json* member_ = nullptr;
};

}  // namespace

Json parse_json(std::string_view text, const std::string& what) {
    BoundedBuilder builder(what);
    Json::sax_parse(text.begin(), text.end(), &builder);
    return builder.take();
}

Json recorded_json(const std::string& text) {
    if (text.empty()) return nullptr;
    try {
        return parse_json(text, "a recorded text");
    } catch (const Error&) {
        return text;
    }
}

std::string json_excerpt(const Json& value) {
    switch (value.type()) {
        case Json::value_t::string: return quoted_excerpt(value.get_ref<const std::string&>());
        case Json::value_t::array: return "an array of " + counted(value.size(), "value");
        case Json::value_t::object: return "an object of " + counted(value.size(), "member");
        default: return value.dump();  // null, a boolean or a number: short by nature
    }
}

}  // namespace nl
