// Handles with revisions and the slot map that issues them (Box2D-style ids: index + 1, revision),
// each carrying the kind of thing it names.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "util/error.h"

namespace nl {

// What a handle names. Every slot map of a world issues handles of one kind, in the top bits of
// index1, so an id of one kind (a navmesh's) is never taken for a live one of another kind (an
// agent's) that happens to sit in a slot of the same number. 0: a slot map of no particular kind.
enum class HandleKind : uint32_t { None = 0, Mesh, NavMesh, Link, Plugin, PathTicket, Agent };

struct Handle {
    uint32_t index1 = 0;  // kind << kHandleSlotBits | (slot index + 1); 0 is the null handle
    uint32_t revision = 0;

    bool is_null() const noexcept { return index1 == 0; }
    // Both halves in one number, as a hash key.
    uint64_t packed() const noexcept { return (uint64_t(index1) << 32) | revision; }
    friend bool operator==(Handle a, Handle b) noexcept { return a.index1 == b.index1 && a.revision == b.revision; }
    friend bool operator!=(Handle a, Handle b) noexcept { return !(a == b); }
};

constexpr uint32_t kHandleSlotBits = 28;
constexpr uint32_t kHandleSlotMask = (1u << kHandleSlotBits) - 1;  // also the most slots one map holds

// Throws InvalidHandle for a handle that a slot map did not recognise; `what` names its kind.
[[noreturn]] inline void fail_stale(const char* what, Handle h) {
    fail(ErrorCode::InvalidHandle, what, " {", h.index1, ", ", h.revision, "} is null, removed or from another world");
}

// Stores values in reusable slots. A removed slot's revision is bumped, so an old handle to it is
// recognised as stale instead of reaching the slot's next occupant. A slot whose revision counter
// is used up is retired, never reused: a handle can never come back to life, however long the
// program runs (a retired slot costs its size once per 2^20 - 1 lifetimes of it). The top bits of
// every revision carry the owner's tag, so a handle from another owner (another world) is refused
// as well.
template <typename T>
class SlotMap {
public:
    static constexpr uint32_t kTagBits = 12;
    static constexpr uint32_t kCounterBits = 32 - kTagBits;
    static constexpr uint32_t kCounterMask = (1u << kCounterBits) - 1;

    // Only the low kTagBits bits of `tag` are used.
    explicit SlotMap(uint32_t tag = 0, HandleKind kind = HandleKind::None)
        : tag_bits_((tag & ((1u << kTagBits) - 1)) << kCounterBits),
          kind_bits_(static_cast<uint32_t>(kind) << kHandleSlotBits) {}

    // Throws OutOfMemory when kHandleSlotMask slots are in use or retired.
    Handle insert(T value) {
        uint32_t index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = static_cast<uint32_t>(slots_.size());
            if (index >= kHandleSlotMask)
                fail(ErrorCode::OutOfMemory, "more than ", kHandleSlotMask,
                     " ids of one kind in use or retired at once");
            // Room in free_ for every slot, grown geometrically: erase then never allocates (nor throws).
            if (free_.capacity() <= slots_.size())
                free_.reserve(std::max<size_t>(2 * free_.capacity(), slots_.size() + 16));
            slots_.push_back(Slot{});
        }
        Slot& slot = slots_[index];
        slot.value.emplace(std::move(value));
        ++live_;
        return Handle{kind_bits_ | (index + 1), revision_of(slot)};
    }

    T* find(Handle h) noexcept {
        Slot* slot = slot_of(h);
        return slot ? &*slot->value : nullptr;
    }
    const T* find(Handle h) const noexcept { return const_cast<SlotMap*>(this)->find(h); }

    bool erase(Handle h) noexcept {
        Slot* slot = slot_of(h);
        if (!slot) return false;
        slot->value.reset();
        --live_;
        if (slot->counter == kCounterMask) {
            ++retired_;  // its next revision would repeat an old one
        } else {
            ++slot->counter;
            free_.push_back((h.index1 & kHandleSlotMask) - 1);
        }
        return true;
    }

    // Handle of the occupied slot at `index`; used to map back from internal indices.
    Handle handle_at(uint32_t index) const noexcept {
        return Handle{kind_bits_ | (index + 1), revision_of(slots_[index])};
    }

    template <typename Fn>
    void for_each(Fn&& fn) const {
        for (uint32_t i = 0; i < slots_.size(); ++i) {
            if (slots_[i].value) fn(handle_at(i), *slots_[i].value);
        }
    }
    template <typename Fn>
    void for_each(Fn&& fn) {
        for (uint32_t i = 0; i < slots_.size(); ++i) {
            if (slots_[i].value) fn(handle_at(i), *slots_[i].value);
        }
    }

    uint32_t size() const noexcept { return live_; }
    // Slots whose revisions are used up.
    uint32_t retired() const noexcept { return retired_; }

private:
    struct Slot {
        std::optional<T> value;
        uint32_t counter = 1;
    };

    uint32_t revision_of(const Slot& slot) const noexcept { return tag_bits_ | slot.counter; }

    Slot* slot_of(Handle h) noexcept {
        const uint32_t slot1 = h.index1 & kHandleSlotMask;
        if ((h.index1 & ~kHandleSlotMask) != kind_bits_ || slot1 == 0 || slot1 > slots_.size()) return nullptr;
        Slot& slot = slots_[slot1 - 1];
        return slot.value && revision_of(slot) == h.revision ? &slot : nullptr;
    }

    std::vector<Slot> slots_;
    std::vector<uint32_t> free_;
    uint32_t live_ = 0;
    uint32_t retired_ = 0;
    uint32_t tag_bits_;
    uint32_t kind_bits_;
};

// The handles removed from one owner's slot map, for a store that keeps state beside it and must
// refuse a removed handle for good (a link store asked to keep links for a navmesh removed while they
// were being generated). One word per slot, not one per removal: a slot's revisions only grow (the
// slot map retires a slot before its counter could wrap), so a handle is removed when its revision
// is at most the last one removed from its slot. Only handles the owner issued may be added.
class RemovedHandles {
public:
    void add(Handle h) {
        const uint32_t slot1 = h.index1 & kHandleSlotMask;
        if (slot1 == 0) return;  // the null handle was never issued
        if (slot1 > last_removed_.size()) last_removed_.resize(slot1, 0);
        uint32_t& last = last_removed_[slot1 - 1];
        if (h.revision > last) last = h.revision;
    }
    bool contains(Handle h) const noexcept {
        const uint32_t slot1 = h.index1 & kHandleSlotMask;
        return slot1 != 0 && slot1 <= last_removed_.size() && h.revision <= last_removed_[slot1 - 1];
    }

private:
    std::vector<uint32_t> last_removed_;  // by slot index
};

}  // namespace nl
