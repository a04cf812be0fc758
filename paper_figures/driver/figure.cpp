#include "driver/figure.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "shitsukan/core/output_file.hpp"
#include "shitsukan/image/image_io.hpp"

namespace shitsukan::figures {

namespace {

std::vector<FigureSpec>& registry() {
    static std::vector<FigureSpec> figures;
    return figures;
}

int paper_rank(const std::string& paper) {
    static const char* order[] = {"foundation", "okada1987",    "okada1989",
                                  "tokai1994",  "fujimoto2000", "hirota1998"};
    for (int i = 0; i < 6; ++i)
        if (paper == order[i]) return i;
    return 6;
}

std::string vformat(const char* format, va_list args) {
    va_list copy;
    va_copy(copy, args);
    int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    if (n <= 0) return std::string();
    std::string s(std::size_t(n) + 1, '\0');
    std::vsnprintf(&s[0], s.size(), format, args);
    s.resize(std::size_t(n));
    return s;
}

}  // namespace

std::string fmt(const char* format, ...) {
    va_list args;
    va_start(args, format);
    std::string s = vformat(format, args);
    va_end(args);
    return s;
}

bool register_figure(const FigureSpec& spec) {
    registry().push_back(spec);
    return true;
}

std::vector<FigureSpec> registered_figures() {
    std::vector<FigureSpec> list = registry();
    std::stable_sort(list.begin(), list.end(), [](const FigureSpec& a, const FigureSpec& b) {
        int ra = paper_rank(a.paper), rb = paper_rank(b.paper);
        if (ra != rb) return ra < rb;
        if (std::string(a.paper) != b.paper) return std::string(a.paper) < b.paper;
        return std::string(a.id) < b.id;
    });
    return list;
}

FigureContext::FigureContext(std::string out_dir, std::string paper, std::string id, bool quick,
                             bool full)
    : out_dir_(std::move(out_dir)),
      paper_(std::move(paper)),
      id_(std::move(id)),
      quick_(quick),
      full_(full) {}

const std::vector<std::string>& FigureContext::kept(int part) const {
    static const std::vector<std::string> none;
    return part >= 0 && std::size_t(part) < parts_.size() ? parts_[std::size_t(part)] : none;
}

void FigureContext::given(const std::string& name, const std::string& value,
                          const std::string& where) {
    parameters_.push_back({name, value, true, where});
}

void FigureContext::chosen(const std::string& name, const std::string& value,
                           const std::string& why) {
    parameters_.push_back({name, value, false, why});
}

void FigureContext::note(const std::string& text) { notes_.push_back(text); }

void FigureContext::progress(const char* format, ...) {
    va_list args;
    va_start(args, format);
    std::string s = vformat(format, args);
    va_end(args);
    if (part_ >= 0)
        std::printf("      %s/%s (part %d): %s\n", paper_.c_str(), id_.c_str(), part_ + 1,
                    s.c_str());
    else
        std::printf("      %s/%s: %s\n", paper_.c_str(), id_.c_str(), s.c_str());
    std::fflush(stdout);
}

std::string FigureContext::path(const std::string& suffix) const {
    return out_dir_ + "/" + paper_ + "/" + id_ + suffix;
}

Status FigureContext::save_png(const RgbView& image) {
    SHITSUKAN_TRY(write_png(path(".png").c_str(), image));
    outputs_.push_back(id_ + ".png");
    return Status::success();
}

Status FigureContext::save_png(const GrayView& image) {
    SHITSUKAN_TRY(write_png(path(".png").c_str(), image));
    outputs_.push_back(id_ + ".png");
    return Status::success();
}

Status FigureContext::save_markdown(const std::string& markdown) {
    SHITSUKAN_TRY(save_text(".md", markdown));
    return Status::success();
}

Status FigureContext::save_text(const std::string& suffix, const std::string& text) {
    SHITSUKAN_TRY(write_text_file(path(suffix).c_str(), text));  // core/output_file.hpp
    outputs_.push_back(id_ + suffix);
    return Status::success();
}

}  // namespace shitsukan::figures
