// paper_figures/driver/figure.hpp — how a figure registers itself with build/paper_figures.
//
// Manual: one .cpp per figure (or per figure family) under paper_figures/<paper key>/.
//
//   #include "driver/figure.hpp"
//   SHITSUKAN_FIGURE(fig10_cube_marble, "okada1987", "fig10a",
//                    "Cube with the marble texture (k = 16)") {
//       ctx.given("k", "16", "okada1987 §4");
//       ctx.chosen("beta", "0.9", "not printed in the paper; smooth folds at k = 16");
//       RgbImage img(ctx.quick() ? 128 : 512, ...);
//       ... render ...
//       return ctx.save_png(img.view());            // -> out/okada1987/fig10a.png
//   }
//
// - ids starting with "table" save Markdown with ctx.save_markdown(text) (-> <id>.md).
// - ctx.quick(): CI smoke run; use small sizes/few iterations, but the same code path.
// - ctx.path(".svg"): a path for extra outputs next to the main one (<id>.svg, <id>.obj).
// - ctx.note(text): a paragraph for the index (what to look for, measured numbers).
// - ctx.progress(fmt, ...): a progress line for long figures (printed indented).
// - Return a non-ok Status to report a failure; the driver goes on and exits non-zero.
// - Figures run in parallel (--jobs N): a figure's own state is local; anything shared
//   between figures (a memoised simulation, a lattice) is built once under a lock, and a
//   figure that needs another's results registers with SHITSUKAN_FIGURE_AFTER(..., "fig21").
// - A long figure made of independent pieces (a table timed row block by row block) registers
//   with SHITSUKAN_FIGURE_PARTS(..., parts): the driver runs it `parts` times as separate jobs
//   (ctx.in_part(), ctx.part() = 0 .. parts - 1; each hands its results on with ctx.keep(text))
//   and then once more to assemble (ctx.in_part() false, ctx.kept(p) = what part p kept), so
//   the output is the same whatever --jobs is. Parameters, notes and files belong to the
//   assembling call.
// Every figure's parameters appear in paper_figures/out/index.md as a table with a
// "given / chosen" column (docs/DESIGN.md: given vs. chosen).
#pragma once

#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image.hpp"

namespace shitsukan::figures {

struct Parameter {
    std::string name;
    std::string value;
    bool given = false;     // stated by the paper
    std::string source;     // for given: where in the paper; for chosen: the reason
};

class FigureContext {
public:
    FigureContext(std::string out_dir, std::string paper, std::string id, bool quick,
                  bool full = false);

    bool quick() const { return quick_; }
    bool full() const { return full_; }  // --full: the paper's own counts where a figure
                                         // chose fewer for the default run (said in its notes)
    const std::string& paper() const { return paper_; }
    const std::string& id() const { return id_; }

    void given(const std::string& name, const std::string& value, const std::string& where);
    void chosen(const std::string& name, const std::string& value, const std::string& why);
    void note(const std::string& text);
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    void progress(const char* format, ...);

    std::string path(const std::string& suffix) const;  // <out>/<paper>/<id><suffix>
    Status save_png(const RgbView& image);
    Status save_png(const GrayView& image);
    Status save_markdown(const std::string& markdown);
    Status save_text(const std::string& suffix, const std::string& text);

    // SHITSUKAN_FIGURE_PARTS: which part this job is (-1: the assembling call), what it keeps
    // for the assembling call, and there what part p kept (in the order it kept it).
    bool in_part() const { return part_ >= 0; }
    int part() const { return part_; }
    void keep(std::string text) { kept_.push_back(std::move(text)); }
    const std::vector<std::string>& kept(int part) const;

    // For the driver.
    void set_part(int part) { part_ = part; }
    void set_kept_parts(std::vector<std::vector<std::string>> parts) { parts_ = std::move(parts); }
    std::vector<std::string> take_kept() { return std::move(kept_); }

    const std::vector<Parameter>& parameters() const { return parameters_; }
    const std::vector<std::string>& notes() const { return notes_; }
    const std::vector<std::string>& outputs() const { return outputs_; }

private:
    std::string out_dir_, paper_, id_;
    bool quick_, full_;
    int part_ = -1;
    std::vector<std::string> kept_;                // a part job's results
    std::vector<std::vector<std::string>> parts_;  // the assembling call's: kept per part
    std::vector<Parameter> parameters_;
    std::vector<std::string> notes_;
    std::vector<std::string> outputs_;  // file names relative to <out>/<paper>/
};

using FigureFunction = Status (*)(FigureContext&);

struct FigureSpec {
    const char* paper;
    const char* id;
    const char* caption;
    FigureFunction run;
    // With --jobs N the figures run in parallel; a figure that reads what others of its paper
    // recorded (a table of a figure's stage times) names their id prefix here and starts only
    // after every figure of its paper whose id starts with it has finished.
    const char* after = nullptr;
    // SHITSUKAN_FIGURE_PARTS: the number of independent part jobs before the assembling call.
    int parts = 1;
};

bool register_figure(const FigureSpec& spec);
std::vector<FigureSpec> registered_figures();  // sorted: paper order, then id

// printf into a std::string: fmt("%.3f", x)
#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
std::string fmt(const char* format, ...);

}  // namespace shitsukan::figures

#define SHITSUKAN_FIGURE(name, paper, id, caption)                                      \
    static ::shitsukan::Status name(::shitsukan::figures::FigureContext& ctx);         \
    static const bool name##_registered_ =                                              \
        ::shitsukan::figures::register_figure({paper, id, caption, &name});             \
    static ::shitsukan::Status name([[maybe_unused]] ::shitsukan::figures::FigureContext& ctx)

#define SHITSUKAN_FIGURE_AFTER(name, paper, id, caption, after)                         \
    static ::shitsukan::Status name(::shitsukan::figures::FigureContext& ctx);         \
    static const bool name##_registered_ =                                              \
        ::shitsukan::figures::register_figure({paper, id, caption, &name, after});      \
    static ::shitsukan::Status name([[maybe_unused]] ::shitsukan::figures::FigureContext& ctx)

#define SHITSUKAN_FIGURE_PARTS(name, paper, id, caption, parts)                         \
    static ::shitsukan::Status name(::shitsukan::figures::FigureContext& ctx);         \
    static const bool name##_registered_ = ::shitsukan::figures::register_figure(      \
        {paper, id, caption, &name, nullptr, parts});                                   \
    static ::shitsukan::Status name([[maybe_unused]] ::shitsukan::figures::FigureContext& ctx)
