// ports/cortex-m/host_main.cpp — the transcript program on the host (stdout).
#include <cstdio>

#include "transcript.hpp"

int main() {
    return shitsukan::port::run_transcript(
        [](const char* text, int length) { std::fwrite(text, 1, std::size_t(length), stdout); });
}
