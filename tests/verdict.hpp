#pragma once
// The verdict channel: how a unit-test program tells the grader (tools/grading/units.py) which
// test cases it ran and how each ended, in a way the student's code linked into the same
// program cannot imitate by printing, exiting early or forking.
//
// The grader starts the program with RTLAB_VERDICT=R,W: R is a pipe holding a secret (64 hex
// digits, new for every run), W a file the records go to. The secret is read before any other
// code of the program runs (a .preinit_array entry runs before every static constructor, a
// student's included), the pipe is closed and the variable removed. Each record is one line,
// "SECRET PID WHAT", written with one write(): a line without the secret is not the harness's,
// and one from another process (a fork) is not the program's. The grader counts a test case
// only from a "start" and an "end ... passed" of the same run, and a run as whole only with its
// "complete": so an exit, an _Exit or a crash inside a test is a failure of that test, never a
// pass. What it cannot stop is code written to read this program's own memory; that code would
// be in the submission, for the instructor to see (book §B.8).
#include <string>

namespace rt::verdict {

// True when a grader is listening (RTLAB_VERDICT was given and read).
bool listening();

// Appends "SECRET PID what" (newlines in `what` become spaces); nothing when not listening.
void record(const std::string& what);

}  // namespace rt::verdict
