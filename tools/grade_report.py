#!/usr/bin/env python3
"""The grade's report: what tools/grade says about the chapters it graded, in one program.

tools/grade builds, runs each chapter's unit tests (leaving STATE/chNN.unitscore, "passed
total", and STATE/chNN.unit, one reason line per failing test case) and its golden tests
(STATE/ctest.txt and each test's output under BUILD/golden), then calls this program, which

1. records each chapter just graded: STATE/chNN.json (the scores, the reasons, a row per
   golden image) and its pictures in STATE/img/chNN/; then STATE/chNN.key, the key tools/grade
   compares to leave the chapter cached next time;
2. prints the scorecard and writes the HTML report from every chapter's record, new or
   cached, with the reasons per chapter; its exit code checks --expect.

  tools/grade_report.py --build DIR --state DIR --report DIR --chapters "NN ..." --solved "NN ..."
                        [--graded NN=KEY ...] [--units] [--expect none|all]
"""

import argparse
import html
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def settings(*names):
    """Values of tools/settings.cmake, the one place they are stated, as lists of words."""
    out = subprocess.run(["cmake", "-DGET=" + ";".join(names), "-P", str(ROOT / "tools" / "settings.cmake")],
                         check=True, capture_output=True, text=True).stdout
    return [line.split() for line in out.splitlines()]


def esc(text):
    """What the page shows as text (quotes are safe outside attributes)."""
    return html.escape(text, quote=False)


def read_text(path):
    """A file the tests may not have written (a render that never ran): None then."""
    try:
        return Path(path).read_bytes().decode("utf-8", "replace")
    except OSError:
        return None


def golden_tests(ch, build, units):
    """Each golden test of chapter CH: its scene, its reference picture, and where the test
    left its output (PREFIX.png or PREFIX-yours.png, PREFIX-heatmap.png or PREFIX-map.png,
    PREFIX.txt). A noisy chapter's tests are statistical (book §14.6): the picture is the
    reference's mean, which the test writes next to its output."""
    if units:
        return []
    golden = ROOT / "tests" / "golden" / f"ch{ch}"
    tests = []
    for ref in sorted(golden.glob("*.png")):
        if ref.name.endswith(".float.png"):  # Real=float's own reference: not this build's
            continue
        scene = ref.name[: -len(".png")]
        tests.append((scene, Path("tests/golden") / f"ch{ch}" / ref.name, build / "golden" / f"ch{ch}" / scene))
    for ref in sorted(golden.glob("*.mean.pfm")):
        scene = ref.name[: -len(".mean.pfm")]
        out = build / "golden" / f"golden_ch{ch}_{scene}" / scene
        tests.append((scene, Path(f"{out}-reference.png"), out))
    return tests


def ctest_result(ctest_log, ch, scene):
    """ctest's word for one test ("Passed", "Failed", "Timeout", ...), or "" when it did not run."""
    pattern = re.compile(r".*Test +#[0-9]+: golden_ch" + ch + "_" + re.escape(scene) +
                         r" \.+ *(\*\*\*)?([A-Za-z ]+[a-z]).*")
    for line in ctest_log.splitlines():
        m = pattern.fullmatch(line)
        if m:
            return m.group(2)
    return ""


def why_it_differs(out, result):
    """The reason line's words for a golden test that did not pass."""
    why = (read_text(f"{out}.txt") or "").encode()[:400].decode("utf-8", "replace")
    why = why.replace("\n", " ").rstrip(" ")
    if why.startswith("render failed:"):
        why = "did not render: " + re.sub(r"render failed: *(ch[0-9]+: error: )?", "", why, count=1)
    elif not why:
        why = f"did not run ({result or 'no result'})"
    else:
        why = "differs past the tolerance: " + why
    ran = (read_text(f"{out}.uses") or "").rstrip("\n")
    if ran:
        why += f" (ran your exercises {ran})"
    return why


def record_chapter(ch, key, args):
    """Step 1 for chapter CH: its record and pictures, then its key."""
    state, build = args.state, args.build
    passed, total = (int(x) for x in (state / f"ch{ch}.unitscore").read_text().split())
    reasons = (state / f"ch{ch}.unit").read_text().splitlines()
    ctest_log = read_text(state / "ctest.txt") or ""
    images = state / "img" / f"ch{ch}"
    shutil.rmtree(images, ignore_errors=True)
    images.mkdir(parents=True)
    rows = []
    for scene, ref, out in golden_tests(ch, build, args.units):
        result = ctest_result(ctest_log, ch, scene)
        if result != "Passed":
            reasons.append(f"  ch{ch} golden image {scene}: {why_it_differs(out, result)}")
        score = read_text(f"{out}.txt")
        yours, heat = Path(f"{out}.png"), Path(f"{out}-heatmap.png")
        if Path(f"{out}-yours.png").is_file():
            yours = Path(f"{out}-yours.png")
        if Path(f"{out}-map.png").is_file():
            heat = Path(f"{out}-map.png")
        for source, name in ((ROOT / ref, "reference"), (yours, "yours"), (heat, "heatmap")):
            if source.is_file():
                shutil.copyfile(source, images / f"{scene}-{name}.png")
        rows.append({"scene": scene, "passed": result == "Passed",
                     "score": "not rendered" if score is None else score.rstrip("\n"),
                     "yours": yours.is_file(), "heatmap": heat.is_file()})
    golden_passed = sum(row["passed"] for row in rows)
    record = {"unit_passed": passed, "unit_total": total, "golden_passed": golden_passed,
              "golden_total": len(rows), "rows": rows, "reasons": reasons}
    (state / f"ch{ch}.json").write_text(json.dumps(record, indent=1) + "\n")
    (state / f"ch{ch}.key").write_text(key + "\n")


def chapter_table(ch, record):
    """A chapter's section of the report: its unit score and a row per golden image."""
    img = f"img/ch{ch}"
    lines = [f"<h2>Chapter {ch}: unit tests {record['unit_passed']} of {record['unit_total']}</h2><table>",
             "<tr><th>scene</th><th>reference | yours</th><th>difference</th><th>score</th></tr>"]
    for row in record["rows"]:
        scene = row["scene"]
        lines.append(f"<tr><td>{scene}</td>")
        if row["yours"]:
            lines.append(f'<td><div class="cmp"><img src="{img}/{scene}-reference.png"><img class="top" '
                         f'src="{img}/{scene}-yours.png" style="clip-path:inset(0 0 0 50%)"></div>')
            lines.append('<input type="range" min="0" max="100" value="50" style="width:240px" '
                         "oninput=\"this.previousElementSibling.lastElementChild.style.clipPath="
                         "'inset(0 0 0 '+this.value+'%)'\"></td>")
        else:
            lines.append(f'<td><img src="{img}/{scene}-reference.png">(no image of yours)</td>')
        lines.append(f'<td><img src="{img}/{scene}-heatmap.png"></td>' if row["heatmap"] else "<td></td>")
        verdict = '<span class="pass">match</span>' if row["passed"] else '<span class="fail">differs</span>'
        lines.append(f"<td>{verdict}<br><code>{esc(row['score'])}</code></td></tr>")
    lines.append("</table>")
    return lines


def ran_exercises(line):
    """The exercises a failure line says it ran ("(ran your exercises 9.1 9.2)"), or None."""
    m = re.fullmatch(r".*\(ran your exercises ([0-9. ]+)\)", line)
    return set(m.group(1).split()) if m else None


def wrong_exercises(records):
    """The exercises that fail a unit test of their own which no other such exercise ran.

    A test named for 9.1 that also runs 9.2 fails when 9.2 is wrong, 9.1 right: 9.1 then
    fails only tests that a failing 9.2 ran too, and is not named; 9.2, failing a test that
    ran no other of them, is. A line that does not say what it ran (a crash, a hang) counts
    against its own exercise. Should every failing exercise be covered by another (each
    test running both), all of them are named."""
    own = []  # (exercise a failing test is named for, the exercises it ran or None)
    for record in records.values():
        for line in record["reasons"]:
            m = re.search(r' unit test "([0-9]+\.[0-9]+) ', line)
            if m:
                own.append((m.group(1), ran_exercises(line)))
    failing = {e for e, _ in own}
    wrong = {e for e, ran in own if ran is None or (ran & failing) <= {e}}
    return wrong or failing


def point_back(ch, line, chapters, records, wrong):
    """A failure that ran an earlier chapter's exercise whose own tests fail there points back
    to it: a wrong 14.1 shows in chapter 15's images, but is fixed in chapter 14. Only the
    exercises that are wrong (wrong_exercises) are named, not those failing through them."""
    hint = []
    for e in sorted(ran_exercises(line) or (), key=lambda e: tuple(int(x) for x in e.split("."))):
        c = "%02d" % int(e.split(".")[0])
        if int(c) < int(ch) and c in chapters and c in records and e in wrong:
            hint.append(e)
    if hint:
        line += f"; start with {', '.join(hint)}, which fails its own tests in its chapter"
    return line


def waiting_line(ch, mine):
    """On the scorecard, what waits for an exercise not written yet is one line a chapter."""
    waits = [line for line in mine if "is not done yet" in line or "needs exercise " in line]
    if not waits:
        return []
    numbers = {m for line in waits for m in re.findall(r"exercise ([0-9]+\.[0-9]+)", line)}
    waiting = " ".join(sorted(numbers, key=lambda e: tuple(int(x) for x in e.split("."))))
    how = next((m.group(0) for line in mine for m in
                [re.search(r'take chapter [0-9]+ from solutions/ with ./lab grade --solved "[0-9;]*"', line)] if m),
               "")
    return [f"  ch{ch}: {len(waits)} tests and images stop at exercises not done yet: {waiting}" +
            (f" (or {how})" if how else "")]


def report(args):
    """Step 2: the scorecard on stdout, the HTML report, and the exit code for --expect."""
    chapters, solved, graded = args.chapters.split(), args.solved.split(), dict(args.graded)
    records = {}
    for ch in chapters:
        path = args.state / f"ch{ch}.json"
        if path.is_file():
            records[ch] = json.loads(path.read_text())
    for ch in chapters:
        if ch not in records:  # a state the grade did not leave: nothing to report from
            sys.exit(f"grade: no result for chapter {ch} in {args.state}: grade it again")
    noisy, seeds, tolerance = settings("RTLAB_NOISY_CHAPTERS", "RTLAB_STAT_SEEDS", "RTLAB_STAT_TOLERANCE")
    alpha = float(tolerance[tolerance.index("--alpha") + 1])

    report_dir = args.report
    page = report_dir / "report.html"
    shutil.rmtree(report_dir / "img", ignore_errors=True)
    (report_dir / "img").mkdir(parents=True)
    out = [
        '<!doctype html><meta charset="utf-8"><title>rtlab grade</title>',
        "<style>body{font-family:sans-serif;margin:2em}img{image-rendering:pixelated;width:240px;"
        "border:1px solid #888;display:block}",
        "td{padding:4px;vertical-align:top}.pass{color:#070}.fail{color:#b00}",
        ".cmp{position:relative;width:240px}.cmp .top{position:absolute;top:0;left:0;width:240px;"
        "clip-path:inset(0 50% 0 0)}",
        ".legend{display:inline-block;width:200px;height:12px;background:linear-gradient(to right,#000,#f00,#ff0);"
        "vertical-align:middle}</style>",
        f"<h1>rtlab grade</h1><p>Chapters graded: {' '.join(chapters)}. Taken from <code>solutions/</code>: "
        f"{' '.join(solved) or 'none'}. Build: <code>{esc(str(args.build))}</code>.</p>",
        '<p>Heatmap: <span class="legend"></span> black = equal, red = 32 of 255 levels apart, yellow = 64 or more.',
        f" Noisy chapters ({int(min(noisy))} on) are tested statistically (book §14.6): their \"yours\" is the "
        f"average of {len(seeds)} renders,",
        " their map black where your average agrees with the reference, orange as a pixel-channel's p-value falls",
        " towards the corrected level, red where it fails: one red pixel fails the image (one test with a "
        f"{alpha * 100:g} % false-alarm rate, book §14.6).",
        " Drag the slider under a comparison to wipe between the reference (left) and yours (right).</p>",
    ]
    wrong = wrong_exercises(records)
    card = ["%-8s %-12s %-12s %s" % ("chapter", "unit tests", "golden", "exercises")]
    reasons, n_cached, ok_none, ok_all = [], 0, True, True
    for ch in chapters:
        r = records[ch]
        passed, total = r["unit_passed"], r["unit_total"]
        g_passed, g_total = r["golden_passed"], r["golden_total"]
        note = ""
        if ch not in graded:
            note = "  (cached: unchanged since it was last graded)"
            n_cached += 1
        source = "solutions/" if ch in solved else "yours"
        golden = "%-12s" % "(not run)" if args.units else "%3d of %-5d" % (g_passed, g_total)
        card.append("ch%-6s %3d of %-5d %s %-10s%s" % (ch, passed, total, golden, source, note))
        out += chapter_table(ch, r)
        mine = [point_back(ch, line, chapters, records, wrong) for line in r["reasons"]]
        if mine:
            out.append("<p>What did not pass:</p><ul>")
            out += [f"<li><code>{esc(line.lstrip(' '))}</code></li>" for line in mine]
            out.append("</ul>")
            reasons += [line for line in mine if not ("is not done yet" in line or "needs exercise " in line)]
            reasons += waiting_line(ch, mine)
        shutil.copytree(args.state / "img" / f"ch{ch}", report_dir / "img" / f"ch{ch}")
        ok_none = ok_none and passed == 0 and g_passed == 0
        ok_all = ok_all and passed == total and g_passed == g_total and total > 0
    page.write_text("\n".join(out) + "\n")

    if reasons:
        card.append("unit tests and golden images that did not pass (first failed check, values, inputs; "
                    "the report has all):")
        card += reasons[:20]
        if len(reasons) > 20:
            card.append(f"  ... and {len(reasons) - 20} more (see the report)")
    card.append(f"chapters graded: {' '.join(chapters)} ({n_cached} cached)")
    card.append(f"chapters taken from solutions/: {' '.join(solved) or 'none'}")
    card.append(f"report: {page}")
    print("\n".join(card), flush=True)
    if args.expect == "none" and not ok_none:
        sys.exit("grade: expected nothing to pass with the stubs")
    if args.expect == "all" and not ok_all:
        sys.exit("grade: expected everything to pass")


def main():
    parser = argparse.ArgumentParser(prog="tools/grade_report.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=Path, required=True)
    parser.add_argument("--state", type=Path, required=True)
    parser.add_argument("--report", type=Path, required=True)
    parser.add_argument("--chapters", required=True)
    parser.add_argument("--solved", default="")
    parser.add_argument("--graded", action="append", default=[], type=lambda s: tuple(s.split("=", 1)),
                        metavar="NN=KEY")
    parser.add_argument("--units", action="store_true")
    parser.add_argument("--expect", choices=["none", "all"])
    args = parser.parse_args()
    for ch, key in args.graded:
        record_chapter(ch, key, args)
    report(args)


if __name__ == "__main__":
    main()
