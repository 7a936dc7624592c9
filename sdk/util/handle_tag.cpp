#include "util/handle_tag.h"

#include <bitset>
#include <mutex>

#include "util/error.h"
#include "util/handle.h"

namespace nl {
namespace {

static_assert(HandleTag::kCount == (1u << SlotMap<int>::kTagBits) - 1, "one tag per nonzero value of the tag bits");

// Which tags live worlds hold. Process-wide by nature: it is what keeps the worlds of one process
// apart. Holds no world state.
struct TagTable {
    std::mutex mutex;
    std::bitset<HandleTag::kCount + 1> in_use;
    uint32_t last = 0;
};

TagTable& tags() {
    static TagTable table;
    return table;
}

}  // namespace

HandleTag HandleTag::acquire() {
    TagTable& t = tags();
    std::lock_guard lock(t.mutex);
    for (uint32_t step = 1; step <= kCount; ++step) {
        const uint32_t candidate = (t.last + step - 1) % kCount + 1;
        if (t.in_use[candidate]) continue;
        t.in_use[candidate] = true;
        t.last = candidate;
        return HandleTag(candidate);
    }
    fail(ErrorCode::OutOfMemory, kCount, " worlds exist at once, the most there can be: destroy one first");
}

HandleTag::~HandleTag() {
    if (!value_) return;
    TagTable& t = tags();
    std::lock_guard lock(t.mutex);
    t.in_use[value_] = false;
}

HandleTag& HandleTag::operator=(HandleTag&& other) noexcept {
    if (this != &other) {
        HandleTag released(value_);  // gives the old tag back as it goes
        value_ = other.value_;
        other.value_ = 0;
    }
    return *this;
}

}  // namespace nl
