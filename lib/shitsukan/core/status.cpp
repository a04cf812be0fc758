// small-device: yes (no allocation, no exceptions)
#include "shitsukan/core/status.hpp"

#include <cstdarg>
#include <cstddef>
#include <cstring>

#include "shitsukan/core/format_number.hpp"

namespace shitsukan {

const char* status_code_name(StatusCode code) {
    switch (code) {
        case StatusCode::ok:
            return "ok";
        case StatusCode::invalid_argument:
            return "invalid argument";
        case StatusCode::out_of_range:
            return "out of range";
        case StatusCode::too_large:
            return "too large";
        case StatusCode::buffer_too_small:
            return "buffer too small";
        case StatusCode::degenerate:
            return "degenerate";
        case StatusCode::io_error:
            return "i/o error";
        case StatusCode::not_supported:
            return "not supported";
    }
    return "unknown status";
}

namespace {

// One printf conversion: %[flags][width][.precision][length]conversion.
enum class Length { none, hh, h, l, ll, z, j, t, L };

struct Spec {
    NumberFormat number;
    bool width_star = false, precision_star = false;
    Length length = Length::none;
    char conversion = 0;  // 0: the format ended inside the specification
};

// Reads the specification after a '%'; p ends after its conversion character.
Spec parse_spec(const char*& p) {
    Spec s;
    for (;; ++p) {
        if (*p == '-')
            s.number.left = true;
        else if (*p == '+')
            s.number.plus = true;
        else if (*p == ' ')
            s.number.space = true;
        else if (*p == '0')
            s.number.zero = true;
        else if (*p == '#')
            s.number.alternate = true;
        else
            break;
    }
    if (*p == '*') {
        s.width_star = true;
        ++p;
    } else {
        while (*p >= '0' && *p <= '9') s.number.width = s.number.width * 10 + (*p++ - '0');
    }
    if (*p == '.') {
        ++p;
        s.number.precision = 0;
        if (*p == '*') {
            s.precision_star = true;
            ++p;
        } else {
            while (*p >= '0' && *p <= '9')
                s.number.precision = s.number.precision * 10 + (*p++ - '0');
        }
    }
    if (p[0] == 'h' && p[1] == 'h')
        s.length = Length::hh, p += 2;
    else if (p[0] == 'l' && p[1] == 'l')
        s.length = Length::ll, p += 2;
    else if (*p == 'h')
        s.length = Length::h, ++p;
    else if (*p == 'l')
        s.length = Length::l, ++p;
    else if (*p == 'z')
        s.length = Length::z, ++p;
    else if (*p == 'j')
        s.length = Length::j, ++p;
    else if (*p == 't')
        s.length = Length::t, ++p;
    else if (*p == 'L')
        s.length = Length::L, ++p;
    if (*p != '\0') s.conversion = *p++;
    return s;
}

bool is_signed_conversion(char c) { return c == 'd' || c == 'i'; }
bool is_unsigned_conversion(char c) { return c == 'u' || c == 'x' || c == 'X' || c == 'o'; }
bool is_floating_conversion(char c) {
    return c == 'g' || c == 'G' || c == 'e' || c == 'E' || c == 'f' || c == 'F' || c == 'a' ||
           c == 'A';
}

std::int64_t read_signed(va_list& args, Length length) {
    switch (length) {
        case Length::l:
            return va_arg(args, long);
        case Length::ll:
            return va_arg(args, long long);
        case Length::z:
            return std::int64_t(va_arg(args, std::size_t));
        case Length::j:
            return va_arg(args, std::intmax_t);
        case Length::t:
            return va_arg(args, std::ptrdiff_t);
        default:
            return va_arg(args, int);
    }
}

std::uint64_t read_unsigned(va_list& args, Length length) {
    switch (length) {
        case Length::l:
            return va_arg(args, unsigned long);
        case Length::ll:
            return va_arg(args, unsigned long long);
        case Length::z:
            return va_arg(args, std::size_t);
        case Length::j:
            return va_arg(args, std::uintmax_t);
        case Length::t:
            return std::uint64_t(va_arg(args, std::ptrdiff_t));
        default:
            return va_arg(args, unsigned);
    }
}

// printf's narrowing for hh and h.
std::int64_t narrow_signed(std::int64_t v, Length length) {
    if (length == Length::hh) return static_cast<signed char>(v);
    if (length == Length::h) return static_cast<short>(v);
    return v;
}
std::uint64_t narrow_unsigned(std::uint64_t v, Length length) {
    if (length == Length::hh) return static_cast<unsigned char>(v);
    if (length == Length::h) return static_cast<unsigned short>(v);
    return v;
}

// A kept argument: an integer (signed or not), a double, or a string (in the arguments).
struct Item {
    std::uint64_t bits;  // integer value, or the double's bits
    int bytes;           // bytes it takes when kept: 4 or 8
};

Item make_integer(std::uint64_t v, bool is_signed) {
    bool fits = is_signed ? (std::int64_t(v) >= INT32_MIN && std::int64_t(v) <= INT32_MAX)
                          : v <= UINT32_MAX;
    return Item{v, fits ? 4 : 8};
}

Item make_double(double d) {
    float f = static_cast<float>(d);
    Item it{0, 8};
    if (static_cast<double>(f) == d) {  // exact as a float (never a NaN): 4 bytes
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        it.bits = u;
        it.bytes = 4;
    } else {
        std::memcpy(&it.bits, &d, 8);
    }
    return it;
}

int string_length(const char* s, int precision) {
    int n = 0;
    while (s[n] != '\0' && (precision < 0 || n < precision)) ++n;
    return n;
}

constexpr int kMaxStrings = 8;

// Walks the format once, reading every argument into the keeper (one function, not a
// template per pass: a firmware links one copy).
struct Keeper;
void keep_number(Keeper& k, const Item& it);
void keep_text(Keeper& k, const char* str, int n);

void walk_arguments(const char* format, va_list& args, Keeper& keeper) {
    for (const char* p = format; *p != '\0';) {
        if (*p++ != '%') continue;
        Spec s = parse_spec(p);
        if (s.width_star) keep_number(keeper, make_integer(std::uint64_t(va_arg(args, int)), true));
        if (s.precision_star) {
            int precision = va_arg(args, int);
            keep_number(keeper, make_integer(std::uint64_t(precision), true));
            s.number.precision = precision < 0 ? -1 : precision;
        }
        char c = s.conversion;
        if (is_signed_conversion(c) || c == 'c') {
            keep_number(keeper, make_integer(std::uint64_t(read_signed(args, s.length)), true));
        } else if (is_unsigned_conversion(c)) {
            keep_number(keeper, make_integer(read_unsigned(args, s.length), false));
        } else if (is_floating_conversion(c)) {
            double d =
                s.length == Length::L ? double(va_arg(args, long double)) : va_arg(args, double);
            keep_number(keeper, make_double(d));
        } else if (c == 'p') {
            keep_number(keeper,
                        make_integer(std::uint64_t(std::uintptr_t(va_arg(args, void*))), false));
        } else if (c == 's') {
            const char* str = va_arg(args, const char*);
            if (str == nullptr) str = "(null)";
            keep_text(keeper, str, string_length(str, s.number.precision));
        } else if (c == 'n') {
            (void)va_arg(args, int*);  // nothing is written back
        }
    }
}

// Max-min fair shares of `budget` bytes (each string needs length + 1 for its NUL).
void share_string_bytes(const int* need, int count, int budget, int* share) {
    bool settled[kMaxStrings] = {};
    int left = count;
    for (bool changed = true; changed && left > 0;) {
        changed = false;
        int cap = budget / left;
        for (int i = 0; i < count; ++i) {
            if (settled[i] || need[i] > cap) continue;
            share[i] = need[i];
            budget -= need[i];
            settled[i] = true;
            --left;
            changed = true;
        }
    }
    for (int i = 0, cap = left > 0 ? budget / left : 0; i < count; ++i)
        if (!settled[i]) share[i] = cap;
}

// The destination of message formatting: cut at capacity, counts the full length.
struct Text {
    char* out;
    int capacity;
    int length = 0;
    void put(char c) {
        if (length + 1 < capacity) out[length] = c;
        ++length;
    }
    char* room(int& bytes) {  // where a number may go, and how many bytes
        bytes = length < capacity ? capacity - length : 0;
        return bytes > 0 ? out + length : nullptr;
    }
};

void put_padded_text(Text& t, const char* s, int n, const NumberFormat& f) {
    int pad = f.width - n;
    if (!f.left)
        for (int i = 0; i < pad; ++i) t.put(' ');
    for (int i = 0; i < n; ++i) t.put(s[i]);
    if (f.left)
        for (int i = 0; i < pad; ++i) t.put(' ');
}

// Pass 1 (planning) measures: the bytes the numbers take, the length of every string.
// Pass 2 keeps them, in format order, until the bytes run out.
struct Keeper {
    bool planning = true;
    int number_bytes = 0, strings = 0;
    int need[kMaxStrings] = {}, share[kMaxStrings] = {};
    unsigned char* arguments = nullptr;
    std::uint32_t* narrow = nullptr;
    int capacity = 0, used = 0, index = 0, string_index = 0;
    bool full = false;
};

void keep_number(Keeper& k, const Item& it) {
    if (k.planning) {
        k.number_bytes += it.bytes;
        return;
    }
    if (k.full || k.used + it.bytes > k.capacity) {
        k.full = true;
        return;
    }
    if (it.bytes == 4) {
        std::uint32_t u = std::uint32_t(it.bits);
        std::memcpy(k.arguments + k.used, &u, 4);
        if (k.index < 32) *k.narrow |= 1u << k.index;
    } else {
        std::memcpy(k.arguments + k.used, &it.bits, 8);
    }
    k.used += it.bytes;
    ++k.index;
}

void keep_text(Keeper& k, const char* str, int n) {
    if (k.planning) {
        if (k.strings < kMaxStrings) k.need[k.strings] = n + 1;
        ++k.strings;
        return;
    }
    int room = k.string_index < kMaxStrings ? k.share[k.string_index] : 0;
    ++k.string_index;
    if (k.full || room < 1 || k.used + room > k.capacity) {
        k.full = true;
        return;
    }
    char* dst = reinterpret_cast<char*>(k.arguments + k.used);
    if (n + 1 <= room) {
        std::memcpy(dst, str, std::size_t(n));
        dst[n] = '\0';
        k.used += n + 1;
    } else {  // cut, marked with "..." when there is room for it
        int keep = room - 1;
        std::memcpy(dst, str, std::size_t(keep));
        for (int i = keep - 3 > 0 ? keep - 3 : 0; i < keep; ++i) dst[i] = '.';
        dst[keep] = '\0';
        k.used += room;
    }
    ++k.index;
}

// SHITSUKAN_STATUS_NO_ARGUMENTS (status.hpp): the arguments are not kept, so none of the
// keeping above is linked.
#if defined(SHITSUKAN_STATUS_NO_ARGUMENTS)
constexpr bool kKeepArguments = false;
#else
constexpr bool kKeepArguments = true;
#endif

}  // namespace

Status Status::error(StatusCode code, const char* format, ...) {
    Status s;
    s.code_ = code == StatusCode::ok ? StatusCode::invalid_argument : code;
    s.format_ = format != nullptr ? format : "(no message)";
    if (!kKeepArguments) return s;  // message(): the format, every conversion a '?'
    Keeper k;
    k.arguments = s.arguments_;
    k.narrow = &s.narrow_;
    k.capacity = kArgumentBytes;
    va_list args;
    va_start(args, format);
    walk_arguments(s.format_, args, k);
    va_end(args);
    const int budget = kArgumentBytes - k.number_bytes;
    share_string_bytes(k.need, k.strings < kMaxStrings ? k.strings : kMaxStrings,
                       budget > 0 ? budget : 0, k.share);
    k.planning = false;
    va_start(args, format);
    walk_arguments(s.format_, args, k);
    va_end(args);
    s.used_ = std::uint8_t(k.used);
    return s;
}

namespace {

// The kept arguments read back in the order the format asks for them; once one is missing
// (it did not fit when the Status was made) every later one prints as '?'.
struct KeptArguments {
    const unsigned char* bytes;
    int used;
    std::uint32_t narrow;  // bit i: the i-th argument is kept in 4 bytes
    int offset = 0, index = 0;
    bool missing = false;

    // The next number as 64 bits (a narrow float widened to double, a narrow integer extended).
    bool number(std::uint64_t& bits, bool is_signed, bool floating) {
        const bool is_narrow = index < 32 && (narrow >> index & 1u) != 0;
        const int size = is_narrow ? 4 : 8;
        if (missing || offset + size > used) {
            missing = true;
            return false;
        }
        if (is_narrow) {
            std::uint32_t u;
            std::memcpy(&u, bytes + offset, 4);
            if (floating) {
                float f;
                std::memcpy(&f, &u, 4);
                double d = f;
                std::memcpy(&bits, &d, 8);
            } else {
                bits = is_signed ? std::uint64_t(std::int64_t(std::int32_t(u))) : u;
            }
        } else {
            std::memcpy(&bits, bytes + offset, 8);
        }
        offset += size;
        ++index;
        return true;
    }

    // The next kept string (nullptr when missing) and its length.
    const char* string(int* length) {
        if (missing || offset >= used) {
            missing = true;
            return nullptr;
        }
        const char* str = reinterpret_cast<const char*>(bytes + offset);
        *length = string_length(str, -1);
        offset += *length + 1;
        ++index;
        return str;
    }
};

// One numeric conversion (d i u x X o c p and the floating ones) of a kept value.
void put_number_conversion(Text& t, char c, Spec& s, std::uint64_t bits) {
    const bool is_signed = is_signed_conversion(c) || c == 'c';
    int room = 0;
    if (c == 'c') {
        char ch = char(bits);
        put_padded_text(t, &ch, 1, s.number);
    } else if (c == 'p' && bits == 0) {
        put_padded_text(t, "(nil)", 5, s.number);
    } else if (is_floating_conversion(c)) {
        double d;
        std::memcpy(&d, &bits, 8);
        s.number.conversion = c == 'a' ? 'e' : c == 'A' ? 'E' : c;
        char* dst = t.room(room);
        t.length += format_double(dst, room, d, s.number);
    } else {
        bool negative = false;
        std::uint64_t magnitude = bits;
        if (is_signed) {
            std::int64_t v = narrow_signed(std::int64_t(bits), s.length);
            negative = v < 0;
            magnitude = negative ? 0u - std::uint64_t(v) : std::uint64_t(v);
        } else {
            magnitude = narrow_unsigned(bits, s.length);
        }
        s.number.conversion = c == 'p' ? 'x' : c == 'i' ? 'd' : c;
        if (c == 'p') s.number.alternate = true;
        char* dst = t.room(room);
        t.length += format_integer(dst, room, magnitude, negative, s.number);
    }
}

// The format with its conversions filled from the kept arguments.
void put_formatted(Text& t, const char* format, KeptArguments& kept) {
    for (const char* p = format; *p != '\0';) {
        if (*p != '%') {
            t.put(*p++);
            continue;
        }
        ++p;
        Spec s = parse_spec(p);
        std::uint64_t bits = 0;
        if (s.width_star && kept.number(bits, true, false)) {
            int w = int(std::int64_t(bits));
            s.number.left = s.number.left || w < 0;
            s.number.width = w < 0 ? -w : w;
        }
        if (s.precision_star && kept.number(bits, true, false)) {
            int w = int(std::int64_t(bits));
            s.number.precision = w < 0 ? -1 : w;
        }
        const char c = s.conversion;
        if (c == '%') {
            t.put('%');
        } else if (c == 's') {
            int n = 0;
            const char* str = kept.string(&n);
            if (str)
                put_padded_text(t, str, n, s.number);
            else
                t.put('?');
        } else if (is_signed_conversion(c) || is_unsigned_conversion(c) || c == 'c' || c == 'p' ||
                   is_floating_conversion(c)) {
            const bool is_signed = is_signed_conversion(c) || c == 'c';
            if (kept.number(bits, is_signed, is_floating_conversion(c)))
                put_number_conversion(t, c, s, bits);
            else
                t.put('?');
        } else if (c != 'n' && c != 0) {  // not a conversion printf knows: as written
            t.put('%');
            t.put(c);
        }
    }
}

}  // namespace

int Status::format_message(char* out, int capacity) const {
    Text t{out, capacity};
    if (ok()) {
        for (const char* c = "ok"; *c; ++c) t.put(*c);
    } else {
        KeptArguments kept{arguments_, used_, narrow_};
        put_formatted(t, format_, kept);
    }
    if (capacity > 0) out[t.length < capacity ? t.length : capacity - 1] = '\0';
    return t.length;
}

#if defined(SHITSUKAN_SMALL_DEVICE)
#define SHITSUKAN_STATUS_PER_THREAD  // one program, no threads: plain static buffers
#else
#define SHITSUKAN_STATUS_PER_THREAD thread_local
#endif

const char* Status::message() const {
    if (ok()) return "ok";
    static SHITSUKAN_STATUS_PER_THREAD char slots[kMessageSlots][kMessageCapacity];
    static SHITSUKAN_STATUS_PER_THREAD int next = 0;
    char* out = slots[next];
    next = (next + 1) % kMessageSlots;
    (void)format_message(out, kMessageCapacity);
    return out;
}

}  // namespace shitsukan
