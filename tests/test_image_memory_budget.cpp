// Tests for the memory budget (core/memory_budget.hpp) in image/: owning images
// (try_resize) and the readers refuse at once, with the byte count, what does not fit.
#include <cstdio>
#include <cstring>
#include <string>

#include <doctest/doctest.h>
#include "shitsukan/core/memory_budget.hpp"
#include "shitsukan/image/image.hpp"
#include "shitsukan/image/image_read.hpp"
#include "shitsukan/image/pfm.hpp"
#include "shitsukan/image/png16.hpp"

using namespace shitsukan;

namespace {
struct BudgetGuard {  // a small budget for one test, the default again afterwards
    explicit BudgetGuard(std::uint64_t bytes) { set_memory_budget(bytes); }
    ~BudgetGuard() { set_memory_budget(0); }
};
}  // namespace

TEST_CASE("Image::try_resize refuses sizes over the memory budget, naming the bytes") {
    BudgetGuard guard(1 << 20);
    RgbImage img;
    CHECK(img.try_resize(512, 512).ok());  // 768 KiB
    CHECK(img.width() == 512);
    Status s = img.try_resize(1024, 1024);  // 3 MiB
    CHECK(s.code() == StatusCode::too_large);
    CHECK(std::strstr(s.message(), "3145728") != nullptr);
    CHECK(img.width() == 512);  // unchanged
    FloatImage huge;
    s = huge.try_resize(100000, 100000);  // 40 GB: refused at once, no bad_alloc
    CHECK(s.code() == StatusCode::too_large);
    CHECK(huge.width() == 0);
}

TEST_CASE("read_pfm and read_image refuse images over the memory budget before decoding") {
    FloatImage small(64, 64, 0.5f);
    REQUIRE(write_pfm("build/budget_test.pfm", small.data(), 64, 64, 1).ok());
    Gray16Image g(64, 64, 1234);
    REQUIRE(write_png16("build/budget_test.png", g.view()).ok());
    {
        BudgetGuard guard(8 * 1024);  // 64 x 64 floats are 16 KiB
        PfmImage back;
        Status s = read_pfm("build/budget_test.pfm", back);
        CHECK(s.code() == StatusCode::too_large);
        CHECK(std::strstr(s.message(), "16384") != nullptr);
        if (image_reading_available()) {
            LoadedImage img;
            s = read_image("build/budget_test.png", img);
            CHECK(s.code() == StatusCode::too_large);
        }
    }
    PfmImage back;
    CHECK(read_pfm("build/budget_test.pfm", back).ok());
    if (image_reading_available()) {
        LoadedImage img;
        CHECK(read_image("build/budget_test.png", img).ok());
    }
    std::remove("build/budget_test.pfm");
    std::remove("build/budget_test.png");
}
