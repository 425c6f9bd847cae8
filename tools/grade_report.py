#!/usr/bin/env python3
"""The grade's report: what a grade says about the chapters it graded, in one program.

The grader (tools/grading/) leaves a record per chapter, STATE/chNN.json (the scores, the
reasons, a row per golden image, the compiler's warnings) with its pictures in STATE/img/chNN/,
then calls this program, which prints the scorecard and writes the HTML report from every
chapter's record, new or cached (--graded names the new ones), with the reasons per chapter;
its exit code checks --expect.

  tools/grade_report.py --build DIR --state DIR --report DIR --chapters "NN ..." --solved "NN ..."
                        [--graded NN ...] [--units] [--expect none|all]
"""

import argparse
import html
import json
import re
import shutil
import sys
from pathlib import Path

from grading.settings import settings



def esc(text):
    """What the page shows as text (quotes are safe outside attributes)."""
    return html.escape(text, quote=False)


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


def scorecard(args):
    """The scorecard's lines, and the HTML report written beside it; (lines, nothing passed,
    everything passed). args.who, when given, names the student (a class's grade)."""
    chapters, solved, graded = args.chapters.split(), args.solved.split(), set(args.graded)
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
        f"<h1>rtlab grade{': ' + esc(args.who) if getattr(args, 'who', '') else ''}</h1><p>Chapters graded: {' '.join(chapters)}. Taken from <code>solutions/</code>: "
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
    reasons, warnings, n_cached, ok_none, ok_all = [], [], 0, True, True
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
        # What the compiler said of the student's exercises when it built them: worth reading
        # even when every test passes ("iteration 7 invokes undefined behavior").
        if r.get("warnings"):
            out.append("<p>Compiler warnings in your exercises:</p><ul>")
            out += [f"<li><code>{esc(line.lstrip(' '))}</code></li>" for line in r["warnings"]]
            out.append("</ul>")
            warnings += r["warnings"]
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
    if warnings:
        card.append("compiler warnings in your exercises (the report has all):")
        card += warnings[:10]
        if len(warnings) > 10:
            card.append(f"  ... and {len(warnings) - 10} more (see the report)")
    card.append(f"chapters graded: {' '.join(chapters)} ({n_cached} cached)")
    card.append(f"chapters taken from solutions/: {' '.join(solved) or 'none'}")
    card.append(f"report: {page}")
    return card, ok_none, ok_all


def report(args):
    """The scorecard on stdout, the HTML report, and the exit code for --expect."""
    card, ok_none, ok_all = scorecard(args)
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
    parser.add_argument("--graded", action="append", default=[], metavar="NN")
    parser.add_argument("--units", action="store_true")
    parser.add_argument("--expect", choices=["none", "all"])
    report(parser.parse_args())


if __name__ == "__main__":
    main()
