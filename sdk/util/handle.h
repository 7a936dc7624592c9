// Generational handles and the slot map that issues them (Box2D-style ids: index + 1, generation).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace nl {

struct Handle {
    uint32_t index1 = 0;  // slot index + 1; 0 is the null handle
    uint32_t generation = 0;

    bool is_null() const noexcept { return index1 == 0; }
    friend bool operator==(Handle a, Handle b) noexcept {
        return a.index1 == b.index1 && a.generation == b.generation;
    }
    friend bool operator!=(Handle a, Handle b) noexcept { return !(a == b); }
};

// Stores values in reusable slots. A removed slot's generation is bumped, so an old handle to it is
// recognised as stale instead of reaching the slot's next occupant.
template <typename T>
class SlotMap {
public:
    Handle insert(T value) {
        uint32_t index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = static_cast<uint32_t>(slots_.size());
            slots_.push_back(Slot{});
        }
        Slot& slot = slots_[index];
        slot.value.emplace(std::move(value));
        ++live_;
        return Handle{index + 1, slot.generation};
    }

    T* find(Handle h) noexcept {
        Slot* slot = slot_of(h);
        return slot ? &*slot->value : nullptr;
    }
    const T* find(Handle h) const noexcept { return const_cast<SlotMap*>(this)->find(h); }

    bool erase(Handle h) {
        Slot* slot = slot_of(h);
        if (!slot) return false;
        slot->value.reset();
        ++slot->generation;
        free_.push_back(h.index1 - 1);
        --live_;
        return true;
    }

    // Handle of the occupied slot at `index`; used to map back from internal indices.
    Handle handle_at(uint32_t index) const noexcept {
        return Handle{index + 1, slots_[index].generation};
    }

    template <typename Fn>
    void for_each(Fn&& fn) const {
        for (uint32_t i = 0; i < slots_.size(); ++i) {
            if (slots_[i].value) fn(handle_at(i), *slots_[i].value);
        }
    }

    uint32_t size() const noexcept { return live_; }

private:
    struct Slot {
        std::optional<T> value;
        uint32_t generation = 1;
    };

    Slot* slot_of(Handle h) noexcept {
        if (h.index1 == 0 || h.index1 > slots_.size()) return nullptr;
        Slot& slot = slots_[h.index1 - 1];
        return slot.value && slot.generation == h.generation ? &slot : nullptr;
    }

    std::vector<Slot> slots_;
    std::vector<uint32_t> free_;
    uint32_t live_ = 0;
};

}  // namespace nl
