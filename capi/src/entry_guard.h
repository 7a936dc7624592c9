// Every nl_* entry point runs its body through guarded(): it records the call's status and message
// for the calling thread, sends failures to the world's log callback, and stops every C++ exception
// at the ABI boundary.
#pragma once

#include <algorithm>
#include <memory>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "navlink/navlink.h"
#include "util/error.h"

struct nl_world;

namespace nl::capi {

nl_status to_status(ErrorCode code) noexcept;
// The error code of a failure status (the most specific detail bit), for failures a plugin returns.
ErrorCode to_error_code(nl_status status) noexcept;

// Records the outcome of the current call on this thread (and logs failures through `world`).
nl_status record(const char* function, const nl_world* world, nl_status status, const char* message) noexcept;

inline nl_status record_success() noexcept { return record(nullptr, nullptr, NL_STATUS_SUCCESS, ""); }

template <typename Call>
nl_status guarded(const char* function, const nl_world* world, Call&& call) noexcept {
    try {
        call();
        return record_success();
    } catch (const Error& e) {
        return record(function, world, NL_STATUS_FAILURE | to_status(e.code()), e.what());
    } catch (const std::bad_alloc&) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception& e) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, e.what());
    } catch (...) {
        return record(function, world, NL_STATUS_FAILURE | NL_STATUS_INTERNAL_ERROR, "unknown exception");
    }
}

// Throws InvalidArgument naming `name` when `pointer` is null.
inline void require(const void* pointer, const char* name) {
    if (!pointer) fail(ErrorCode::InvalidArgument, name, " is null");
}
// The same for a field of a struct being read (the caller names the struct: naming_fields).
inline void require_field(const void* pointer, const char* name) {
    if (!pointer) fail_field(ErrorCode::InvalidArgument, name, " is null");
}

// The two-call list pattern: a NULL buffer asks only for the count (a success); a buffer with too
// little capacity is BUFFER_TOO_SMALL, with the count still written so the caller can grow it.
// `write_all` fills the buffer once it is known to be large enough.
template <typename WriteAll>
void list_into(size_t count, const void* out, uint32_t capacity, uint32_t* out_count, const char* out_name,
               WriteAll&& write_all) {
    require(out_count, "out_count");
    if (!out && capacity > 0) fail(ErrorCode::InvalidArgument, out_name, " is null but capacity is ", capacity);
    *out_count = static_cast<uint32_t>(count);
    if (!out) return;
    if (count > capacity)
        fail(ErrorCode::BufferTooSmall, "capacity is ", capacity, " but ", count, " entries are needed");
    write_all();
}

template <typename Item, typename Out, typename Convert>
void list_into(const std::vector<Item>& items, Out* out, uint32_t capacity, uint32_t* out_count, const char* out_name,
               Convert&& convert) {
    list_into(items.size(), out, capacity, out_count, out_name, [&] {
        for (size_t i = 0; i < items.size(); ++i) out[i] = convert(items[i]);
    });
}

// Output arrays of growable elements (nl_link, nl_path_point, ...): the caller's element size is its
// first element's `size` (at least `first_version_size`); element i is written at i times that
// stride, as many bytes of it as both sides know, with its `size` set to the caller's.
template <typename T>
class ElementWriter {
public:
    // Elements of a newer header than the library's are allowed, up to a bound that also catches
    // most uninitialised memory (a malloc'd array whose first `size` was never set).
    static constexpr uint32_t kLargestElement = 4096;

    ElementWriter(T* out, size_t first_version_size, const char* out_name)
        : bytes_(reinterpret_cast<unsigned char*>(out)) {
        stride_ = out->size;
        if (stride_ < first_version_size || stride_ > kLargestElement || stride_ % alignof(T) != 0)
            fail(ErrorCode::InvalidArgument, out_name, "[0].size is ", stride_, ", expected sizeof (at least ",
                 first_version_size, ", a multiple of ", alignof(T), "; set it with its nl_*_init function)");
    }
    void write(size_t i, T value) const {
        value.size = stride_;
        std::memcpy(bytes_ + i * size_t(stride_), &value, std::min<size_t>(stride_, sizeof(T)));
    }

private:
    unsigned char* bytes_;
    uint32_t stride_ = 0;
};

// list_into for growable elements. The caller's element size is checked whenever it hands over a
// buffer, whether or not there is anything to write, so an unset one is found on the first call.
template <typename Item, typename Out, typename Convert>
void list_growable_into(const std::vector<Item>& items, Out* out, uint32_t capacity, uint32_t* out_count,
                        size_t first_version_size, const char* out_name, Convert&& convert) {
    require(out_count, "out_count");
    if (!out && capacity > 0) fail(ErrorCode::InvalidArgument, out_name, " is null but capacity is ", capacity);
    std::optional<ElementWriter<Out>> writer;
    if (out && capacity > 0) writer.emplace(out, first_version_size, out_name);
    list_into(items.size(), out, capacity, out_count, out_name, [&] {
        for (size_t i = 0; i < items.size(); ++i) writer->write(i, convert(items[i]));
    });
}

// Growable structs: a caller built against an older header passes a smaller `size`. Fields it does
// not have keep their defaults; `first_version_size` is where the struct's first release ended
// (offsetof + sizeof of its last field then), which is all the library can require.
// A size that is not a multiple of the struct's alignment cannot be a struct's sizeof, and could end
// inside a field (half a pointer copied).
template <typename T>
T read_growable(const T& in, T defaults, size_t first_version_size, const char* name) {
    if (in.size < first_version_size || in.size % alignof(T) != 0)
        fail(ErrorCode::InvalidArgument, name, "->size is ", in.size, ", expected sizeof (at least ",
             first_version_size, ", a multiple of ", alignof(T),
             "; initialise it from its nl_default_* function or with sizeof)");
    std::memcpy(&defaults, &in, std::min<size_t>(in.size, sizeof(T)));
    defaults.size = static_cast<uint32_t>(sizeof(T));
    return defaults;
}

// Throws unless the caller's output struct has a size the library can write into; a call that
// changes the world checks it before the change, so a refusal changes nothing.
template <typename T>
void check_growable_output(const T* out, size_t first_version_size, const char* name) {
    if (out->size < first_version_size || out->size % alignof(T) != 0)
        fail(ErrorCode::InvalidArgument, name, "->size is ", out->size, ", expected sizeof (at least ",
             first_version_size, ", a multiple of ", alignof(T), "; set it to sizeof or with its nl_*_init function)");
}

// Writes an output struct into as many bytes as the caller's struct has (its `size`, kept as is).
template <typename T>
void write_growable(T* out, const T& value, size_t first_version_size, const char* name) {
    check_growable_output(out, first_version_size, name);
    const uint32_t caller_size = out->size;
    std::memcpy(out, &value, std::min<size_t>(caller_size, sizeof(T)));
    out->size = caller_size;
}

}  // namespace nl::capi
