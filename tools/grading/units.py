"""A chapter's unit tests, scored from the verdict channel (tests/verdict.hpp), never from what
the program prints: a test case passes only when the harness itself recorded its start and its
passing end, in one run whose records carry that run's secret and come from its own process.

A run that does not reach its "complete" record (an exit, an _Exit, a crash, a test that never
returns) costs the test case it stopped in, and the run goes on from the next case (doctest's
--first), so one bad test never takes the others with it, and never earns a pass.
"""
import os
import secrets
import time
from dataclasses import dataclass, field
from pathlib import Path

from . import sandbox

CASE_SECONDS = 30  # a test case running longer is stopped: an exercise that never returns (the longest
# of the lab's own, a sweep against brute force, takes a few seconds alone, 10 beside a class)
START_SECONDS = 60  # the time a run may take to start its first test case (or to list them)


@dataclass
class UnitScore:
    passed: int = 0
    total: int = 0
    reasons: list = field(default_factory=list)  # one line per test case that did not pass
    cases: list = field(default_factory=list)  # {"name", "passed", "reason"} per test case, in order


@dataclass
class Records:
    """What the harness recorded in one run, and only that."""
    began: bool = False
    complete: bool = False
    cases: list = field(default_factory=list)  # names, from a --list-test-cases run
    started: dict = field(default_factory=dict)  # index -> name
    ended: dict = field(default_factory=dict)  # index -> (passed, reason)


def parse(text, secret):
    """The harness's records in a verdict file: lines with this run's secret, from the process
    that wrote the first of them ("begin", written before any code of the student's ran)."""
    out, harness = Records(), None
    for line in text.splitlines():
        parts = line.split(" ", 3)
        if len(parts) < 3 or not secrets.compare_digest(parts[0], secret):
            continue
        pid, what, rest = parts[1], parts[2], parts[3] if len(parts) > 3 else ""
        if harness is None:
            if what != "begin":
                continue
            harness, out.began = pid, True
            continue
        if pid != harness:  # a fork of the program: not the harness's word
            continue
        if what == "case":
            out.cases.append(rest)
        elif what == "start":
            index, _, name = rest.partition(" ")
            if index.isdigit():
                out.started[int(index)] = name
        elif what == "end":
            index, _, verdict = rest.partition(" ")
            if index.isdigit():
                word, _, reason = verdict.partition(" ")
                why, _, exercises = reason.rpartition(" | ")  # "FIRST FAILED CHECK | ran your exercises 2.2"
                out.ended[int(index)] = (word == "passed", f"{why} ({exercises})" if why else reason)
        elif what == "complete":
            out.complete = True
    return out


class Channel:
    """One run's verdict channel: a pipe with a new secret, and a file for the records that only
    the grader can name (it lives in the grader's folder, outside any sandbox)."""

    def __init__(self, path):
        self.path = Path(path)
        self.secret = secrets.token_hex(32)

    def __enter__(self):
        self.read_end, write_end = os.pipe()
        os.write(write_end, self.secret.encode())
        os.close(write_end)
        self.records = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_APPEND, 0o600)
        return self

    def __exit__(self, *exc):
        os.close(self.read_end)
        os.close(self.records)

    @property
    def env(self):
        return {"RTLAB_VERDICT": f"{self.read_end},{self.records}"}

    @property
    def fds(self):
        return (self.read_end, self.records)

    def read(self):
        try:
            return parse(self.path.read_bytes().decode("utf-8", "replace"), self.secret)
        except OSError:
            return Records()


def run_once(runner, program, args, work, log, tag, budget=None):
    """One run of the program through a fresh channel; (Records, Outcome)."""
    channel = Channel(work / f"verdict-{tag}.txt")
    with channel:
        state = {"case": None, "since": time.monotonic(), "seen": 0}

        def watch():
            # The case now running, from the records so far: stop it after CASE_SECONDS.
            records = channel.read()
            if len(records.started) != state["seen"]:
                state["seen"] = len(records.started)
                state["case"] = max(records.started)
                state["since"] = time.monotonic()
            running = state["case"] is not None and state["case"] not in records.ended
            if running and time.monotonic() - state["since"] > CASE_SECONDS:
                return f"did not finish in {CASE_SECONDS:g} s (an exercise that never returns?)"
            return None

        outcome = sandbox.run(runner, [str(program), *args], cwd=runner.scratch, stdout=log,
                              seconds=START_SECONDS + CASE_SECONDS * 200, env=channel.env, pass_fds=channel.fds,
                              watch=watch, budget=budget)
        return channel.read(), outcome


def list_cases(runner, program, work):
    """The program's test cases, as its harness lists them (a single student's grade: their own
    program is all there is); None when it could not say."""
    records, outcome = run_once(runner, program, ["--list-test-cases", "--no-colors"], work,
                                work / "list.log", "list")
    if not records.complete:
        return None, outcome.describe()
    return records.cases, ""


def score(runner, program, work, cases, chapter, budget=None):
    """Runs the chapter's test program until every case in `cases` (the trusted list of names)
    has a verdict. Returns a UnitScore whose passed never exceeds len(cases)."""
    work = Path(work)
    verdict = {}  # name -> (passed, reason); a name seen twice is a failure
    first, run_number = 1, 0
    while True:
        run_number += 1
        log = work / f"units-{run_number}.log"
        records, outcome = run_once(runner, program, ["--no-colors", f"--first={first}"], work, log, run_number,
                                    budget)
        for index in sorted(records.started):
            name = records.started[index]
            passed, reason = records.ended.get(index, (False, None))
            if reason is None:  # started, never ended: the run stopped inside it
                if outcome.stopped:
                    reason = outcome.stopped
                elif outcome.code == 0:
                    reason = "the program ended inside this test with exit status 0 (an exit() in an exercise?)"
                else:
                    reason = f"{outcome.describe()} inside this test"
            if name in verdict:
                verdict[name] = (False, "ran more than once: a test case of the same name was added")
            else:
                verdict[name] = (passed, reason)
        if records.complete or not records.began:
            break
        if not records.started:
            break  # ended before its next test: what remains gets the reason below
        first = max(records.started) + 1
        if run_number > len(cases) + 1:  # each run goes one case further at least: never more runs
            break
    if records.complete:
        missing_reason = "did not run (not in this program: was it renamed?)"
    elif budget is not None and outcome.stopped == budget.reason():
        missing_reason = outcome.stopped
    elif not records.began:
        missing_reason = f"the program ended before the harness started ({outcome.describe()})"
    else:
        missing_reason = f"the program ended before this test ({outcome.describe()})"
    out = UnitScore(total=len(cases))
    for name in cases:
        passed, reason = verdict.get(name, (False, missing_reason))
        out.cases.append({"name": name, "passed": passed, "reason": "" if passed else reason})
        if passed:
            out.passed += 1
        else:
            out.reasons.append(f'  ch{chapter} unit test "{name}": {reason}')
    return out
