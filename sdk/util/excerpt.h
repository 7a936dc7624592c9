// Text a caller handed over, quoted for a message: cut short and with control bytes escaped, so a
// huge or binary input never makes a huge or garbled message.
#pragma once

#include <string>
#include <string_view>

namespace nl {

constexpr size_t kExcerptBytes = 40;

// The first `limit` bytes of `text` (never splitting a UTF-8 sequence), with "..." when cut.
std::string cut_text(std::string_view text, size_t limit);

// `text` cut to kExcerptBytes, in double quotes; quotes, backslashes and control bytes escaped.
std::string quoted_excerpt(std::string_view text);

}  // namespace nl
