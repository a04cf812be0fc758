// cli/main.cpp — `shitsukan`: the library's papers from the shell, for artists and teachers.
//
//   shitsukan marble -o marble.png                        okada1987 §4.1, a slice
//   shitsukan marble --obj vase.obj -o vase_marble.png    baked onto the OBJ's uv map
//   shitsukan leather --size 2048 -o croc                 tokai1994 §3: height + normal maps
//   shitsukan bark --species pine -o pine                 hirota1998 §3: crack map, SVG, CSV, OBJ
//   shitsukan <command> --help                            every flag, its default, the paper
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "commands.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/core/config.hpp"

namespace {

int usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: shitsukan <command> [flags]   (shitsukan <command> --help for its flags)\n"
                 "\n"
                 "commands (each cites its paper; see docs/TOOL.md):\n"
                 "  marble    okada1987 §4.1 / okada1989: 3D fractal marble, a slice or baked on an OBJ\n"
                 "  wood      okada1987 §4.2: 3D fractal wood, a slice or baked on an OBJ\n"
                 "  leather   tokai1994 §3: reptile scales (two-stage Voronoi), height/normal maps, OBJ\n"
                 "  wrinkly   fujimoto2000 §3-4: a WR or superposed surface from a control-mesh file\n"
                 "  bark      hirota1998 §3: growing and cracking bark of Table 2's three species\n"
                 "  ist       fujimoto2000 §2: the table of an Iterated Shuffle Transformation\n"
                 "  normals   a normal map from any height map (an image or PFM you give it)\n"
                 "  version   the library version\n");
    return out == stderr ? 2 : 0;
}

int run(int argc, char** argv) {
    using namespace shitsukan::cli;
    if (argc < 2) return usage(stderr);
    const char* c = argv[1];
    if (std::strcmp(c, "--help") == 0 || std::strcmp(c, "-h") == 0 || std::strcmp(c, "help") == 0)
        return usage(stdout);
    if (std::strcmp(c, "version") == 0 || std::strcmp(c, "--version") == 0) {
        std::printf("shitsukan %s\n", SHITSUKAN_VERSION_STRING);
        return 0;
    }
    if (std::strcmp(c, "marble") == 0) return run_solid(argc - 2, argv + 2, false);
    if (std::strcmp(c, "wood") == 0) return run_solid(argc - 2, argv + 2, true);
    if (std::strcmp(c, "leather") == 0) return run_leather(argc - 2, argv + 2);
    if (std::strcmp(c, "wrinkly") == 0) return run_wrinkly(argc - 2, argv + 2);
    if (std::strcmp(c, "bark") == 0) return run_bark(argc - 2, argv + 2);
    if (std::strcmp(c, "ist") == 0) return run_ist(argc - 2, argv + 2);
    if (std::strcmp(c, "normals") == 0) return run_normals(argc - 2, argv + 2);
    std::fprintf(stderr, "shitsukan: unknown command \"%s\" (marble, wood, leather, wrinkly, bark, "
                         "ist, normals, version; see shitsukan --help)\n", c);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    // Ctrl-C, kill or a hang-up while files are written: their temporaries are removed and
    // nothing appears under the requested names (core/output_file.hpp).
    shitsukan::remove_temporaries_on_signals();
    const int rc = run(argc, argv);
    // Standard output (ist's table, --help) is checked like every file: `ist > /dev/full` fails.
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "shitsukan: cannot write standard output: %s\n", std::strerror(errno));
        return rc == 0 ? 1 : rc;
    }
    return rc;
}
