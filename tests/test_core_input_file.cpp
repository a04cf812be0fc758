// Tests for lib/shitsukan/core/input_file: a file read whole keeps every byte (a binary file its
// NUL bytes too), and is refused, naming the path, past its bound, past the memory budget, with
// a NUL byte in a text (naming the line), or when it cannot be opened (with the reason).
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "shitsukan/core/input_file.hpp"
#include "shitsukan/core/memory_budget.hpp"

using namespace shitsukan;

namespace {
std::string temp_path(const char* name) {
    return std::string("/tmp/shitsukan_input_") + std::to_string(getpid()) + "_" + name;
}
void write_bytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
    REQUIRE(std::fclose(f) == 0);
}
bool says(const Status& s, const std::string& what) {
    return std::string(s.message()).find(what) != std::string::npos;
}
}  // namespace

TEST_CASE("read_binary_file and read_text_file: every byte, in order, across 64 KiB chunks") {
    const std::string path = temp_path("bytes");
    std::vector<unsigned char> bytes(200000);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = (unsigned char)(i * 7 + i / 251);
    write_bytes(path, bytes);
    std::vector<unsigned char> back;
    REQUIRE(read_binary_file(path.c_str(), bytes.size(), "test: the file", back).ok());
    CHECK(back == bytes);  // NUL bytes included
    std::string text;
    const Status nul = read_text_file(path.c_str(), bytes.size(), "test: the text", text);
    CHECK(nul.code() == StatusCode::invalid_argument);
    CHECK(says(nul, path + ":1: NUL byte"));
    for (unsigned char& b : bytes) b = (unsigned char)('a' + b % 26);
    bytes[70000] = '\n';
    write_bytes(path, bytes);
    REQUIRE(read_text_file(path.c_str(), bytes.size(), "test: the text", text).ok());
    CHECK(text == std::string(bytes.begin(), bytes.end()));
    std::remove(path.c_str());
}

TEST_CASE("read_binary_file and read_text_file: bound, budget and missing file refused") {
    const std::string path = temp_path("bounds");
    write_bytes(path, std::vector<unsigned char>(100000, 'x'));
    std::vector<unsigned char> back{1, 2, 3};
    const Status longer = read_binary_file(path.c_str(), 99999, "test: the file", back);
    CHECK(longer.code() == StatusCode::too_large);
    CHECK(says(longer, "longer than 99999 bytes"));
    CHECK(back == std::vector<unsigned char>{1, 2, 3});  // untouched on failure
    set_memory_budget(50000);
    const Status budget = read_binary_file(path.c_str(), std::size_t(-1), "test: the file", back);
    set_memory_budget(0);
    CHECK(budget.code() == StatusCode::too_large);
    CHECK(says(budget, "test: the file"));
    std::remove(path.c_str());
    std::string text;
    const Status missing = read_text_file(path.c_str(), 10, "test: the text", text);
    CHECK(missing.code() == StatusCode::io_error);
    CHECK(says(missing, path));
    CHECK(says(missing, "No such file"));
    CHECK(read_binary_file("", 10, "test", back).code() == StatusCode::invalid_argument);
}
