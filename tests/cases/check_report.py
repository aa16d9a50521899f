"""The run report against the run's own files: check_report.py RUN [REPORT].

REPORT is RUN/report, or a report-<T>mm folder made with --travel T (then
history.csv counts up to T). What report.md must say:
- how the run ended: a split as "The part splits: <measure> at punch travel
  X mm, at <location>." with run-summary.txt's split_measure, split_travel
  and split_location; a Newton failure as "The solver failed in step N at
  punch travel X mm; results up to punch travel Y mm" (Y the last row of
  history.csv); end_reason verbatim in the key table;
- the numbers of history.csv (and solver.csv): peak punch force and its
  travel ("still rising" exactly when the peak is the last row), final
  minimum thickness and thinning, thickening, cup height, margin to the
  forming limit, the largest penetration, steps, Newton iterations and cuts;
  the largest ironing wall pressure;
- the FLD zone counts: those of run-summary.txt's columns_* (history.csv's
  at a travel) and of sheet.csv's zone column;
- no -1 sentinel in the key table;
- the trimmed and the sprung part's pictures where the run wrote
  trimmed_*.pvtu or springback_*.pvtu;
- every embedded PNG, the rendered ones included, is a PNG that is not
  blank (its pixels are not all one colour); report.html holds the same
  table rows and embeds the same pictures."""
import base64
import csv
import glob
import html
import os
import re
import sys

import matplotlib.image

import results

ZONES = ["safe", "insufficient stretch", "wrinkling tendency", "compression", "severe thinning",
         "risk of crack", "crack", "fracture"]
run = sys.argv[1]
report = sys.argv[2] if len(sys.argv) > 2 else os.path.join(run, "report")
m = re.search(r"report-([0-9.eE+-]+)mm/?$", report)
as_of = float(m.group(1)) if m else None
text = open(os.path.join(report, "report.md")).read()
summary = dict(l.rstrip("\n").split(" = ", 1) for l in open(os.path.join(run, "run-summary.txt")) if " = " in l)
rows = [r for r in results.read(run) if as_of is None or float(r["punch_travel"]) <= as_of + 1e-6]
col = lambda k: [float(r[k]) for r in rows]
ok = True


def verdict(what, good, detail=""):
    global ok
    print(f"{what}: {detail}{': ' if detail else ''}{'ok' if good else 'WRONG'}")
    ok = ok and good


def check(what, got, expected, digits):
    """got as printed with `digits` decimal places."""
    verdict(what, abs(got - expected) <= 0.51 * 10 ** (-digits), f"report {got}, run {expected:.6g}")


def cell(name):
    m = re.search(r"^\| " + re.escape(name) + r" \| (.*) \|$", text, re.M)
    if not m:
        raise SystemExit(f"report.md has no row '{name}'")
    return m.group(1)


def summary_travel(key):
    """A travel of run-summary.txt, None when -1 or past the report's travel."""
    t = float(summary.get(key, -1))
    return None if t < 0 or (as_of is not None and t > as_of + 1e-9) else t


# How the run ended.
split = summary_travel("split_travel") if summary.get("split") == "yes" else None
said = re.search(r"The part splits: (.+?) at punch travel ([-\d.]+) mm, at (.+)\.\*\*$", text, re.M)
if split is not None:
    verdict("split statement", bool(said) and said.group(1) == summary["split_measure"]
            and abs(float(said.group(2)) - split) < 0.0051 and said.group(3) == summary["split_location"],
            said.group(0) if said else "missing")
    verdict("split row", cell("split").startswith("yes"), cell("split"))
else:
    verdict("no split statement", not said)
    verdict("split row", cell("split").startswith(("no", "not by")), cell("split"))
end = summary.get("end_reason", "")
verdict("end of run row", cell("end of run") == end)
failed = re.search(r"step (\d+) \(punch travel ([-\d.eE+]+) mm\)", end)
if as_of is None and failed and "did not converge" in end:
    said = re.search(r"The solver (?:then )?failed in step (\d+) at punch travel ([-\d.]+) mm; "
                     r"(?:results up to punch travel ([-\d.]+) mm|no step converged)", text)
    good = bool(said) and said.group(1) == failed.group(1) and abs(float(said.group(2)) - float(failed.group(2))) < 0.0051
    if good and rows:
        good = said.group(3) is not None and abs(float(said.group(3)) - col("punch_travel")[-1]) < 0.0051
    elif good:
        good = said.group(3) is None
    verdict("solver failure statement", good, said.group(0) if said else "missing")

# The key numbers.
if rows:
    force = col("punch_force")
    peak = max(range(len(rows)), key=lambda i: force[i])
    m = re.match(r"([-\d.]+) N at ([-\d.]+) mm", cell("peak punch force"))
    check("peak punch force (N)", float(m.group(1)), force[peak], 0)
    check("its punch travel (mm)", float(m.group(2)), col("force_travel")[peak], 2)
    verdict("'still rising' when the peak is the last row",
            ("still rising" in cell("peak punch force")) == (peak == len(rows) - 1))
    m = re.match(r"([-\d.]+) mm \(thinning ([-\d.]+) %\)", cell("minimum thickness"))
    check("final minimum thickness (mm)", float(m.group(1)), col("min_thickness")[-1], 4)
    check("final thinning (%)", float(m.group(2)), col("max_thinning_percent")[-1], 1)
    check("largest thickening (%)", float(cell("largest thickening").split()[0]), col("max_thickening_percent")[-1], 1)
    check("cup height (mm)", float(cell("cup height").split()[0]), col("cup_height")[-1], 2)
    check("margin to the forming limit (%)", float(cell("margin to the forming limit").split()[0]),
          col("flc_margin_percent")[-1], 1)
    got = float(cell("max penetration over the run").split()[0])
    expected = max(col("max_penetration"))
    verdict("max penetration (mm)", abs(got / expected - 1) < 1e-2, f"report {got}, run {expected:.6g}")
else:
    verdict("no steps: said so", "no step converged" in cell("formed part"))
steps, newton, cuts = (int(v) for v in re.findall(r"\d+", cell("steps, Newton iterations, time-step cuts"))[:3])
check("steps", steps, len(rows), 0)
check("Newton iterations", newton, sum(col("newton_iterations")), 0)
check("time-step cuts", cuts, sum(col("cutbacks")), 0)
if summary.get("fracture_criterion") == "none":
    verdict("fracture criterion", cell("fracture criterion").startswith("none chosen"))
else:
    stroke, critical = cell("critical stroke"), summary_travel("critical_stroke")
    good = stroke.startswith("not reached") if critical is None else abs(float(stroke.split()[0]) - critical) < 6e-4
    verdict("critical stroke", good, stroke)
release = summary_travel("holder_release_travel")
verdict("blank holder", (cell("blank holder") == "not released") == (release is None), cell("blank holder"))
ironing = cell("ironing (wall squeezed between punch and die)")
if summary_travel("ironing_travel") is None:
    verdict("ironing", ironing == "none", ironing)
else:
    m = re.search(r"wall pressure at most ([\d.]+) MPa", ironing)
    verdict("ironing: a wall pressure, no force", bool(m) and " force " not in ironing.replace("wall force", ""))
    check("largest ironing wall pressure (MPa)", float(m.group(1)), max(col("ironing_pressure")), 0)

# FLD zones: the report's counts, the program's, the sheet's.
counts = dict((n, int(c)) for n, c in re.findall(r"([a-z ]+?) (\d+)(?:, |$)", cell("FLD zones (columns)")))
got = [counts.get(z) for z in ZONES]
if as_of is None:
    source, expected = "run-summary.txt", [int(summary["columns_" + z.replace(" ", "_")]) for z in ZONES]
    sheet = list(csv.DictReader(open(os.path.join(run, "sheet.csv"))))
    in_sheet = [sum(1 for r in sheet if int(r["zone"]) == k) for k in range(len(ZONES))]
    verdict("zone counts = sheet.csv's zone column", got == in_sheet, f"report {got}, sheet.csv {in_sheet}")
else:  # the sheet of the last output at or before the travel: its step's row
    m = re.search(r"the part and the FLD at the output of ([-\d.]+) mm", text)
    row = [r for r in rows if m and abs(float(r["punch_travel"]) - float(m.group(1))) < 0.0051][-1:]
    source = "history.csv"
    expected = [int(float(row[0]["columns_" + z.replace(" ", "_")])) for z in ZONES] if row else None
if expected is None:  # the sheet of step 0: history.csv has no row for it
    print("zone counts: no history.csv row at the sheet's travel: not compared")
else:
    verdict(f"zone counts = {source}'s columns_*", got == expected, f"report {got}, {source} {expected}")

# No -1 sentinel in the key table.
key_table = text[text.index("## Key numbers"):text.index("## ", text.index("## Key numbers") + 3)]
sentinels = re.findall(r"(?<![\w.])[-−]1(?![\d.])[^|]{0,20}", key_table)
verdict("no -1 sentinel in the key table", not sentinels, "; ".join(sentinels))

# Pictures.
pictures = re.findall(r"!\[[^]]*\]\(([^)]+)\)", text)
expected = {"thickness-change.png", "penetration.png"}
if rows:
    expected |= {"force-travel.png", "damage.png"}
if os.path.exists(os.path.join(run, "sheet.csv")):
    expected |= {"thickness.png", "fld.png"}
    if summary.get("model") != "axisymmetric":
        drawn = summary.get("end_reason", "").startswith("drawn through") and as_of is None
        expected.add("earing.png" if drawn else "draw-in.png")
# The trimmed and the sprung part, drawn where the run wrote them.
for pattern, picture in (("trimmed_*.pvtu", "trimmed-part.png"), ("springback_*.pvtu", "springback-part.png")):
    if as_of is None and glob.glob(os.path.join(run, pattern)):
        expected.add(picture)
verdict("pictures in report.md", expected <= set(pictures), f"missing {sorted(expected - set(pictures))}")
for p in pictures:
    path = os.path.join(report, p)
    good = os.path.exists(path) and open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    spread = float(matplotlib.image.imread(path).std()) if good else 0.0
    verdict(p, good and spread > 0.01, f"pixel spread {spread:.3f}")
page = open(os.path.join(report, "report.html")).read()
table = re.findall(r"^\| ([^|]+) \| (.*) \|$", text, re.M)
missing = [q for q, v in table if q not in ("quantity", "---") and
           f"<tr><td>{html.escape(q)}</td><td>{html.escape(v)}</td></tr>" not in page]
embedded = re.findall(r"src='data:image/png;base64,([^']+)'", page)
verdict("report.html", not missing and len(embedded) == len(pictures) and all(
    base64.b64decode(e) == open(os.path.join(report, p), "rb").read() for e, p in zip(embedded, pictures)),
    f"{len(table) - 2} rows, {len(embedded)} embedded pictures{', missing ' + str(missing) if missing else ''}")
sys.exit(0 if ok else 1)
