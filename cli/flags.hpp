// cli/flags.hpp — the flags of one `shitsukan` subcommand: every paper parameter under the
// paper's name, with its default and range; `--help` prints them with the paper's section.
//
//   FlagSet f("marble", "okada1987 §4.1 marble ...", "usage line");
//   f.number("k", &k, 0, 1000, "okada1987 eq. (9): contribution of the turbulence");
//   int rc = f.parse(argc, argv);    // kParsed, 0 after --help, 2 on a bad flag (message printed)
//
// A bad flag or value prints ONE line to stderr naming the flag and its range, e.g.
//   shitsukan marble: --k must be a number in [0, 1000] (got "abc")
// and the command exits with 2. Values: "--name value" or "--name=value"; switches take none.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/image/map_set.hpp"

namespace shitsukan::cli {

constexpr int kParsed = -1;

class FlagSet {
public:
    FlagSet(const char* command, const char* about, const char* usage);
    void number(const char* name, float* value, double lo, double hi, const char* help);
    void integer(const char* name, int* value, long lo, long hi, const char* help);
    void seed(std::uint32_t* value, const char* help);
    void text(const char* name, std::string* value, const char* help);
    // choices: "a|b|c"; *value is the index of the chosen one
    void choice(const char* name, int* value, const char* choices, const char* help);
    void toggle(const char* name, bool* value, const char* help);

    int parse(int argc, char** argv);
    bool given(const char* name) const;
    // One line "shitsukan <command>: <message>" on stderr; returns 2.
    int fail(const char* format, ...) const;
    // Output names (0 when fine, else 2 with one line naming the flag): a file flag must end
    // in the one extension the command writes ("-o must name a .png file (got "x.jpg")") or
    // name a device or FIFO (/dev/stdout); a
    // prefix flag (the command adds "_height16.png" and the like) must not end in one.
    int check_output(const char* flag, const std::string& path, const char* extension) const;
    int check_prefix(const char* flag, const std::string& prefix) const;
    // A library error: "shitsukan <command>: <message>"; returns 1.
    int fail_status(const Status& s) const;
    const char* command() const { return command_; }
    bool quiet() const { return quiet_; }
    // A progress line on stderr ("shitsukan marble: baking  42%"), unless --quiet.
    Progress progress(const char* stage);

private:
    enum class Kind { number, integer, seed, text, choice, toggle };
    struct Flag {
        std::string name;
        Kind kind;
        void* value;
        double lo = 0, hi = 0;
        std::string choices, help, default_text;
        bool given = false;
    };
    void add(Flag f);
    void print_help() const;
    const char* command_;
    const char* about_;
    const char* usage_;
    std::vector<Flag> flags_;
    bool quiet_ = false;
    std::string stage_;
};

// The map set, one -o convention for every material command (marble, wood, leather, bark,
// wrinkly): -o is a PREFIX and the maps are <prefix>_albedo.png, _height16.png, _height.exr
// (and/or _height.pfm), _normal.png, _roughness.png, _ao.png (image/map_set.hpp says how each
// is derived). A prefix ending in a file extension ("-o out.jpg") is refused with exit 2.
//   MapFlags maps;  maps.prefix = "marble";  maps.strength = 2.0f;   // the command's defaults
//   add_map_flags(f, maps);                  // -o, --normal, --float, --strength, --ao-radius
//   ... f.parse ...;  if (int e = check_map_flags(f, maps)) return e;
//   MapSetOptions o = map_set_options(maps, tileable);
//   OutputSet files;  if (int e = write_maps(f, maps, input, o)) return e;  then files.commit()
struct MapFlags {
    std::string prefix;
    int normal = 0;  // 0 opengl, 1 directx
    int floats = 0;  // 0 exr, 1 pfm, 2 both
    float strength = 4.0f;
    float ao_radius = 16.0f;
};
void add_map_flags(FlagSet& f, MapFlags& maps);
int check_map_flags(const FlagSet& f, const MapFlags& maps);
MapSetOptions map_set_options(const MapFlags& maps, bool tileable);
// Writes the set (inside the caller's OutputSet); 0, or 1 with the library's message. The
// names written are appended to *written when it is given.
int write_maps(const FlagSet& f, const MapFlags& maps, const MapSetInput& input,
               const MapSetOptions& options, std::vector<std::string>* written = nullptr);

// Whole-string number parsing (no trailing junk, finite).
bool parse_double(const char* text, double* out);
bool parse_long(const char* text, long* out);

}  // namespace shitsukan::cli
