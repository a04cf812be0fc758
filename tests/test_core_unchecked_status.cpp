// Tests for lib/shitsukan/core/assert.hpp's SHITSUKAN_REQUIRE_BUILT: an object used after its
// builder refused the caller's values (and the Status was ignored) aborts with a message that
// names the builder, not "internal check failed". Each case runs in a child process (POSIX
// fork) whose stderr is read back through a pipe.
#include <doctest/doctest.h>

#include <csignal>
#include <fcntl.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "shitsukan/solid/lattice_store.hpp"
#include "shitsukan/solid/lattice_type3.hpp"
#include "shitsukan/solid/turbulence.hpp"

using namespace shitsukan;

namespace {

struct ChildResult {
    bool aborted = false;
    std::string stderr_text;
};

// Runs body() in a child, returns whether it died of SIGABRT and what it wrote to stderr.
template <class F> ChildResult run_in_child(F body) {
    ChildResult r;
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        // The child dies by abort(): let it, without doctest's crash report (the parent
        // judges the child) and without writing to the parent's stdout.
        std::signal(SIGABRT, SIG_DFL);
        const int null_fd = open("/dev/null", O_WRONLY);
        if (null_fd >= 0) dup2(null_fd, 1);
        close(fds[0]);
        dup2(fds[1], 2);
        body();
        _exit(0);  // not reached when the check fires
    }
    close(fds[1]);
    char buf[512];
    ssize_t n;
    while ((n = read(fds[0], buf, sizeof buf)) > 0) r.stderr_text.append(buf, std::size_t(n));
    close(fds[0]);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    r.aborted = WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
    return r;
}

bool contains(const std::string& text, const char* part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("a refused FractalLattice::build() with its Status ignored aborts naming the call") {
    ChildResult r = run_in_child([] {
        FractalParams params;
        params.R = 40;  // refused: far beyond the memory budget
        FractalLattice lattice;
        (void)lattice.build(params);  // the user's mistake under test: the Status is dropped
        volatile float d = turbulence(lattice.view(), Vec3{1, 2, 3});
        (void)d;
    });
    CHECK(r.aborted);
    CHECK(contains(r.stderr_text, "FractalLattice::build()"));
    CHECK(contains(r.stderr_text, "Status it returned was ignored"));
    CHECK_FALSE(contains(r.stderr_text, "internal check failed"));
}

TEST_CASE("a refused TypeIIILattice::init() with its Status ignored aborts naming the call") {
    ChildResult r = run_in_child([] {
        FractalParams params;
        params.beta = -1.0f;  // refused: beta must be >= 0
        TypeIIILattice lattice;
        (void)lattice.init(params);
        volatile float d = lattice.turbulence(Vec3{1, 2, 3});
        (void)d;
    });
    CHECK(r.aborted);
    CHECK(contains(r.stderr_text, "TypeIIILattice::init()"));
    CHECK_FALSE(contains(r.stderr_text, "internal check failed"));
}

TEST_CASE("a checked, successful build does not trip the check") {
    ChildResult r = run_in_child([] {
        FractalParams params;
        params.R = 2;
        FractalLattice lattice;
        if (!lattice.build(params)) _exit(3);
        volatile float d = turbulence(lattice.view(), Vec3{1, 2, 3});
        (void)d;
    });
    CHECK_FALSE(r.aborted);
    CHECK(r.stderr_text.empty());
}
