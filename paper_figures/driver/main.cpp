// build/paper_figures — runs the registered paper figures and writes an index.
//
//   build/paper_figures [--list] [--only <paper>/<id> | --only <paper>] [--out DIR]
//                       [--quick | --full] [--jobs N]
//
// Writes DIR/<paper>/<id>.png (or .md for tables) and DIR/index.md (image, caption,
// parameter table marking each value given/chosen, wall time). Default DIR:
// paper_figures/out. Exit status: 0 when every figure ran, 1 when one failed, 2 on bad usage.
//
// --jobs N renders N figures at once on N threads (default: the number of cores). The files
// are the same bytes whatever N is, and so is the index (in registry order) apart from the
// measured times; the longest figures start first (kLongFirst below), and a figure registered
// with SHITSUKAN_FIGURE_AFTER waits for the figures it reads, and one registered with
// SHITSUKAN_FIGURE_PARTS runs as independent part jobs (on any thread) and an assembling job.
// The last line gives the total wall time and the process's CPU time (user + sys).
//
// --quick: the CI smoke run (small sizes). --full: the paper's own counts where a figure
// chose fewer for the default run (the figure's parameters and notes say which and why).
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "driver/figure.hpp"
#include "shitsukan/core/output_file.hpp"

using namespace shitsukan;
using namespace shitsukan::figures;

namespace {

void make_dir(const std::string& path) {
    std::string partial;
    for (std::size_t i = 0; i <= path.size(); ++i) {
        if (i == path.size() || path[i] == '/') {
            if (!partial.empty()) mkdir(partial.c_str(), 0755);
        }
        if (i < path.size()) partial += path[i];
    }
}

std::string escape_cell(std::string s) {
    std::string r;
    for (char c : s) {
        if (c == '|')
            r += "\\|";
        else if (c == '\n')
            r += ' ';
        else
            r += c;
    }
    return r;
}

struct Result {
    FigureSpec spec;
    bool ok;
    std::string error;
    double seconds;
    std::vector<Parameter> parameters;
    std::vector<std::string> notes, outputs;
};

// The long poles of a full run, longest first (measured: per-figure CPU seconds printed by
// this driver, median of full runs with --jobs 2). They start before everything else so that
// no long figure is left alone at the end; the others follow in registry order.
const char* const kLongFirst[] = {
    "fujimoto2000/fig22",   "hirota1998/fig05",     "fujimoto2000/fig23",
    "hirota1998/fig06",     "okada1989/table-types", "fujimoto2000/table01",
    "fujimoto2000/fig21f",  "okada1987/table01",    "fujimoto2000/fig18b5",
    "tokai1994/fig18",      "fujimoto2000/fig18b4", "tokai1994/fig15c",
    "tokai1994/fig14c",     "fujimoto2000/fig21d",  "fujimoto2000/fig18a5",
    "fujimoto2000/fig18a4", "fujimoto2000/fig21g",  "tokai1994/fig13c",
    "fujimoto2000/fig21e",  "hirota1998/fig04",     "tokai1994/fig19"};

std::string key_of(const FigureSpec& s) { return std::string(s.paper) + "/" + s.id; }

std::vector<std::size_t> schedule_order(const std::vector<FigureSpec>& figures) {
    std::vector<std::size_t> order;
    std::vector<bool> taken(figures.size(), false);
    for (const char* key : kLongFirst)
        for (std::size_t i = 0; i < figures.size(); ++i)
            if (!taken[i] && key_of(figures[i]) == key) {
                order.push_back(i);
                taken[i] = true;
            }
    for (std::size_t i = 0; i < figures.size(); ++i)
        if (!taken[i]) order.push_back(i);
    return order;
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double process_cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Runs the figures on `jobs` threads. A figure waits until every figure of its paper whose
// id starts with its `after` prefix is done. A figure registered with parts runs as that many
// part jobs, then an assembling job once they are all done; its time is the sum of its jobs.
class Scheduler {
public:
    Scheduler(const std::vector<FigureSpec>& figures, std::string out, bool quick, bool full)
        : figures_(figures),
          out_(std::move(out)),
          quick_(quick),
          full_(full),
          done_(figures.size(), false),
          kept_(figures.size()),
          cost_(figures.size()),
          results_(figures.size()) {
        for (std::size_t i : schedule_order(figures)) {
            const int parts = figures[i].parts > 1 ? figures[i].parts : 0;
            kept_[i].resize(std::size_t(parts));
            for (int p = 0; p < parts; ++p) jobs_.push_back({i, p});
            jobs_.push_back({i, -1});
        }
        state_.assign(jobs_.size(), State::pending);
    }

    std::vector<Result> run(int jobs) {
        std::vector<std::thread> threads;
        for (int t = 1; t < jobs; ++t) threads.emplace_back([this] { work(); });
        work();
        for (std::thread& t : threads) t.join();
        return results_;
    }

private:
    enum class State { pending, running, done };
    struct Job {
        std::size_t figure;
        int part;  // 0 .. parts - 1, or -1: the whole figure (or its assembling call)
    };
    struct Cost {
        double seconds = 0.0, cpu = 0.0;
        std::string error;  // of a failed part
    };

    bool ready(const Job& job, std::size_t index) const {
        const FigureSpec& s = figures_[job.figure];
        if (job.part < 0)  // the assembling call follows the figure's parts (listed before it)
            for (std::size_t k = index; k-- > 0 && jobs_[k].figure == job.figure;)
                if (state_[k] != State::done) return false;
        if (!s.after) return true;
        const std::size_t n = std::strlen(s.after);
        for (std::size_t j = 0; j < figures_.size(); ++j)
            if (j != job.figure && std::strcmp(figures_[j].paper, s.paper) == 0 &&
                std::strncmp(figures_[j].id, s.after, n) == 0 && !done_[j])
                return false;
        return true;
    }

    std::string job_name(const Job& job) const {
        const FigureSpec& s = figures_[job.figure];
        std::string name = std::string(s.paper) + "/" + s.id;
        if (job.part >= 0) name += fmt(" part %d/%d", job.part + 1, s.parts);
        return name;
    }

    // The counters count figures, as the summary line does: a figure with parts is announced
    // when its first part starts ("(N parts)"), its parts' times follow indented, and it is
    // counted as finished once its assembling job is.
    void announce(const Job& job) {
        const FigureSpec& s = figures_[job.figure];
        if (started_figure_[job.figure]) return;
        started_figure_[job.figure] = true;
        ++started_;
        std::string name = std::string(s.paper) + "/" + s.id;
        if (s.parts > 1) name += fmt(" (%d parts)", s.parts);
        std::printf("[%zu/%zu] %s ...\n", started_, figures_.size(), name.c_str());
        std::fflush(stdout);
    }

    // The next job to run, or jobs_.size() when none is left.
    std::size_t next() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            bool pending = false;
            for (std::size_t k = 0; k < jobs_.size(); ++k) {
                if (state_[k] != State::pending) continue;
                pending = true;
                if (ready(jobs_[k], k)) {
                    state_[k] = State::running;
                    announce(jobs_[k]);
                    return k;
                }
            }
            if (!pending) return jobs_.size();
            changed_.wait(lock);
        }
    }

    // Runs one job; its kept results go to kept_ (a part) or the figure's result is made.
    void run_job(std::size_t k) {
        const Job job = jobs_[k];
        const FigureSpec& s = figures_[job.figure];
        FigureContext ctx(out_, s.paper, s.id, quick_, full_);
        ctx.set_part(job.part);
        std::string failed_part;
        if (job.part < 0 && s.parts > 1) {
            std::lock_guard<std::mutex> lock(mutex_);
            ctx.set_kept_parts(std::move(kept_[job.figure]));
            failed_part = cost_[job.figure].error;
        }
        const double c0 = thread_cpu_seconds();
        auto t0 = std::chrono::steady_clock::now();
        Status st = failed_part.empty() ? s.run(ctx)
                                        : Status::error(StatusCode::io_error, "%s",
                                                        failed_part.c_str());
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = thread_cpu_seconds() - c0;
        if (st.ok() && job.part < 0 && ctx.outputs().empty())
            st = Status::error(StatusCode::io_error, "figure wrote no output");
        std::lock_guard<std::mutex> lock(mutex_);
        Cost& cost = cost_[job.figure];
        cost.seconds += secs;
        cost.cpu += cpu;
        std::string counter = "     ";  // a part: indented under its figure, not counted
        if (job.part < 0) counter = fmt("[%zu/%zu]", ++finished_, figures_.size());
        if (st.ok())
            std::printf("%s %s ... %.2f s (CPU %.2f s)\n", counter.c_str(), job_name(job).c_str(),
                        job.part < 0 ? cost.seconds : secs, job.part < 0 ? cost.cpu : cpu);
        else
            std::printf("%s %s ... FAILED (%s)\n", counter.c_str(), job_name(job).c_str(),
                        st.message());
        std::fflush(stdout);
        if (job.part >= 0) {
            kept_[job.figure][std::size_t(job.part)] = ctx.take_kept();
            if (!st.ok() && cost.error.empty())
                cost.error = fmt("part %d: %s", job.part + 1, st.message());
        } else {
            results_[job.figure] = {s,           st.ok(),      st.message(), cost.seconds,
                                    ctx.parameters(), ctx.notes(), ctx.outputs()};
            done_[job.figure] = true;
        }
        state_[k] = State::done;
        changed_.notify_all();
    }

    void work() {
        for (std::size_t k = next(); k < jobs_.size(); k = next()) run_job(k);
    }

    const std::vector<FigureSpec>& figures_;
    std::string out_;
    bool quick_, full_;
    std::vector<bool> done_;  // per figure
    std::vector<bool> started_figure_ = std::vector<bool>(figures_.size(), false);
    std::vector<std::vector<std::vector<std::string>>> kept_;  // per figure, per part
    std::vector<Cost> cost_;                                   // per figure
    std::vector<Job> jobs_;                                    // in the order they start
    std::vector<State> state_;                                 // per job
    std::vector<Result> results_;
    std::size_t started_ = 0, finished_ = 0;
    std::mutex mutex_;
    std::condition_variable changed_;
};

bool write_index(const std::string& out, const std::vector<Result>& results, bool quick) {
    std::string p = out + "/index.md";
    OutputFile f;  // core/output_file.hpp: complete or not there, failures with the reason
    Status s = f.open(p);
    if (!s) {
        std::fprintf(stderr, "paper_figures: %s\n", s.message());
        return false;
    }
    f.print("# shitsukan paper figures\n\nGenerated by `build/paper_figures%s`. "
            "Each figure lists its parameters: *given* by the paper (with where) or "
            "*chosen* here (with why). Times are wall-clock on the machine that ran it.\n\n",
            quick ? " --quick" : "");
    std::string paper;
    for (const Result& r : results) {
        if (paper != r.spec.paper) {
            paper = r.spec.paper;
            f.print("## %s\n\n", paper.c_str());
        }
        f.print("### %s/%s\n\n%s\n\n", r.spec.paper, r.spec.id, r.spec.caption);
        for (const std::string& o : r.outputs) {
            if (o.size() > 4 && o.compare(o.size() - 4, 4, ".png") == 0)
                f.print("![%s](%s/%s)\n\n", r.spec.id, r.spec.paper, o.c_str());
            else
                f.print("Output: [%s](%s/%s)\n\n", o.c_str(), r.spec.paper, o.c_str());
        }
        if (!r.parameters.empty()) {
            f.print("| parameter | value | given / chosen | where / why |\n|---|---|---|---|\n");
            for (const Parameter& q : r.parameters)
                f.print("| %s | %s | %s | %s |\n", escape_cell(q.name).c_str(),
                        escape_cell(q.value).c_str(), q.given ? "given" : "chosen here",
                        escape_cell(q.source).c_str());
            f.print("\n");
        }
        for (const std::string& n : r.notes) f.print("%s\n\n", n.c_str());
        if (r.ok)
            f.print("Wall time: %.3f s\n\n", r.seconds);
        else
            f.print("**FAILED**: %s\n\n", r.error.c_str());
    }
    s = f.commit();
    if (!s) std::fprintf(stderr, "paper_figures: %s\n", s.message());
    return s.ok();
}

void usage() {
    std::fprintf(stderr,
                 "usage: paper_figures [--list] [--only <paper>[/<id>]]... [--out DIR] [--quick | --full] "
                 "[--jobs N]\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "paper_figures/out";
    std::vector<std::string> only;
    bool list = false, quick = false, full = false;
    int jobs = int(std::thread::hardware_concurrency());
    if (jobs < 1) jobs = 1;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--list")
            list = true;
        else if (a == "--quick")
            quick = true;
        else if (a == "--full")
            full = true;
        else if (a == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (a == "--jobs" && i + 1 < argc) {
            char* end = nullptr;
            const long n = std::strtol(argv[++i], &end, 10);
            if (!end || *end != '\0' || n < 1 || n > 256) {
                std::fprintf(stderr, "paper_figures: --jobs wants a number from 1 to 256\n");
                return 2;
            }
            jobs = int(n);
        } else if (a == "--only" && i + 1 < argc)
            only.push_back(argv[++i]);
        else if (a == "--help" || a == "-h") {
            usage();
            return 0;
        } else {
            usage();
            return 2;
        }
    }
    std::vector<FigureSpec> figures;
    for (const FigureSpec& s : registered_figures()) {
        std::string key = std::string(s.paper) + "/" + s.id;
        bool take = only.empty();
        for (const std::string& o : only)
            if (o == key || o == s.paper) take = true;
        if (take) figures.push_back(s);
    }
    if (quick && full) {
        std::fprintf(stderr, "paper_figures: --quick and --full exclude each other\n");
        return 2;
    }
    if (!only.empty() && figures.empty()) {
        std::fprintf(stderr, "paper_figures: no figure matches --only (try --list)\n");
        return 2;
    }
    if (list) {
        for (const FigureSpec& s : figures) std::printf("%s/%s  %s\n", s.paper, s.id, s.caption);
        return 0;
    }
    int failures = 0;
    auto start_all = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    for (const FigureSpec& s : figures) make_dir(out + "/" + s.paper);
    int job_count = 0;  // a figure with parts is that many jobs (and a short assembling one)
    for (const FigureSpec& s : figures) job_count += s.parts > 1 ? s.parts : 1;
    if (jobs > job_count) jobs = job_count > 0 ? job_count : 1;
    const std::vector<Result> results = Scheduler(figures, out, quick, full).run(jobs);
    for (const Result& r : results)
        if (!r.ok) ++failures;
    make_dir(out);
    if (!write_index(out, results, quick)) ++failures;
    double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_all).count();
    const double cpu = process_cpu_seconds() - cpu_start;
    std::printf(
        "paper_figures: %zu figures, %d failed, %.1f s wall, %.1f s CPU (user + sys), "
        "%d jobs; index: %s/index.md\n",
        figures.size(), failures, total, cpu, jobs, out.c_str());
    // The whole set as `make figures` makes it: its CPU time against the goal (20 s, so two
    // cores finish in about 10 s); `make measurements` puts this line in docs/MEASUREMENTS.md.
    if (only.empty() && !quick && !full)
        std::printf("bench: make figures, all %zu figures: %.1f s CPU (user + sys), %.1f s wall, "
                    "%d jobs (goal <= 20 s CPU: %s)\n",
                    figures.size(), cpu, total, jobs, cpu <= 20.0 ? "met" : "MISSED");
    return failures ? 1 : 0;
}
