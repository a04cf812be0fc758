// The test runner: doctest, plus a last line "tests: N passed, N failed" that CI reads.
// Exit status is non-zero when any test fails.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>

namespace {

unsigned g_passed = 0, g_failed = 0;

struct CountListener : doctest::IReporter {
    explicit CountListener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& s) override {
        unsigned ran = s.numTestCasesPassingFilters;
        unsigned failed = s.numTestCasesFailed;
        g_passed = ran - failed;
        g_failed = failed;
    }
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace

REGISTER_LISTENER("counts", 1, CountListener);

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    int result = context.run();
    if (!context.shouldExit()) std::printf("tests: %u passed, %u failed\n", g_passed, g_failed);
    return result != 0 ? 1 : 0;
}
