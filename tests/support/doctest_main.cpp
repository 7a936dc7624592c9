// The main of the doctest programs (tests/unit, tests/recast, tests/plugins, tests/samples): doctest's
// own, plus one option for ctest (navlink_discover_tests registers each test case as a ctest test):
//
//   --exact-test-case=NAME   runs the test case named exactly NAME, and fails unless that case, and
//                            no other, ran and made at least one assertion.
//
// doctest's --test-case filter cannot say that by itself: it splits at ',', reads '*' and '?' as
// wildcards and ignores case, so a name can match several cases (or, mangled, none, which doctest
// counts as success). The filter made here escapes ',' and '\', puts '?' for '*' and '?', and asks for
// case-sensitive matching; the listener below sees which cases started.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

std::vector<std::string>& started_cases() {
    static std::vector<std::string> names;
    return names;
}

int g_assertions = 0;  // made by the test cases that ran

// Records the name of each test case that starts (once per case, whatever its subcases) and counts
// the assertions made.
struct StartedCases : doctest::IReporter {
    explicit StartedCases(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData& data) override { started_cases().emplace_back(data.m_name); }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats& stats) override {
        g_assertions += stats.numAssertsCurrentTest;
    }
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

// A --test-case value that matches `name` and, but for '?', nothing else.
std::string test_case_filter(const std::string& name) {
    std::string filter;
    for (const char c : name) {
        if (c == ',' || c == '\\') {
            filter += '\\';
            filter += c;
        } else if (c == '*' || c == '?') {
            filter += '?';
        } else {
            filter += c;
        }
    }
    return filter;
}

}  // namespace

DOCTEST_REGISTER_LISTENER("navlink_started_cases", 1, StartedCases);

int main(int argc, char** argv) {
    static const char option[] = "--exact-test-case=";
    std::vector<const char*> args;
    std::string exact, filter;
    bool has_exact = false;
    for (int i = 0; i < argc; ++i) {
        if (i > 0 && std::strncmp(argv[i], option, sizeof option - 1) == 0) {
            exact = argv[i] + sizeof option - 1;
            has_exact = true;
        } else {
            args.push_back(argv[i]);
        }
    }
    if (has_exact) {
        if (exact.empty()) {
            std::fprintf(stderr, "%s needs a test case's name\n", option);
            return 2;
        }
        filter = "--test-case=" + test_case_filter(exact);
        args.push_back(filter.c_str());
        args.push_back("--case-sensitive=true");
    }

    doctest::Context context;
    context.applyCommandLine(static_cast<int>(args.size()), args.data());
    const int result = context.run();
    if (context.shouldExit() || !has_exact) return result;

    const std::vector<std::string>& started = started_cases();
    if (started.size() == 1 && started[0] == exact) {
        if (g_assertions > 0) return result;
        std::fprintf(stderr, "--exact-test-case: the test case \"%s\" made no assertion\n", exact.c_str());
        return 1;
    }
    std::fprintf(stderr, "--exact-test-case: expected the one test case \"%s\" to run; %zu ran%s\n", exact.c_str(),
                 started.size(), started.empty() ? " (no case has that name)" : ":");
    for (const std::string& name : started) std::fprintf(stderr, "  \"%s\"\n", name.c_str());
    return result != 0 ? result : 1;
}
