// Host side: the alpha^0 -> alpha^K table of an IST (ist_table.hpp).
#include "shitsukan/wrinkly/ist_table.hpp"

#include <cstdio>
#include <cstring>

#include "shitsukan/wrinkly/ist_digits.hpp"

namespace shitsukan {

Status ist_table(const IstAxis& axis, const IstTableOptions& options, IstTableLine line,
                 void* user) {
    if (line == nullptr)
        return Status::error(StatusCode::invalid_argument, "ist_table: no line function");
    SHITSUKAN_TRY(ist_validate(axis));
    const std::uint64_t count = ist_sub_interval_count(axis);
    // count (up to 2^53) times B (up to 2^20) can wrap a 64-bit integer: compare by division.
    if (count > options.max_lines / std::uint64_t(axis.base_intervals))
        return Status::error(StatusCode::too_large,
                             "ist_table: N^K x B = %llu x %d pairs is over the limit of %llu "
                             "lines; lower N, K or B",
                             static_cast<unsigned long long>(count), axis.base_intervals,
                             static_cast<unsigned long long>(options.max_lines));
    const bool connected = axis.kind != IstKind::unit;
    const char* name = options.name != nullptr ? options.name
                       : axis.kind == IstKind::unit ? "unit"
                       : axis.kind == IstKind::fully_connected ? "fully"
                                                                : "connected";
    char text[32 * 16 + 64];
    int used = std::snprintf(text, sizeof text, "# fujimoto2000 IST (%s), N = %d, K = %d", name,
                             axis.n, axis.iterations);
    if (connected)
        std::snprintf(text + used, sizeof text - std::size_t(used), ", %d base intervals (%s axis)",
                      axis.base_intervals,
                      axis.ends == IstEnds::cyclic ? "cyclic" : "translation");
    line(text, user);
    line(options.inverse ? "# alpha^K alpha^0" : "# alpha^0 alpha^K", user);
    if (connected) {
        used = std::snprintf(text, sizeof text, "# external shuffle (group:offset slot):");
        for (int g = 0; g < axis.n && used < int(sizeof text) - 16; ++g)
            used += std::snprintf(text + used, sizeof text - std::size_t(used), " %d:%+d %d", g,
                                  axis.shuffle.offset[g], axis.shuffle.slot[g]);
        line(text, user);
    }
    // A unit-IST on one base interval is written with its digits only, as in fig. 3.
    const bool plain = !connected && axis.base_intervals == 1;
    char left[96], right[96];
    for (int b = 0; b < axis.base_intervals; ++b)
        for (std::uint64_t i = 0; i < count; ++i) {
            IstDigits a, image;
            ist_digits_from_index(axis, b, i, &a);
            if (options.inverse)
                ist_digits_inverse(axis, a, &image);
            else
                ist_digits_forward(axis, a, &image);
            ist_digits_format(a, options.first, left, sizeof left);
            ist_digits_format(image, options.first, right, sizeof right);
            const char* l = plain && std::strchr(left, '.') ? std::strchr(left, '.') + 1 : left;
            const char* r = plain && std::strchr(right, '.') ? std::strchr(right, '.') + 1 : right;
            std::snprintf(text, sizeof text, "%s %s", l, r);
            line(text, user);
        }
    return Status::success();
}

}  // namespace shitsukan
