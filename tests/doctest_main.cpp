// The main() of every unit-test program: doctest's, plus what a student needs to read a
// failure: which exercises this build takes from solutions/; when a test stops at an
// exercise of an earlier chapter, which one and how to get past it; and, for every test
// case that fails, one line it shows: its first failed check with its values and captured
// inputs, and which of the student's exercises it ran. The grader (tools/grading/units.py)
// reads what ran and how it ended from the verdict channel (verdict.hpp), never from what
// the program prints.
#define DOCTEST_CONFIG_IMPLEMENT
#include "core/build_info.hpp"
#include "core/exercise.hpp"
#include "verdict.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

std::string this_chapter;  // "02" for test_ch02, empty for test_common

// The --solved value that adds `chapter` to what this build already takes from solutions/.
std::string solved_with(const std::string& chapter) {
    std::set<std::string> chapters{chapter};
    std::stringstream list(rt::build_info::solved);
    for (std::string ch; std::getline(list, ch, ';');)
        if (!ch.empty()) chapters.insert(ch);
    std::string out;
    for (const std::string& ch : chapters) {
        if (!out.empty()) out += ';';
        out += ch;
    }
    return out;
}

// One line, however many the text had.
std::string one_line(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

// Prints, for each failing test case, "[rtlab] failed: NAME | FIRST FAILURE | ran your
// exercises 10.1 10.4" (the console reporter still prints everything in full above it), and
// records on the verdict channel each test case's start and end by its place in the run
// (doctest's --first counts the same way), and the list of test cases --list-test-cases asks.
struct FailureLine : doctest::IReporter {
    const doctest::TestCaseData* test = nullptr;
    int index = 0;      // the current test case's place among those the run went through, from 1
    std::string first;  // the first failed check of the current test case, with its context
    std::mutex lock;    // checks may be made from several threads

    explicit FailureLine(const doctest::ContextOptions&) {}

    static std::string context() {
        std::string out;
        const int n = doctest::IReporter::get_num_active_contexts();
        const doctest::IContextScope* const* scopes = doctest::IReporter::get_active_contexts();
        for (int i = 0; i < n; ++i) {
            std::ostringstream s;
            scopes[i]->stringify(&s);
            if (!out.empty()) out += "; ";
            out += one_line(s.str());
        }
        return out.empty() ? "" : " [" + out + "]";
    }

    void test_case_start(const doctest::TestCaseData& t) override {
        test = &t;
        first.clear();
        rt::exercise_use::clear();
        rt::verdict::record("start " + std::to_string(++index) + " " + t.m_name);
    }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void log_assert(const doctest::AssertData& a) override {
        if (!a.m_failed) return;
        std::lock_guard<std::mutex> hold(lock);
        if (!first.empty()) return;
        if (a.m_threw)
            first = std::string(a.m_expr) + " threw: " + one_line(a.m_exception.c_str());
        else
            first = one_line(a.m_expr) + " is false: " + one_line(a.m_decomp.c_str());
        first += context();
    }
    void log_message(const doctest::MessageData& m) override {
        if (m.m_severity & doctest::assertType::is_warn) return;  // MESSAGE, WARN: not failures
        std::lock_guard<std::mutex> hold(lock);
        if (first.empty()) first = one_line(m.m_string.c_str()) + context();
    }
    void test_case_exception(const doctest::TestCaseException& e) override {
        std::lock_guard<std::mutex> hold(lock);
        if (first.empty()) first = (e.is_crash ? "crashed: " : "threw: ") + one_line(e.error_string.c_str());
    }
    void test_case_end(const doctest::CurrentTestCaseStats& stats) override {
        if (!test) return;
        if (stats.testCaseSuccess) {
            rt::verdict::record("end " + std::to_string(index) + " passed");
            return;
        }
        const std::string ran = rt::exercise_use::list();
        const std::string why = first.empty() ? "(no message)" : first;
        const std::string exercises = ran.empty() ? "ran none of your exercises" : "ran your exercises " + ran;
        std::printf("[rtlab] failed: %s | %s | %s\n", test->m_name, why.c_str(), exercises.c_str());
        std::fflush(stdout);
        rt::verdict::record("end " + std::to_string(index) + " failed " + why + " | " + exercises);
    }

    void report_query(const doctest::QueryData& q) override {
        if (!q.data) return;
        for (unsigned i = 0; i < q.num_data; ++i) rt::verdict::record(std::string("case ") + q.data[i]->m_name);
    }
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    // Counted as doctest's --first counts: a case left out by --first still has its place (the
    // grader selects only by --first; a case marked skip has none).
    void test_case_skipped(const doctest::TestCaseData& t) override {
        if (!t.m_skip) ++index;
    }
};

}  // namespace

REGISTER_LISTENER("rtlab-failures", 1, FailureLine);

REGISTER_EXCEPTION_TRANSLATOR(const rt::NotImplemented& e) {
    // The stub's message starts "exercise N.M (name) is not done yet"; chapter N is the
    // exercise's own.
    static const std::regex form(R"(^exercise (\d+)\.(\S+) \((.*)\) is not done yet)");
    const std::string what = e.what();
    std::smatch m;
    if (std::regex_search(what, m, form)) {
        std::string chapter = m[1].str();
        if (chapter.size() == 1) chapter = "0" + chapter;
        if (chapter != this_chapter)
            return doctest::String(("needs exercise " + m[1].str() + "." + m[2].str() + " (" + m[3].str() +
                                    ", chapter " + chapter + "): solve it, or take chapter " + chapter +
                                    " from solutions/ with ./lab grade --solved \"" + solved_with(chapter) + "\"")
                                       .c_str());
    }
    return doctest::String(what.c_str());
}

int main(int argc, char** argv) {
    static const std::regex name(R"(test_ch(\d\d)$)");
    std::smatch m;
    const std::string program = argv[0];
    if (std::regex_search(program, m, name)) this_chapter = m[1].str();
    if (std::string(rt::build_info::track) == "exercises")
        std::printf("[rtlab] exercises track: chapters from solutions/: %s\n", rt::build_info::from_solutions);
    doctest::Context context(argc, argv);
    const int result = context.run();
    // The proof that the run went to its end: a test that exits, or crashes, leaves none.
    rt::verdict::record("complete");
    return result;
}
