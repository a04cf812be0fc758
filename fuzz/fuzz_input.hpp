// fuzz/fuzz_input.hpp — reading a libFuzzer input as a stream of values, and the contract
// check every harness uses. (Not part of the library: `make fuzz` only.)
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace fuzz {

class Input {
public:
    Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool empty() const { return pos_ >= size_; }
    std::size_t left() const { return size_ - pos_; }
    template <class T> T take() {  // raw bits (NaN, inf, subnormals included); 0 when used up
        T v{};
        std::size_t n = sizeof(T) < left() ? sizeof(T) : left();
        std::memcpy(&v, data_ + pos_, n);
        pos_ += n;
        return v;
    }
    // A "nice" double half of the time (small integers over a power of two, so lattices and
    // cocircular points occur), raw bits otherwise.
    double coordinate() {
        std::uint8_t mode = take<std::uint8_t>();
        if (mode & 1) return take<double>();
        std::int16_t k = take<std::int16_t>();
        return double(k) / double(1 << (mode >> 4));
    }
    // A "nice" float seven times in eight (a small integer over a power of two), raw bits
    // (NaN, inf, huge) otherwise.
    float value() {
        const std::uint8_t mode = take<std::uint8_t>();
        if ((mode & 7) == 7) return take<float>();
        return float(take<std::int16_t>()) / float(1 << (mode >> 4));
    }

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

// A broken contract: say which and abort (libFuzzer saves the input as a crash).
[[noreturn]] inline void fail(const char* what) {
    std::fprintf(stderr, "fuzz contract broken: %s\n", what);
    std::abort();
}
// All three components finite (the library's Vec3, or any type with x, y, z).
template <class V> bool finite3(const V& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
#define FUZZ_REQUIRE(cond) \
    do {                   \
        if (!(cond)) ::fuzz::fail(#cond); \
    } while (0)

}  // namespace fuzz
