#pragma once
// What every exercise shares: the exception a stub throws, and the record of which of the
// student's exercises ran.
#include <atomic>
#include <stdexcept>
#include <string>

namespace rt {

// Thrown by every stub, so that an unfinished exercise fails a test with a message that
// names it, rather than crashing or returning garbage.
struct NotImplemented : std::logic_error {
    using std::logic_error::logic_error;
};

// Which of the student's exercises have run since the last clear(). The student's copies in
// exercises/ mark themselves on entry (tools/gen_exercises.cpp writes the call, outside the
// student's lines; the reference copies in solutions/ have none), so that a failing test or
// golden image can say which exercises it went through: a wrong 14.1 that fails chapter
// 15's images is then named there. A mark costs one load once it is set, and no store: no
// cache line bounces between the threads of a render.
namespace exercise_use {

inline constexpr int kChapters = 100, kNumbers = 10;
inline std::atomic<bool> ran[kChapters][kNumbers];

inline void mark(int chapter, int number) {
    std::atomic<bool>& flag = ran[chapter][number];
    if (!flag.load(std::memory_order_relaxed)) flag.store(true, std::memory_order_relaxed);
}

inline void clear() {
    for (auto& chapter : ran)
        for (auto& flag : chapter) flag.store(false, std::memory_order_relaxed);
}

// "10.1 10.4", in the course's order; empty when none ran.
inline std::string list() {
    std::string out;
    for (int c = 0; c < kChapters; ++c)
        for (int n = 0; n < kNumbers; ++n)
            if (ran[c][n].load(std::memory_order_relaxed)) {
                if (!out.empty()) out += ' ';
                out += std::to_string(c) + '.' + std::to_string(n);
            }
    return out;
}

}  // namespace exercise_use
}  // namespace rt

// The line the generator puts at the top of each exercise function of exercises/.
#define RT_STUDENT_EXERCISE(chapter, number) ::rt::exercise_use::mark(chapter, number)
