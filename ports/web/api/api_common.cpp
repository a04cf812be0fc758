// ports/web/api/api_common.cpp — the buffers, status text and progress of the C API
// (api_common.hpp). Exported: sk_picture_* (RGBA), sk_floats_*, sk_text, sk_status_*,
// sk_progress, sk_version.
#include "api_common.hpp"

#include <chrono>

#include "shitsukan/core/config.hpp"
#include "shitsukan/core/memory_budget.hpp"

#if defined(__EMSCRIPTEN__)
// Posted from the worker that runs the module (page/worker.js forwards it to the panel).
EM_JS(void, sk_js_progress, (float fraction), {
    if (typeof postMessage === 'function' && typeof WorkerGlobalScope !== 'undefined')
        postMessage({progress : fraction});
});
#endif

namespace skweb {
namespace {
std::vector<std::uint8_t> g_picture;
int g_width = 0, g_height = 0;
std::vector<float> g_floats;
int g_float_columns = 0;
std::string g_text;
shitsukan::Status g_status;
std::string g_message = "ok";
float g_progress = 0.0f;

void report(float fraction, void*) {
    g_progress = fraction;
#if defined(__EMSCRIPTEN__)
    sk_js_progress(fraction);
#endif
}
}  // namespace

void set_picture(const shitsukan::RgbImage& image) {
    g_width = image.width();
    g_height = image.height();
    g_picture.assign(std::size_t(g_width) * std::size_t(g_height) * 4u, 255u);
    const shitsukan::Rgb8* p = image.data();
    for (std::size_t i = 0, n = std::size_t(g_width) * std::size_t(g_height); i < n; ++i) {
        g_picture[4 * i + 0] = p[i].r;
        g_picture[4 * i + 1] = p[i].g;
        g_picture[4 * i + 2] = p[i].b;
    }
}

std::vector<float>& floats() { return g_floats; }
void set_float_columns(int columns) { g_float_columns = columns; }
std::string& text() { return g_text; }

int finish(const shitsukan::Status& status) {
    g_status = status;
    g_message = status.message();
    return int(status.code());
}

shitsukan::Progress progress() {
    g_progress = 0.0f;
    return shitsukan::Progress{report, nullptr};
}

std::string json_string(const char* text) {
    std::string out = "\"";
    for (const char* c = text; *c; ++c) {
        if (*c == '"' || *c == '\\') {
            out += '\\';
            out += *c;
        } else if (static_cast<unsigned char>(*c) < 0x20) {
            out += ' ';
        } else {
            out += *c;
        }
    }
    return out + "\"";
}

double now_ms() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace skweb

SK_API const std::uint8_t* sk_picture_data() { return skweb::g_picture.data(); }
SK_API int sk_picture_width() { return skweb::g_width; }
SK_API int sk_picture_height() { return skweb::g_height; }
SK_API const float* sk_floats_data() { return skweb::g_floats.data(); }
SK_API int sk_floats_count() { return int(skweb::g_floats.size()); }
SK_API int sk_floats_columns() { return skweb::g_float_columns; }
SK_API const char* sk_text() { return skweb::g_text.c_str(); }
// The library's own message of the last call's Status ("ok" on success).
SK_API const char* sk_status_message() { return skweb::g_message.c_str(); }
SK_API const char* sk_status_code_name() { return shitsukan::status_code_name(skweb::g_status.code()); }
SK_API float sk_progress() { return skweb::g_progress; }
SK_API const char* sk_version() { return SHITSUKAN_VERSION_STRING; }
// Clears every output buffer (a call that fails leaves them empty, never stale).
SK_API void sk_clear_outputs() {
    skweb::g_picture.clear();
    skweb::g_width = skweb::g_height = 0;
    skweb::g_floats.clear();
    skweb::g_float_columns = 0;
    skweb::g_text.clear();
}
// Once before the first call (the page's worker and the native reference alike): the
// per-request memory budget the web build runs under — chosen here: 1 GiB, half of the
// browser's 2 GiB WASM heap, so a request the budget admits still finds room beside the
// lattice already held; a larger request (a Type I lattice of R = 10, 4.3 GB) gets the
// library's too_large message instead of an out-of-memory abort.
SK_API int sk_init() {
    shitsukan::set_memory_budget(std::uint64_t(1) << 30);
    return skweb::finish(shitsukan::Status::success());
}
