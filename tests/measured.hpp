// MEASURED(stream expression): one plain line of what a test measured, printed while the
// tests run ("  measured  test_file.cpp:LINE  ...").
//
// doctest's MESSAGE prints a block between two "=====" rules, the shape doctest also gives
// a failure, so a measurement read like one. A failure keeps doctest's own block (CHECK,
// REQUIRE, and MESSAGE where it sits on a failure's path); a measurement is one line.
#pragma once

#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

namespace shitsukan_tests {

inline void print_measured(const char* file, int line, const std::string& text) {
    const char* slash = std::strrchr(file, '/');
    std::printf("  measured  %s:%d  %s\n", slash ? slash + 1 : file, line, text.c_str());
    std::fflush(stdout);
}

}  // namespace shitsukan_tests

#define MEASURED(expr)                                                        \
    do {                                                                      \
        std::ostringstream measured_text_;                                    \
        measured_text_ << expr;                                               \
        ::shitsukan_tests::print_measured(__FILE__, __LINE__, measured_text_.str()); \
    } while (0)
