// Little-endian bytes written and read field by field, for the binary files. The reader never reads
// past its end: a short read fails, naming what was being read and how many bytes were missing.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace nl {

class ByteWriter {
public:
    void u8(uint8_t v) { bytes_.push_back(v); }
    void u16(uint16_t v) { little(v, 2); }
    void u32(uint32_t v) { little(v, 4); }
    void u64(uint64_t v) { little(v, 8); }
    void f32(float v) {
        uint32_t bits;
        std::memcpy(&bits, &v, 4);
        u32(bits);
    }
    // An unsigned integer in `width` bytes (1 to 8).
    void little(uint64_t v, unsigned width) {
        for (unsigned i = 0; i < width; ++i) bytes_.push_back(static_cast<uint8_t>(v >> (8 * i)));
    }
    // 7 bits per byte, low first; the high bit says another byte follows.
    void varint(uint64_t v) {
        while (v >= 0x80) {
            bytes_.push_back(static_cast<uint8_t>(v | 0x80));
            v >>= 7;
        }
        bytes_.push_back(static_cast<uint8_t>(v));
    }
    // Small magnitudes of either sign in few bytes.
    void signed_varint(int64_t v) { varint((static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63)); }
    void text(std::string_view s) {
        varint(s.size());
        bytes_.insert(bytes_.end(), s.begin(), s.end());
    }
    void append(const std::vector<uint8_t>& more) { bytes_.insert(bytes_.end(), more.begin(), more.end()); }
    // Overwrites 4 bytes at `at` (a size or checksum known only later).
    void patch_u32(size_t at, uint32_t v) {
        for (unsigned i = 0; i < 4; ++i) bytes_[at + i] = static_cast<uint8_t>(v >> (8 * i));
    }
    void patch_u64(size_t at, uint64_t v) {
        for (unsigned i = 0; i < 8; ++i) bytes_[at + i] = static_cast<uint8_t>(v >> (8 * i));
    }

    size_t size() const { return bytes_.size(); }
    std::vector<uint8_t>& bytes() { return bytes_; }

private:
    std::vector<uint8_t> bytes_;
};

// Reads a span of bytes it does not own. Failures are Parse errors that start with `context`
// ("navmesh file: GEOM section") and say what was being read.
class ByteReader {
public:
    ByteReader(const uint8_t* data, size_t size, std::string context)
        : data_(data), size_(size), context_(std::move(context)) {}

    size_t position() const { return at_; }
    size_t remaining() const { return size_ - at_; }
    const uint8_t* here() const { return data_ + at_; }
    const std::string& context() const { return context_; }

    uint8_t u8(const char* what) { return static_cast<uint8_t>(little(1, what)); }
    uint16_t u16(const char* what) { return static_cast<uint16_t>(little(2, what)); }
    uint32_t u32(const char* what) { return static_cast<uint32_t>(little(4, what)); }
    uint64_t u64(const char* what) { return little(8, what); }
    float f32(const char* what) {
        const uint32_t bits = u32(what);
        float v;
        std::memcpy(&v, &bits, 4);
        return v;
    }
    uint64_t little(unsigned width, const char* what) {
        need(width, what);
        uint64_t v = 0;
        for (unsigned i = 0; i < width; ++i) v |= uint64_t(data_[at_ + i]) << (8 * i);
        at_ += width;
        return v;
    }
    uint64_t varint(const char* what) {
        uint64_t v = 0;
        for (unsigned shift = 0; shift < 64; shift += 7) {
            const uint8_t b = u8(what);
            if (shift == 63 && b > 1) break;
            v |= uint64_t(b & 0x7f) << shift;
            if (!(b & 0x80)) return v;
        }
        fail(ErrorCode::Parse, context_, ": ", what, " at byte ", at_, " is not a valid number (too long)");
    }
    int64_t signed_varint(const char* what) {
        const uint64_t v = varint(what);
        return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1);
    }
    // A count of items of at least `item_bytes` bytes each that must still fit in what remains, so
    // no count in a file can make the reader allocate more than the file could hold.
    uint32_t count(const char* what, size_t item_bytes) {
        const uint64_t n = varint(what);
        if (n > UINT32_MAX || (item_bytes > 0 && n > remaining() / item_bytes))
            fail(ErrorCode::Parse, context_, ": ", what, " is ", n, ", more than the ", remaining(),
                 " bytes left could hold (truncated or corrupted)");
        return static_cast<uint32_t>(n);
    }
    std::string text(const char* what) {
        const uint32_t n = count(what, 1);
        std::string s(reinterpret_cast<const char*>(data_ + at_), n);
        at_ += n;
        return s;
    }
    void skip(size_t n, const char* what) {
        need(n, what);
        at_ += n;
    }
    void need(size_t n, const char* what) const {
        if (n > remaining())
            fail(ErrorCode::Parse, context_, ": truncated: ", what, " needs ", n, " bytes at byte ", at_, ", ",
                 remaining(), " remain");
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
    std::string context_;
};

}  // namespace nl
