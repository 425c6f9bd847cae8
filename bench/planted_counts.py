"""What the statistical test says about chapters 15 to 18's planted mistakes and correct
renders, in the sentences §15.7, §16.6, §17.7 and §18.6 quote (./lab bench planted).

    python3 bench/planted_counts.py BIN_DIR OUT_DIR

Renders each scene as the statistical golden test does (tools/settings.cmake: 64x48, 16
samples per pixel, seeds 101-108), with a planted program (tests/planted/) and with the
chapter's own, and runs rtlab-stat against the scene's reference, as the ctest tests
stat_catches_* do; and renders the false-alarm groups of stat_false_alarms_ch15_* to
stat_false_alarms_ch18_* (20 groups of 8 seeds each). Writes into OUT_DIR (book/measured/):

  ch14-stat-tests.md       chapter 14's false-alarm tests' 40 groups
  ch14-by-hand.md          the box filter on edges, as a reader types it, and the tent's
  ch15-planted.md          the unshuffled and corner programs' failures
  ch15-by-hand.md          the unshuffled program on fence, as a reader types it, and ch15's
  ch15-false-alarms.md     what the correct renders' 40 groups give
  ch16-off-centre.md       the off-centre lens's failures
  ch16-by-hand.md          the off-centre lens on row, as a reader types it, and ch16's
  ch16-crowded.md          the crowded lens's failures
  ch16-false-alarms.md     what the correct renders' 40 groups give
  ch17-golden.md, ch18-golden.md              the golden tests' verdicts, reference solution
  ch17-false-alarms.md, ch18-false-alarms.md  the false-alarm test's 20 groups
  ch17-planted.md, ch18-planted.md            the doubled width's and the unstratified
                                              time's failures
  ch17-by-hand.md, ch18-by-hand.md            those, as a reader types them, and the chapter's
  ch18-variance.md         the unstratified time's variance against the reference's (1,024
                           renders of each program) and the failures it predicts

Renders and verdicts are exact for a build (fixed seeds), so the numbers are the same on
every run of one build. Where the chapters' prose depends on a verdict (each planted
program fails where its test says, the crowded lens passes on the square lens of row, the
correct renders pass with at most one group of 20 failing, chapters 17 and 18's reference
solutions pass their golden tests with no value failing), a run that breaks it fails here
(exit 1) instead of writing a sentence the prose would contradict.
"""

import json
import math
import os
import subprocess
import sys
import tempfile

import measured
from measured import n, need, write


def setting(name):
    out = subprocess.run(["cmake", f"-DGET={name}", "-P", "tools/settings.cmake"], check=True, capture_output=True,
                         text=True)
    return (out.stdout + out.stderr).split()


SIZE = setting("RTLAB_STAT_ARGS")  # --width 64 --height 48 --spp 16
SEEDS = [int(s) for s in setting("RTLAB_STAT_SEEDS")]
TOLERANCE = setting("RTLAB_STAT_TOLERANCE")
REAL = "double"  # the build's Real, read from its --version in main()



def verdict(bin_dir, program, chapter, scene, seeds, extra=()):
    """rtlab-stat's line and JSON for `program` rendering `scene` at `seeds` (with `extra`
    arguments after the seed, as the ctest tests' EXTRA_ARGS)."""
    with tempfile.TemporaryDirectory() as tmp:
        images = []
        for s in seeds:
            image = os.path.join(tmp, f"{scene}-{s}.pfm")
            subprocess.run([os.path.join(bin_dir, program), "--scene", scene, *SIZE, "--seed", str(s), *extra,
                            "-o", image], check=True, capture_output=True)
            images.append(image)
        ref = f"tests/golden/ch{chapter}/{scene}"
        js = os.path.join(tmp, "v.json")
        run = subprocess.run([os.path.join(bin_dir, "rtlab-stat"), "test", f"{ref}.mean.pfm", f"{ref}.var.pfm",
                              *images, *TOLERANCE, "--json", js], capture_output=True, text=True)
        need(run.returncode in (0, 1), f"rtlab-stat ran on {program} {scene}: {run.stderr.strip()}")
        with open(js) as f:
            v = json.load(f)
    v["line"] = run.stdout.strip()
    print(f"{program} {scene} {seeds[0]}..{seeds[-1]}: {v['line']}", file=sys.stderr)
    return v


def groups(bin_dir, chapter, scene, first):  # a stat_false_alarms_ test's 20 groups
    n = len(SEEDS)
    return [verdict(bin_dir, f"ch{chapter}", chapter, scene, list(range(first + g * n, first + (g + 1) * n)))
            for g in range(20)]


def p(x, digits=1):
    """A p-value as the book writes it: 2.0 × 10^-5, or 10^-17 when the mantissa is about 1."""
    if x == 0:
        return "0 (below what a double holds)"
    m, e = f"{x:.{digits}e}".split("e")
    e = int(e)
    if e > -3:
        return f"{x:.3g}"
    if float(m) == 1.0:
        return f"$10^{{{e}}}$"
    return f"${m} \\times 10^{{{e}}}$"


def variance(bin_dir, program, scene, seeds, tmp):
    """One render's variance per pixel-channel, from renders at `seeds`, as `./lab golden`
    makes a reference's (rtlab-stat reference --spread)."""
    images = []
    for s in seeds:
        images.append(os.path.join(tmp, f"{program}-{s}.pfm"))
        subprocess.run([os.path.join(bin_dir, program), "--scene", scene, *SIZE, "--seed", str(s), "-o", images[-1]],
                       check=True, capture_output=True)
    mean, var = os.path.join(tmp, "mean.pfm"), os.path.join(tmp, f"{program}.var.pfm")
    subprocess.run([os.path.join(bin_dir, "rtlab-stat"), "reference", mean, var, "--converged", images[0],
                    "--spread", *images], check=True, capture_output=True)
    for image in images:
        os.remove(image)
    return measured.read_pfm(var)[2]  # in file order: the order does not matter to a comparison


def t_threshold(level, dof):
    """The t above which a two-sided p falls below `level`, with `dof` degrees of freedom
    (Student's density integrated numerically; bisection on the threshold)."""
    log_c = math.lgamma((dof + 1) / 2) - math.lgamma(dof / 2) - 0.5 * math.log(dof * math.pi)

    def tail(t):  # P(|T| > t) by Simpson's rule on [t, t + 40]
        steps, width = 4000, 40.0
        h = width / steps
        f = [math.exp(log_c - (dof + 1) / 2 * math.log1p((t + i * h) ** 2 / dof)) for i in range(steps + 1)]
        return 2 * h / 3 * (f[0] + f[-1] + 4 * sum(f[1:-1:2]) + 2 * sum(f[2:-1:2]))

    lo, hi = 1.0, 20.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if tail(mid) > level else (lo, mid)
    return hi


def unstratified_variance(bin_dir, wrong):
    """§18.6: the planted sampler's variance against the reference's, and the failures the
    formula predicts from it."""
    reference = measured.read_pfm("tests/golden/ch18/balls.var.pfm")[2]
    seeds = list(range(1001, 2025))  # the reference's (tests/golden: seeds 1001 to 2024)
    with tempfile.TemporaryDirectory() as tmp:
        planted = variance(bin_dir, "planted_unstratified", "balls", seeds, tmp)
        correct = variance(bin_dir, "ch18", "balls", seeds, tmp)
    # Where the variance is only rounding (below 10^-4; most are below 10^-8) its last digits
    # differ; where there is noise, the correct program's renders give the reference's.
    worst = max(abs(c - r) / r for c, r in zip(correct, reference) if r > 1e-4)
    need(worst < 1e-5, "the correct program reproduces the reference's variance where there is noise")
    noisy = [(r, q) for r, q in zip(reference, planted) if r > 1e-4]
    ratios = sorted(q / r for r, q in noisy)
    median, tenth, most = ratios[len(ratios) // 2], ratios[int(0.9 * len(ratios))], ratios[-1]
    floor, m = float(TOLERANCE[TOLERANCE.index("--floor") + 1]), len(SEEDS)
    threshold = t_threshold(wrong["level"], int(TOLERANCE[TOLERANCE.index("--var-renders") + 1]) - 1)
    need(abs(threshold - 4.90) < 0.005, "the Šidák threshold is 4.90 (§18.6's formula)")
    predicted = sum(math.erfc(threshold * math.sqrt(r / m + floor ** 2) / math.sqrt(2 * q / m))
                    for r, q in zip(reference, planted) if q > 0)
    need(median > 1 and abs(predicted - wrong["failed"]) < 0.25 * wrong["failed"],
         "the planted sampler is noisier, and the formula predicts about the failures the test finds")
    return (f"For `balls` the numbers bear this out. Each pixel-channel's variance can be measured from "
            f"{n(len(seeds))} renders of the planted program, with seeds {seeds[0]} to {seeds[-1]}. Over the "
            f"{n(len(noisy))} pixel-channels whose reference variance is above $10^{{-4}}$, the planted sampler's "
            f"variance is a median of {median:.1f} times the reference's, {tenth:.0f} times or more for a tenth of "
            f"them, and up to {most:.0f} times. (The correct program, rendered with those seeds, reproduces the "
            f"reference's variance there to a relative {p(worst)}: the reference was made from the same renders.) "
            "Summing the "
            "formula above over every pixel-channel, with its measured variance and the floor of §14.6, predicts "
            f"{predicted:.0f} failures. The test finds {wrong['failed']}, scattered over the two smears and the "
            "shadow under the sliding ball. In those places, the time decides what a ray sees.")


def by_hand(program, chapter, scene, short, v, correct, extra=()):
    prefix = f"build/release/bin/{program} --scene {scene} {' '.join(SIZE)}"
    ref = f"tests/golden/ch{chapter}/{scene}"
    if extra:  # the option the planted mistake is, on the seed's line
        prefix += " --seed $s"
    return ["```text",
            f"$ for s in $(seq {SEEDS[0]} {SEEDS[-1]}); do",
            f"    {prefix} \\",
            f"        {' '.join(extra) if extra else '--seed $s'} -o /tmp/{short}-$s.pfm",
            "  done",
            f"$ build/release/bin/rtlab-stat test {ref}.mean.pfm {ref}.var.pfm \\",
            f"      /tmp/{short}-*.pfm --map /tmp/map.png",
            v["line"],
            "```", "",
            (f"Without `{' '.join(extra)}` the same seeds give " if extra else
             f"With `build/release/bin/ch{chapter}` in place of the planted program, the same seeds give ")+
            f"`{correct['failed']} fail ... {'pass' if correct['pass'] else 'FAIL'}; smallest p "
            f"{correct['smallest_p']:.3g}`."]


def false_alarms(results):
    """The sentence for a chapter's 40 groups of correct renders."""
    failed = sum(not v["pass"] for v in results)
    need(failed <= 2, "at most one group of 20 fails, in each of the two scenes")
    smallest = min(v["smallest_p"] for v in results)
    verdict_text = "none fails" if failed == 0 else f"{failed} fail"
    return (f"Of the 40 false-alarm groups, rendered by the chapter's own program (Real = {REAL}), {verdict_text}; "
            f"the smallest p among them is {p(smallest)}.")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: planted_counts.py BIN_DIR OUT_DIR")
    bin_dir, out_dir = sys.argv[1:]
    global REAL
    version = subprocess.run([os.path.join(bin_dir, "ch15"), "--version"], check=True, capture_output=True,
                             text=True).stdout
    REAL = version.split("Real=", 1)[1].split(",", 1)[0]

    # Chapter 15.
    fence = verdict(bin_dir, "planted_unshuffled", 15, "fence", SEEDS)
    fence_ok = verdict(bin_dir, "ch15", 15, "fence", SEEDS)
    penumbra = verdict(bin_dir, "planted_unshuffled", 15, "penumbra", SEEDS)
    corner = verdict(bin_dir, "planted_corner", 15, "penumbra", SEEDS)
    need(not fence["pass"] and not penumbra["pass"] and not corner["pass"], "the planted ch15 programs fail")
    need(fence_ok["pass"], "ch15 passes fence at the test's seeds")
    need(fence["failed"] > penumbra["failed"], "the unshuffled program fails fence more plainly than penumbra")
    write(out_dir, "ch15-planted.md",
          [f"With `planted_unshuffled`, {n(fence['failed'])} of `fence`'s {n(fence['tests'])} pixel-channels fail, "
           f"with a smallest p of {p(fence['smallest_p'])}: the columns of the map in §15.2. The same program fails "
           f"`penumbra` too, with {n(penumbra['failed'])}, but the fence was built to make the mistake unmistakable. "
           f"With `planted_corner`, {n(corner['failed'])} of `penumbra`'s pixel-channels fail."])
    write(out_dir, "ch15-by-hand.md", by_hand("planted_unshuffled", 15, "fence", "fence", fence, fence_ok))
    write(out_dir, "ch15-false-alarms.md", [false_alarms(groups(bin_dir, 15, "penumbra", 5000) +
                                                groups(bin_dir, 15, "fence", 9000))])

    # Chapter 16.
    row = verdict(bin_dir, "planted_off_centre", 16, "row", SEEDS)
    row_ok = verdict(bin_dir, "ch16", 16, "row", SEEDS)
    lights = verdict(bin_dir, "planted_off_centre", 16, "lights", SEEDS)
    crowded = verdict(bin_dir, "planted_crowded_centre", 16, "lights", SEEDS)
    crowded_row = verdict(bin_dir, "planted_crowded_centre", 16, "row", SEEDS)
    need(not row["pass"] and not lights["pass"] and not crowded["pass"], "the planted ch16 programs fail")
    need(row_ok["pass"], "ch16 passes row at the test's seeds")
    need(crowded_row["pass"], "the crowded lens passes on row's square lens")
    need(crowded["failed"] < 100 and crowded["smallest_p"] < crowded["level"] / 1000,
         "the crowded lens fails few pixel-channels, by far")
    write(out_dir, "ch16-off-centre.md",
          [f"With `planted_off_centre`, {n(row['failed'])} of `row`'s {n(row['tests'])} pixel-channels fail (on "
           f"`lights`, {n(lights['failed'])})."])
    write(out_dir, "ch16-by-hand.md", by_hand("planted_off_centre", 16, "row", "oc", row, row_ok))
    write(out_dir, "ch16-crowded.md",
          [f"With `planted_crowded_centre`, {n(crowded['failed'])} of `lights`' pixel-channels fail, with a "
           f"smallest p of {p(crowded['smallest_p'])}, far below the level of {p(crowded['level'], 2)}; on `row` the "
           f"same program passes."])
    write(out_dir, "ch16-false-alarms.md", [false_alarms(groups(bin_dir, 16, "row", 5000) +
                                                groups(bin_dir, 16, "lights", 9000))])

    # Chapter 14 (§14.6): its two false-alarm tests' 40 groups and the box filter by hand.
    alarms = groups(bin_dir, 14, "edges", 5000) + groups(bin_dir, 14, "checker", 7000)
    failed = sum(not v["pass"] for v in alarms)
    need(failed == 0, "no group of chapter 14's false-alarm tests fails")
    write(out_dir, "ch14-stat-tests.md",
          [f"In the {REAL} build no group of the two false-alarm tests fails; the smallest p of their 40 groups is "
           f"{p(min(v['smallest_p'] for v in alarms))}."])
    box = verdict(bin_dir, "ch14", 14, "edges", SEEDS, ("--filter", "box"))
    edges = verdict(bin_dir, "ch14", 14, "edges", SEEDS)
    need(not box["pass"] and edges["pass"], "the box filter fails edges and the tent passes")
    write(out_dir, "ch14-by-hand.md", by_hand("ch14", 14, "edges", "box", box, edges, ("--filter", "box")))

    # Chapters 17 and 18: the golden tests' verdicts, the false-alarm test's 20 groups, and the
    # planted mistake with its transcript (§17.7, §18.6).
    for chapter, scenes, planted, short in ((17, ("plates", "grazing"), "twice_as_wide", "wide"),
                                            (18, ("balls", "shutter"), "unstratified", "unstrat")):
        golden = [verdict(bin_dir, f"ch{chapter}", chapter, scene, SEEDS) for scene in scenes]
        need(all(v["pass"] and v["failed"] == 0 for v in golden),
             f"chapter {chapter}'s reference solution passes its golden tests with no value failing")
        write(out_dir, f"ch{chapter}-golden.md",
              [f"With the reference solutions in the {REAL} build, " +
               " and ".join(f"`golden_ch{chapter}_{scene}`" for scene in scenes) +
               " pass with no value failing (smallest p " + " and ".join(p(v["smallest_p"]) for v in golden) + ")."])
        alarms = groups(bin_dir, chapter, scenes[0], 5000)
        failed = sum(not v["pass"] for v in alarms)
        need(failed <= 1, f"stat_false_alarms_ch{chapter}_{scenes[0]} passes: at most one group of 20 fails")
        write(out_dir, f"ch{chapter}-false-alarms.md",
              [f"**False alarms.** `stat_false_alarms_ch{chapter}_{scenes[0]}` tests 20 more groups of 8 correct "
               f"renders, seeds 5000 to {5000 + 20 * len(SEEDS) - 1}, and passes when at most one group fails "
               f"(§14.6). In the {REAL} build {'no group fails' if failed == 0 else 'one group fails'}; the smallest "
               f"p of the 20 is {p(min(v['smallest_p'] for v in alarms))}."])
        wrong = verdict(bin_dir, f"planted_{planted}", chapter, scenes[0], SEEDS)
        need(not wrong["pass"], f"planted_{planted} fails on {scenes[0]}")
        write(out_dir, f"ch{chapter}-planted.md",
              [f"In the {REAL} build, {n(wrong['failed'])} of the {n(wrong['tests'])} pixel-channels fail."])
        write(out_dir, f"ch{chapter}-by-hand.md",
              by_hand(f"planted_{planted}", chapter, scenes[0], short, wrong, golden[0]))
        if chapter == 18:
            write(out_dir, "ch18-variance.md", [unstratified_variance(bin_dir, wrong)])


main()
