// Tests for lib/shitsukan/core/output_file: every writer of the library reports a failed write
// with the path and the reason, a failed overwrite keeps the old file, no temporary survives a
// failure or a signal, and an OutputSet's files appear all together or not at all.
#include <doctest/doctest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "shitsukan/bark/bark.hpp"
#include "shitsukan/core/output_file.hpp"
#include "shitsukan/geom/mesh_builders.hpp"
#include "shitsukan/geom/obj.hpp"
#include "shitsukan/image/image_io.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/image/png16.hpp"
#include "shitsukan/image/svg_canvas.hpp"
#include "shitsukan/solid/lattice_store.hpp"

using namespace shitsukan;

namespace {

// A fresh directory under /tmp, removed with what is left in it.
struct TempDir {
    std::string path;
    TempDir() {
        char name[] = "/tmp/shitsukan_output_XXXXXX";
        REQUIRE(mkdtemp(name) != nullptr);
        path = name;
    }
    ~TempDir() {
        for (const std::string& n : names()) {
            const std::string p = path + "/" + n;
            if (std::remove(p.c_str()) != 0) rmdir(p.c_str());
        }
        rmdir(path.c_str());
    }
    std::string operator/(const char* name) const { return path + "/" + name; }
    std::vector<std::string> names() const {  // every entry, dot files included, sorted
        std::vector<std::string> out;
        if (DIR* d = opendir(path.c_str())) {
            while (dirent* e = readdir(d))
                if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
                    out.push_back(e->d_name);
            closedir(d);
        }
        std::sort(out.begin(), out.end());
        return out;
    }
};

std::string slurp(const std::string& path) {
    std::string bytes;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[4096];
        std::size_t n;
        while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.append(buf, n);
        std::fclose(f);
    }
    return bytes;
}

bool contains(const Status& s, const char* part) {
    return std::strstr(s.message(), part) != nullptr;
}

// The process's file-size limit lowered to `bytes` (writes past it fail with EFBIG, SIGXFSZ
// ignored) while it lives: the disk-full case without filling a disk.
struct FileSizeLimit {
    rlimit old{};
    void (*old_handler)(int) = SIG_DFL;
    explicit FileSizeLimit(rlim_t bytes) {
        REQUIRE(getrlimit(RLIMIT_FSIZE, &old) == 0);
        old_handler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit lower = old;
        lower.rlim_cur = bytes;
        REQUIRE(setrlimit(RLIMIT_FSIZE, &lower) == 0);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old);
        std::signal(SIGXFSZ, old_handler);
    }
};

RgbImage pattern(int w, int h) {
    RgbImage img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.at(x, y) = Rgb8{std::uint8_t(x * 7 + y), std::uint8_t(x ^ y), std::uint8_t(x * y)};
    return img;
}

}  // namespace

TEST_CASE("output_file: every writer reports /dev/full with the path and the reason") {
    const char* full = "/dev/full";
    RgbImage rgb = pattern(64, 64);
    GrayImage gray(64, 64, 7);
    Gray16Image g16(64, 64);
    std::vector<float> samples(64 * 64, 0.5f);
    TriangleMesh mesh;
    REQUIRE(make_torus(1.0f, 0.3f, 32, 16, mesh).ok());
    SvgCanvas svg(64, 64, Rgb8{255, 255, 255});
    FractalLattice lattice;
    FractalParams lp;
    lp.R = 3;
    REQUIRE(lattice.build(lp).ok());
    const Status results[] = {write_png(full, rgb.view()),   write_png(full, gray.view()),
                              write_ppm(full, rgb.view()),   write_pgm(full, gray.view()),
                              write_png16(full, g16.view()), write_pfm(full, samples.data(), 64, 64, 1),
                              write_obj(full, mesh),         svg.save(full),
                              save_lattice(full, lattice),   write_text_file(full, "x\n")};
    for (const Status& s : results) {
        CAPTURE(s.message());
        CHECK(s.code() == StatusCode::io_error);
        CHECK(contains(s, "/dev/full"));
        CHECK(contains(s, std::strerror(ENOSPC)));
    }
}

TEST_CASE("output_file: the reasons are named: missing directory, directory in the way") {
    TempDir dir;
    RgbImage rgb = pattern(8, 8);
    Status s = write_png((dir / "missing/x.png").c_str(), rgb.view());
    CHECK(s.code() == StatusCode::io_error);
    CHECK(contains(s, "missing/x.png"));
    CHECK(contains(s, std::strerror(ENOENT)));
    REQUIRE(mkdir((dir / "taken.png").c_str(), 0755) == 0);
    s = write_png((dir / "taken.png").c_str(), rgb.view());
    CHECK(contains(s, "taken.png"));
    CHECK(contains(s, std::strerror(EISDIR)));
    CHECK(write_png("", rgb.view()).code() == StatusCode::invalid_argument);
}

TEST_CASE("output_file: a failed overwrite keeps the old file and leaves no temporary") {
    TempDir dir;
    const std::string path = dir / "keep.png";
    REQUIRE(write_text_file(path.c_str(), "the old file\n").ok());
    RgbImage big = pattern(512, 512);  // about 100 KB compressed, 786 KB raw
    {
        FileSizeLimit limit(16 * 1024);
        const Status s = write_png(path.c_str(), big.view());
        CHECK(s.code() == StatusCode::io_error);
        CHECK(contains(s, std::strerror(EFBIG)));
        const Status p = write_pfm(path.c_str(), std::vector<float>(512 * 512).data(), 512, 512, 1);
        CHECK(contains(p, std::strerror(EFBIG)));
    }
    CHECK(slurp(path) == "the old file\n");
    CHECK(dir.names() == std::vector<std::string>{"keep.png"});
    // and a successful one replaces it, keeping the old file's mode
    REQUIRE(chmod(path.c_str(), 0640) == 0);
    REQUIRE(write_png(path.c_str(), big.view()).ok());
    struct stat st;
    REQUIRE(stat(path.c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == 0640);
    CHECK(slurp(path).compare(1, 3, "PNG") == 0);
    CHECK(dir.names() == std::vector<std::string>{"keep.png"});
}

TEST_CASE("output_file: an uncommitted file leaves nothing; devices are written in place") {
    TempDir dir;
    {
        OutputFile out;
        REQUIRE(out.open(dir / "never.txt").ok());
        out.print("%s\n", "half");
        CHECK(dir.names().size() == 1u);  // the temporary, under a dot name
        CHECK(dir.names()[0][0] == '.');
    }
    CHECK(dir.names().empty());
    CHECK(write_text_file("/dev/null", "discarded\n").ok());
    // a symbolic link stays a link; the file it points to is replaced
    REQUIRE(write_text_file((dir / "real.txt").c_str(), "old\n").ok());
    REQUIRE(symlink("real.txt", (dir / "link.txt").c_str()) == 0);
    REQUIRE(write_text_file((dir / "link.txt").c_str(), "new\n").ok());
    struct stat st;
    REQUIRE(lstat((dir / "link.txt").c_str(), &st) == 0);
    CHECK(S_ISLNK(st.st_mode));
    CHECK(slurp(dir / "real.txt") == "new\n");
}

TEST_CASE("output_file: an OutputSet writes all its files or none") {
    TempDir dir;
    const std::string a = dir / "a.txt", b = dir / "b.txt";
    REQUIRE(write_text_file(a.c_str(), "old a\n").ok());
    {  // a later file fails: the set is dropped, nothing changes
        OutputSet set;
        REQUIRE(write_text_file(a.c_str(), "new a\n").ok());
        REQUIRE(write_text_file(b.c_str(), "new b\n").ok());
        CHECK(slurp(a) == "old a\n");  // held until the set commits
        CHECK(write_text_file("/dev/full", "x").code() == StatusCode::io_error);
    }
    CHECK(slurp(a) == "old a\n");
    CHECK(dir.names() == std::vector<std::string>{"a.txt"});
    {  // a rename fails at commit (a directory took b's name): a is put back
        OutputSet set;
        REQUIRE(write_text_file(a.c_str(), "new a\n").ok());
        REQUIRE(write_text_file(b.c_str(), "new b\n").ok());
        REQUIRE(mkdir(b.c_str(), 0755) == 0);
        REQUIRE(write_text_file((b + "/inside").c_str(), "x").ok());
        const Status s = set.commit();
        CHECK(s.code() == StatusCode::io_error);
        CHECK(contains(s, "b.txt"));
        std::remove((b + "/inside").c_str());
        rmdir(b.c_str());
    }
    CHECK(slurp(a) == "old a\n");
    CHECK(dir.names() == std::vector<std::string>{"a.txt"});
    {  // nested sets: the inner one hands its files to the outer one
        OutputSet outer;
        REQUIRE(write_text_file(a.c_str(), "new a\n").ok());
        {
            OutputSet inner;
            REQUIRE(write_text_file(b.c_str(), "new b\n").ok());
            REQUIRE(inner.commit().ok());
        }
        CHECK(slurp(a) == "old a\n");
        CHECK(dir.names().size() == 3u);  // a.txt and two temporaries
        REQUIRE(outer.commit().ok());
    }
    CHECK(slurp(a) == "new a\n");
    CHECK(slurp(b) == "new b\n");
    CHECK(dir.names() == (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST_CASE("output_file: write_bark_csv writes its three files or none") {
    CylinderParams p;
    p.N_R = 8, p.N_H = 6;
    BarkCylinder bark;
    REQUIRE(build_cylinder(p, bark).ok());
    TempDir dir;
    REQUIRE(mkdir((dir / "t_triangles.csv").c_str(), 0755) == 0);  // the third file fails
    const Status s = write_bark_csv(bark, 0.0f, bark.net.W.data(), (dir / "t").c_str());
    CHECK(s.code() == StatusCode::io_error);
    CHECK(contains(s, "t_triangles.csv"));
    CHECK(dir.names() == std::vector<std::string>{"t_triangles.csv"});
    REQUIRE(rmdir((dir / "t_triangles.csv").c_str()) == 0);
    REQUIRE(write_bark_csv(bark, 0.0f, bark.net.W.data(), (dir / "t").c_str()).ok());
    CHECK(dir.names().size() == 3u);
}

TEST_CASE("output_file: SIGINT while a file is open removes its temporary") {
    TempDir dir;
    REQUIRE(write_text_file((dir / "x.txt").c_str(), "old\n").ok());
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        remove_temporaries_on_signals();
        OutputFile held, open;
        OutputSet set;
        if (!held.open(dir / "y.txt").ok()) _exit(3);
        held.print("complete\n");
        if (!held.commit().ok()) _exit(4);  // held by the set, under its temporary name
        if (!open.open(dir / "x.txt").ok()) _exit(5);
        open.print("half\n");
        raise(SIGINT);
        _exit(6);  // not reached
    }
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGINT);
    CHECK(slurp(dir / "x.txt") == "old\n");
    CHECK(dir.names() == std::vector<std::string>{"x.txt"});
}
