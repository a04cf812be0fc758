// shitsukan/core/input_file.hpp — a text or binary file read whole, within a stated bound.
//
// Manual
//   std::string text;
//   Status s = read_text_file("mesh.obj", std::size_t(1) << 20, "my_reader: the text", text);
//   if (!s) std::fprintf(stderr, "%s\n", s.message());  // "mesh.obj:3: NUL byte in the text"
//
// The readers of text formats (read_obj, read_control_mesh) hold their file whole before
// parsing it. read_text_file reads in 64 KiB chunks and refuses, before the text grows past
// them: a file longer than max_bytes (too_large, naming the bound), more than the memory
// budget allows (core/memory_budget.hpp; its message names `what`), and a NUL byte, which no text
// holds (/dev/zero, a binary file: invalid_argument naming the line). A read error is io_error with
// the C library's reason. read_binary_file is the same for bytes (read_image's files): NUL
// bytes allowed, the same bounds. Host side.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "shitsukan/core/status.hpp"

namespace shitsukan {

Status read_text_file(const char* path, std::size_t max_bytes, const char* what, std::string& out);
Status read_binary_file(const char* path, std::size_t max_bytes, const char* what,
                        std::vector<unsigned char>& out);

}  // namespace shitsukan
