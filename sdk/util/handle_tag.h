// The tag a world's handles carry (SlotMap's top revision bits), so that a handle of one live world
// is refused by every other: no two live worlds hold the same tag. Tags are handed out round-robin,
// skipping those in use, so a destroyed world's tag comes back only after every other tag was used.
#pragma once

#include <cstdint>

namespace nl {

class HandleTag {
public:
    // Takes a free tag; throws OutOfMemory when every tag is held by a live world.
    static HandleTag acquire();
    ~HandleTag();
    HandleTag(HandleTag&& other) noexcept : value_(other.value_) { other.value_ = 0; }
    HandleTag& operator=(HandleTag&& other) noexcept;
    HandleTag(const HandleTag&) = delete;
    HandleTag& operator=(const HandleTag&) = delete;

    uint32_t value() const noexcept { return value_; }

    // How many worlds may live at once: every nonzero value of SlotMap's tag bits.
    static constexpr uint32_t kCount = 4095;

private:
    explicit HandleTag(uint32_t value) : value_(value) {}
    uint32_t value_;  // 1..kCount; 0 once moved from
};

}  // namespace nl
