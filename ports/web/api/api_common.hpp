// ports/web/api/api_common.hpp — what every api_<paper>.cpp shares: the caller-visible
// buffers, the last Status as text, progress. The C API is a thin layer over the public
// library (no algorithm here): each sk_<paper>_<step> function validates nothing itself,
// calls the library, copies the result into these buffers and returns the Status code
// (0 = ok). The page (ports/web/page/) reads the buffers from the WASM heap; the native
// reference (ports/web/native_reference.cpp) reads them from memory and hashes them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shitsukan/core/progress.hpp"
#include "shitsukan/core/status.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan_web.h"

#if defined(__EMSCRIPTEN__)
#include <emscripten/emscripten.h>
#define SK_API extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define SK_API extern "C"
#endif

namespace skweb {

// The RGBA picture of the last call (alpha 255), width x height, row 0 at the top.
void set_picture(const shitsukan::RgbImage& image);
// Float output of the last call (values, tables), and its row length for 2D data.
std::vector<float>& floats();
void set_float_columns(int columns);
// Text output (a small JSON object: parameters, measured numbers) of the last call.
std::string& text();
// Stores the Status for sk_status_message() and returns its code as an int (0 = ok).
int finish(const shitsukan::Status& status);
// A Progress that forwards the library's fractions to the page (a Web Worker message) and
// records the last one for sk_progress().
shitsukan::Progress progress();
// text as a JSON string literal (quotes added; \" \\ and control characters escaped).
std::string json_string(const char* text);
// Monotonic milliseconds (for the page's live "time per point"; never hashed).
double now_ms();

}  // namespace skweb
