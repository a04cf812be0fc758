// cli/flags.cpp — see flags.hpp.
#include "flags.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <sys/stat.h>  // stat (POSIX)
#include <unistd.h>    // isatty (POSIX)

namespace shitsukan::cli {

bool parse_double(const char* text, double* out) {
    if (text == nullptr || !*text) return false;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !std::isfinite(v)) return false;
    *out = v;
    return true;
}

bool parse_long(const char* text, long* out) {
    if (text == nullptr || !*text) return false;
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE) return false;
    *out = v;
    return true;
}

FlagSet::FlagSet(const char* command, const char* about, const char* usage)
    : command_(command), about_(about), usage_(usage) {
    toggle("quiet", &quiet_, "no progress line on stderr");
}

void FlagSet::add(Flag f) { flags_.push_back(std::move(f)); }

void FlagSet::number(const char* name, float* value, double lo, double hi, const char* help) {
    char d[48];
    std::snprintf(d, sizeof d, "%g", double(*value));
    add(Flag{name, Kind::number, value, lo, hi, "", help, d});
}

void FlagSet::integer(const char* name, int* value, long lo, long hi, const char* help) {
    add(Flag{name, Kind::integer, value, double(lo), double(hi), "", help, std::to_string(*value)});
}

void FlagSet::seed(std::uint32_t* value, const char* help) {
    add(Flag{"seed", Kind::seed, value, 0, 4294967295.0, "", help, std::to_string(*value)});
}

void FlagSet::text(const char* name, std::string* value, const char* help) {
    add(Flag{name, Kind::text, value, 0, 0, "", help, value->empty() ? "none" : *value});
}

void FlagSet::choice(const char* name, int* value, const char* choices, const char* help) {
    std::string c = choices, d;
    std::size_t start = 0;
    for (int i = 0; i <= *value; ++i) {
        const std::size_t bar = c.find('|', start);
        d = c.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
        start = bar + 1;
    }
    add(Flag{name, Kind::choice, value, 0, 0, c, help, d});
}

void FlagSet::toggle(const char* name, bool* value, const char* help) {
    add(Flag{name, Kind::toggle, value, 0, 0, "", help, *value ? "on" : "off"});
}

bool FlagSet::given(const char* name) const {
    for (const Flag& f : flags_)
        if (f.name == name) return f.given;
    return false;
}

int FlagSet::fail(const char* format, ...) const {
    std::fprintf(stderr, "shitsukan %s: ", command_);
    va_list args;
    va_start(args, format);
    std::vfprintf(stderr, format, args);
    va_end(args);
    std::fprintf(stderr, "\n");
    return 2;
}

namespace {

bool ends_with_nocase(const std::string& s, const char* tail) {
    const std::size_t n = std::strlen(tail);
    if (s.size() < n) return false;
    for (std::size_t i = 0; i < n; ++i)
        if (std::tolower((unsigned char)s[s.size() - n + i]) != std::tolower((unsigned char)tail[i]))
            return false;
    return true;
}

std::string flag_name(const char* flag) {
    return std::strcmp(flag, "o") == 0 ? "-o" : std::string("--") + flag;
}

}  // namespace

int FlagSet::check_output(const char* flag, const std::string& path, const char* extension) const {
    if (ends_with_nocase(path, extension) && path.size() > std::strlen(extension)) return 0;
    struct stat st;  // a device or a FIFO (/dev/stdout, /dev/null) takes any bytes
    if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) return 0;
    return fail("%s must name a %s file (got \"%s\")", flag_name(flag).c_str(), extension,
                path.c_str());
}

int FlagSet::check_prefix(const char* flag, const std::string& prefix) const {
    static const char* const kFileKinds[] = {".png", ".jpg", ".jpeg", ".gif", ".bmp", ".tga",
                                             ".tif", ".tiff", ".webp", ".exr", ".hdr", ".pfm",
                                             ".ppm", ".pgm", ".svg", ".obj", ".csv", ".ply"};
    for (const char* kind : kFileKinds)
        if (ends_with_nocase(prefix, kind))
            return fail("%s is the prefix of the files written (<prefix>_...), not a %s file "
                        "(got \"%s\")", flag_name(flag).c_str(), kind, prefix.c_str());
    return 0;
}

void add_map_flags(FlagSet& f, MapFlags& maps) {
    f.text("o", &maps.prefix,
           "prefix of the map set: <o>_albedo.png, _height16.png, _height.exr, _normal.png, "
           "_roughness.png, _ao.png");
    f.choice("normal", &maps.normal, "opengl|directx",
             "normal map convention (directx: green flipped, 255 - g)");
    f.choice("float", &maps.floats, "exr|pfm|both", "format of the float height map");
    f.number("strength", &maps.strength, 0, 1e4,
             "normal and AO: pixels of relief for the full height range");
    f.number("ao-radius", &maps.ao_radius, 1, 4096,
             "ambient occlusion: how far, in pixels, a ridge shades a texel");
}

int check_map_flags(const FlagSet& f, const MapFlags& maps) {
    return f.check_prefix("o", maps.prefix);
}

MapSetOptions map_set_options(const MapFlags& maps, bool tileable) {
    MapSetOptions o;
    o.strength = maps.strength;
    o.normal = maps.normal == 1 ? NormalConvention::directx : NormalConvention::opengl;
    o.wrap = tileable;
    o.ao_radius = maps.ao_radius;
    o.exr = maps.floats != 1;
    o.pfm = maps.floats != 0;
    return o;
}

int write_maps(const FlagSet& f, const MapFlags& maps, const MapSetInput& input,
               const MapSetOptions& options, std::vector<std::string>* written) {
    std::vector<std::string> names;
    const Status s = write_map_set(maps.prefix.c_str(), input, options, names);
    if (!s) return f.fail_status(s);
    if (written) written->insert(written->end(), names.begin(), names.end());
    return 0;
}

int FlagSet::fail_status(const Status& s) const {
    std::fprintf(stderr, "shitsukan %s: %s\n", command_, s.message());
    return 1;
}

void FlagSet::print_help() const {
    std::printf("usage: %s\n\n%s\n\nflags (default in brackets):\n", usage_, about_);
    for (const Flag& f : flags_) {
        std::string left = (f.name == "o" ? "-o" : "--" + f.name);
        char range[96] = "";
        if (f.kind == Kind::number || f.kind == Kind::integer)
            std::snprintf(range, sizeof range, " in [%g, %g]", f.lo, f.hi);
        if (f.kind == Kind::choice) left += " " + f.choices;
        else if (f.kind != Kind::toggle) left += " X";
        std::printf("  %-26s %s%s [%s]\n", left.c_str(), f.help.c_str(), range,
                    f.default_text.c_str());
    }
    std::printf("  %-26s this text\n", "--help");
}

int FlagSet::parse(int argc, char** argv) {
    for (int i = 0; i < argc; ++i) {
        const char* arg = argv[i];
        if (std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0) {
            print_help();
            return 0;
        }
        std::string name;
        const char* value = nullptr;
        if (std::strcmp(arg, "-o") == 0) {
            name = "o";
        } else if (std::strncmp(arg, "--", 2) == 0 && arg[2]) {
            name = arg + 2;
            const std::size_t eq = name.find('=');
            if (eq != std::string::npos) {
                value = arg + 2 + eq + 1;
                name.resize(eq);
            }
        } else {
            return fail("unexpected argument \"%s\" (flags start with --; see --help)", arg);
        }
        Flag* flag = nullptr;
        for (Flag& f : flags_)
            if (f.name == name) flag = &f;
        if (!flag) return fail("unknown flag %s (see shitsukan %s --help)", arg, command_);
        if (flag->kind == Kind::toggle) {
            if (value) return fail("--%s takes no value", name.c_str());
            *static_cast<bool*>(flag->value) = true;
            flag->given = true;
            continue;
        }
        const std::string shown = name == "o" ? "-o" : "--" + name;
        if (!value) {
            if (i + 1 >= argc) return fail("%s needs a value", shown.c_str());
            value = argv[++i];
        }
        flag->given = true;
        switch (flag->kind) {
        case Kind::number: {
            double v;
            if (!parse_double(value, &v) || v < flag->lo || v > flag->hi)
                return fail("%s must be a number in [%g, %g] (got \"%s\")", shown.c_str(),
                            flag->lo, flag->hi, value);
            *static_cast<float*>(flag->value) = float(v);
            break;
        }
        case Kind::integer: {
            long v;
            if (!parse_long(value, &v) || double(v) < flag->lo || double(v) > flag->hi)
                return fail("%s must be an integer in [%g, %g] (got \"%s\")", shown.c_str(),
                            flag->lo, flag->hi, value);
            *static_cast<int*>(flag->value) = int(v);
            break;
        }
        case Kind::seed: {
            long v;
            if (!parse_long(value, &v) || v < 0 || double(v) > flag->hi)
                return fail("--seed must be an integer in [0, 4294967295] (got \"%s\")", value);
            *static_cast<std::uint32_t*>(flag->value) = std::uint32_t(v);
            break;
        }
        case Kind::text:
            if (!*value) return fail("%s needs a non-empty value", shown.c_str());
            *static_cast<std::string*>(flag->value) = value;
            break;
        case Kind::choice: {
            int index = 0;
            std::size_t start = 0;
            bool found = false;
            while (true) {
                const std::size_t bar = flag->choices.find('|', start);
                const std::string c = flag->choices.substr(
                    start, bar == std::string::npos ? std::string::npos : bar - start);
                if (c == value) {
                    found = true;
                    break;
                }
                if (bar == std::string::npos) break;
                start = bar + 1;
                ++index;
            }
            if (!found)
                return fail("%s must be one of %s (got \"%s\")", shown.c_str(),
                            flag->choices.c_str(), value);
            *static_cast<int*>(flag->value) = index;
            break;
        }
        case Kind::toggle:
            break;
        }
    }
    return kParsed;
}

namespace {
struct ProgressState {
    const char* command;
    const std::string* stage;
    int last;
    bool tty;
};
void show_progress(float fraction, void* user) {
    auto* st = static_cast<ProgressState*>(user);
    // A terminal gets one line rewritten in place (every percent); a log or a pipe gets a
    // line every 25 % (chosen: readable logs).
    const int step = st->tty ? 1 : 25;
    const int percent = int(fraction * 100.0f + 0.5f) / step * step;
    if (percent <= st->last) return;
    st->last = percent;
    if (st->tty)
        std::fprintf(stderr, "\rshitsukan %s: %s %3d%%%s", st->command, st->stage->c_str(),
                     percent, percent >= 100 ? "\n" : "");
    else
        std::fprintf(stderr, "shitsukan %s: %s %d%%\n", st->command, st->stage->c_str(), percent);
    std::fflush(stderr);
}
ProgressState g_state;
}  // namespace

Progress FlagSet::progress(const char* stage) {
    if (quiet_) return Progress{};
    stage_ = stage;
    g_state = ProgressState{command_, &stage_, -1, isatty(fileno(stderr)) != 0};
    return Progress{show_progress, &g_state};
}

}  // namespace shitsukan::cli
