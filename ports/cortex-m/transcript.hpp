// ports/cortex-m/transcript.hpp — the one program `make test-mcu` runs on the host, on a
// Cortex-M4F (QEMU mps2-an386) and on a Cortex-M7 (QEMU mps2-an500): it computes the
// library's small-device outputs and writes them as text (floats as their IEEE bits, images
// as FNV-1a 64 hashes), so the three transcripts must be equal byte for byte.
//
// A port provides the output function; nothing here allocates or uses stdio/printf.
#pragma once

namespace shitsukan::port {

// Writes `length` bytes of text somewhere (semihosting, a UART, stdout).
using WriteFn = void (*)(const char* text, int length);

// Runs every section, writing the transcript through `write`; returns 0 when every Status
// was ok (a refused call is written into the transcript and makes the result 1).
int run_transcript(WriteFn write);

}  // namespace shitsukan::port
