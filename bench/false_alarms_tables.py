"""Book §14.6's false-alarm and planted-mistake tables and the sentences that quote them, from
bench/false_alarms.sh's output (./lab bench false-alarms).

    python3 bench/false_alarms_tables.py DOUBLE.txt FLOAT.txt OUT_DIR

DOUBLE.txt and FLOAT.txt are bench/false_alarms.sh's output with the release and the float
build. Writes into OUT_DIR (book/measured/):

  ch14-false-alarms.md      the table of every scene's groups (double) and the summary
                            sentences, with the float build's counts
  ch14-choices-current.md   the choices table's row for the test as it is (t-test, variance
                            from 1,024 renders): the same groups as the first table
  ch14-planted.md           the planted mistakes' table (double) and the closest one's margin

The prose around these says the test is conservative (fewer than a tenth of the groups have
a family p below 0.1, in either build) and that every planted mistake fails, in both builds;
a run that breaks either fails here (exit 1) instead of writing what the prose contradicts.
"""

import math
import sys

from measured import need, write

GROUPS = 200  # per scene, as §14.6's prose says (a run with fewer writes nothing)

# bench/false_alarms.sh's planted rows, by the name its label starts with: the book's words
# for the table and for a sentence.
MISTAKES = {
    "box filter": ("box filter (§14.3)", "`ch14 --filter box`, `edges`", "the box filter"),
    "regular pattern": ("regular pattern (§14.2)", "`ch14 --pattern regular`, `checker`", "the regular pattern"),
    "unshuffled": ("no shuffle (§15.2)", "`planted_unshuffled`, `fence`", "the missing shuffle"),
    "corner": ("light at its corner (§15.1)", "`planted_corner`, `penumbra`", "the light at its corner"),
    "off_centre": ("lens off centre (§16.2)", "`planted_off_centre`, `row`", "the lens off centre"),
    "crowded_centre": ("lens crowding its centre (§16.2)", "`planted_crowded_centre`, `lights`", "the crowded lens"),
    "twice_as_wide": ("glossy width doubled (§17.1)", "`planted_twice_as_wide`, `plates`", "the doubled width"),
    "unstratified": ("time not stratified (§18.2)", "`planted_unstratified`, `balls`", "the unstratified time"),
}


def parse(path):
    """One run's output: [(scene, failing, groups, smallest p, family p, groups below 0.1)],
    [(mistake, failing, pixel-channels tested, smallest p, passed)] and the family alpha."""
    scenes, planted, section, alpha = [], [], "scenes", None
    with open(path) as f:
        lines = f.read().splitlines()
    for line in lines:
        words = line.split()
        if words[:2] == ["rtlab-stat", "test"]:  # the header: the tolerance the groups were tested at
            alpha = float(words[words.index("--alpha") + 1])
            continue
        if not words or words[0] == "scene" or line.startswith("bug ("):
            continue
        if words[0] == "planted":
            section = "planted"
        elif section == "scenes" and words[0] == "every":
            continue
        elif section == "scenes":
            # ch14 checker   0 of 200   5.4e-06   0.048   3 of 200
            need(len(words) == 10 and words[3] == "of", f"a scene's row of {path}: {line!r}")
            scenes.append((f"{words[0]} `{words[1]}`", int(words[2]), int(words[4]), float(words[5]),
                           float(words[6]), int(words[7])))
        else:
            # LABEL   174 of 9216   2.78e-14   FAIL
            need(len(words) >= 6 and words[-4] == "of", f"a planted row of {path}: {line!r}")
            name = next((k for k in MISTAKES if " ".join(words).startswith(k + " ")), None)
            need(name is not None, f"bench/false_alarms.sh's planted row {line!r} has a name in MISTAKES")
            planted.append((name, int(words[-5]), int(words[-3]), float(words[-2]), words[-1] == "pass"))
    need(len(scenes) >= 10 and len(planted) == len(MISTAKES) and alpha,
         f"{path} holds the tolerance, every scene and every planted mistake")
    return scenes, planted, alpha


def sidak_level(alpha, n):
    return -math.expm1(math.log1p(-alpha) / n)


def p(x, digits=1):
    """A p-value as the book writes it: $5.4 \\times 10^{-6}$, 0.048, or 0."""
    if x == 0:
        return "0"
    m, e = f"{x:.{digits}e}".split("e")
    if int(e) > -3:
        return f"{x:.2g}"
    return f"${m} \\times 10^{{{int(e)}}}$"


def upper_bound(k, n, confidence=0.95):
    """The one-sided Clopper-Pearson upper bound of a binomial rate with k of n: the rate at
    which k or fewer would happen with probability 1 - confidence (bisection on the CDF)."""
    def cdf(rate):
        return sum(math.comb(n, i) * rate ** i * (1 - rate) ** (n - i) for i in range(k + 1))
    lo, hi = k / n, 1.0
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if cdf(mid) > 1 - confidence else (lo, mid)
    return hi


def number_word(k):
    words = ["No", "One", "Two", "Three", "Four", "Five", "Six", "Seven", "Eight", "Nine"]
    return words[k] if k < len(words) else f"{k:,}"


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: false_alarms_tables.py DOUBLE.txt FLOAT.txt OUT_DIR")
    double_path, float_path, out_dir = sys.argv[1:]
    scenes, planted, alpha = parse(double_path)
    f_scenes, f_planted, _ = parse(float_path)

    def totals(rows):
        return sum(r[1] for r in rows), sum(r[2] for r in rows), sum(r[5] for r in rows)

    failed, groups, below = totals(scenes)
    f_failed, f_groups, f_below = totals(f_scenes)
    need(all(r[2] == GROUPS for r in scenes + f_scenes), f"every scene has the {GROUPS} groups §14.6 says")
    need(below < groups / 10 and f_below < f_groups / 10,
         "fewer than a tenth of the groups have a family p below 0.1, in both builds")
    need(all(not r[4] for r in planted) and all(not r[4] for r in f_planted),
         "every planted mistake fails, in both builds")

    share = 100 * failed / groups
    bound = math.ceil(10000 * upper_bound(failed, groups)) / 100  # a bound, rounded up
    level = sidak_level(alpha, planted[0][2])  # the pixel-channels tested, as the planted rows count them
    table = ["| scene | groups failing | smallest p | its family p | family p < 0.1 |", "|---|---|---|---|---|"]
    for scene, fail, g, least, family, low in scenes:
        digits = 2 if level / 2 < least < 2 * level else 1  # enough to compare with the level
        table.append(f"| {scene} | {fail} of {g} | {p(least, digits)} | {family:.2g} | "
                     f"{low} of {g} |")
    write(out_dir, "ch14-false-alarms.md", table + [
        "",
        f"{number_word(failed)} group{'s' if failed != 1 else ''} of {groups:,} fail{'s' if failed == 1 else ''}, "
        f"{share:.1f} % (with 95 % confidence, the rate is at most {bound:.2f} %), "
        f"and {below} have a family p below 0.1, {100 * below / groups:.0f} % where 10 % is allowed. The test is "
        "conservative: the three channels of a pixel nearly always fail together, and values with no noise at "
        "all, such as the sky, can hardly fail, yet each counts in Šidák's $N$. The float build "
        f"(`--build build/float`) fails {f_failed} of {f_groups:,} groups, and {f_below} have a family p below "
        "0.1."])

    worst = max(r[1] for r in scenes)
    worst_scenes = ", ".join(s.split()[1] for s, fail, *_ in scenes if fail == worst)
    write(out_dir, "ch14-choices-current.md",
          [f"| t-test | 1,024 renders | {failed} of {groups:,} | "
           f"{f'{worst} of {scenes[0][2]} ({worst_scenes})' if worst else 'none'} |"])

    rows = ["| mistake | program, scene | values failing | smallest p |", "|---|---|---|---|"]
    for name, fail, _, least, _ in planted:
        words, where, _ = MISTAKES[name]
        rows.append(f"| {words} | {where} | {fail:,} | {p(least)} |")
    closest = max(planted, key=lambda r: r[3])
    margin = f"{level / closest[3]:.0e}".split("e")
    write(out_dir, "ch14-planted.md", rows + [
        "",
        f"The closest, {MISTAKES[closest[0]][2]}, fails at a p-value ${margin[0]} \\times 10^{{{int(margin[1])}}}$ "
        "times smaller than the level. In the float build every one fails too."])


main()
