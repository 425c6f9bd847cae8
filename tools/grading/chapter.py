"""One chapter's grade, the same for a student's own grade and a class's: its unit tests through
the verdict channel (units.py) and its golden images (golden.py), into the record the report
reads (report.py): scores, reasons, and a row per golden image with its pictures."""
import shutil
from pathlib import Path

from . import golden, units
from .settings import ROOT


def scenes(ch):
    """The chapter's golden scenes: (scene, kind, reference files), from tests/golden/chNN."""
    folder = ROOT / "tests" / "golden" / f"ch{ch}"
    out = []
    for ref in sorted(folder.glob("*.png")):
        if not ref.name.endswith(".float.png"):  # Real=float's own reference: not a grade's build
            out.append((ref.name[: -len(".png")], "plain", (ref,)))
    for mean in sorted(folder.glob("*.mean.pfm")):
        scene = mean.name[: -len(".mean.pfm")]
        out.append((scene, "statistical", (mean, folder / f"{scene}.var.pfm")))
    return out


def unit_job(runner, program, work, ch, cases, budget=None):
    """The unit tests' part of a chapter's record. `cases`: the trusted list of test names, or
    None to ask the program (a student's own grade)."""
    work.mkdir(parents=True, exist_ok=True)
    if cases is None:
        cases, why = units.list_cases(runner, program, work)
        if cases is None:
            return {"unit_passed": 0, "unit_total": 0, "units": [],
                    "unit_reasons": [f"  ch{ch} unit tests: the program could not list its tests ({why})"]}
    result = units.score(runner, program, work, cases, ch, budget)
    return {"unit_passed": result.passed, "unit_total": result.total, "unit_reasons": result.reasons,
            "units": result.cases}


def golden_job(runner, judge, program, out, ch, scene, kind, refs, budget=None):
    """One golden image's row, with the reason line when it did not pass."""
    if kind == "plain":
        row = golden.plain(runner, judge, program, scene, refs[0], out, budget=budget)
    else:
        row = golden.statistical(runner, judge, program, scene, refs[0], refs[1], out, budget=budget)
    if not row["passed"]:
        why = row["reason"]
        if row.get("exercises"):
            why += f" (ran your exercises {row['exercises']})"
        row["reason_line"] = f"  ch{ch} golden image {scene}: {why}"
    return row


def jobs(ch, runner, judge, programs, work, cases, units_only, budget=None):
    """The chapter's work as independent jobs (callables returning a partial record), so that a
    grade can spread every chapter's jobs over the cores. `budget`: a class's time per student."""
    out = [lambda: unit_job(runner, programs["test"], work / "units", ch, cases, budget)]
    if not units_only:
        for scene, kind, refs in scenes(ch):
            out.append(lambda s=scene, k=kind, r=refs: {
                "rows": [golden_job(runner, judge, programs["chapter"], work / "golden", ch, s, k, r, budget)]})
    return out


def record(ch, parts, units_only, pictures):
    """Joins the jobs' parts into the chapter's record and copies its pictures into `pictures`
    (the report's img/chNN), so the record stands alone when the build is gone."""
    shutil.rmtree(pictures, ignore_errors=True)
    pictures.mkdir(parents=True)
    rec = {"unit_passed": 0, "unit_total": 0, "units": [], "rows": [], "reasons": []}
    for part in parts:
        rec["units"] += part.get("units", [])
        rec["unit_passed"] += part.get("unit_passed", 0)
        rec["unit_total"] += part.get("unit_total", 0)
        rec["reasons"] += part.get("unit_reasons", [])
        rec["rows"] += part.get("rows", [])
    rec["rows"].sort(key=lambda row: row["scene"])
    for row in rec["rows"]:
        if not row["passed"]:
            rec["reasons"].append(row["reason_line"])
        for name in ("reference", "yours", "heatmap"):
            source = row.get(name)
            row[name] = bool(source) and Path(source).is_file()
            if row[name]:
                shutil.copyfile(source, pictures / f"{row['scene']}-{name}.png")
        row["reason"] = row.pop("reason_line", "").strip()
        for transient in ("exercises", "failed_groups"):
            row.pop(transient, None)
    rec["golden_passed"] = sum(row["passed"] for row in rec["rows"])
    rec["golden_total"] = len(rec["rows"])
    rec["units_only"] = units_only
    return rec


def not_compiled(ch, cases, why, units_only):
    """The record of a chapter whose exercise file did not compile: nothing of it passes, and
    the compiler's first message is the reason."""
    rows = [] if units_only else [{"scene": scene, "passed": False, "reference": False, "yours": False,
                                   "heatmap": False, "score": "not rendered: the exercises did not compile"}
                                  for scene, _, _ in scenes(ch)]
    units = [{"name": name, "passed": False, "reason": f"did not compile: {why}"} for name in cases or []]
    return {"unit_passed": 0, "unit_total": len(cases or []), "units": units, "rows": rows, "golden_passed": 0,
            "golden_total": len(rows), "units_only": units_only, "reasons": [f"  ch{ch} did not compile: {why}"]}
