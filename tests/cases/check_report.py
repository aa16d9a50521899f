"""The run report: report/report.md says what history.csv and
run-summary.txt say (peak punch force and its travel, the final minimum
thickness and thinning, thickening, cup height and the margin to the forming
limit, the largest penetration, steps, Newton iterations and cuts, the
critical stroke); every PNG it embeds, the two rendered pictures included,
is a PNG that is not blank (its pixels are not all one colour); report.html
holds the same table rows and embeds the same pictures."""
import csv, os, re, sys
import results

run = sys.argv[1]
report = os.path.join(run, "report")
text = open(os.path.join(report, "report.md")).read()
rows = list(results.read(run))
col = lambda k: [float(r[k]) for r in rows]
ok = True


def check(what, got, expected, digits):
    """got as printed with `digits` significant or decimal places."""
    global ok
    good = abs(got - expected) <= 0.51 * 10 ** (-digits) * (1 if digits > 0 else 1)
    print(f"{what}: report {got}, history.csv {expected:.6g}: {'ok' if good else 'WRONG'}")
    ok = ok and good


def cell(name):
    m = re.search(r"^\| " + re.escape(name) + r" \| (.*) \|$", text, re.M)
    if not m:
        raise SystemExit(f"report.md has no row '{name}'")
    return m.group(1)


force = col("punch_force")
peak = max(range(len(rows)), key=lambda i: force[i])
m = re.match(r"([-\d.]+) N at ([-\d.]+) mm", cell("peak punch force"))
check("peak punch force (N)", float(m.group(1)), force[peak], 0)
check("its punch travel (mm)", float(m.group(2)), col("force_travel")[peak], 2)
m = re.match(r"([-\d.]+) mm \(thinning ([-\d.]+) %\)", cell("minimum thickness"))
check("final minimum thickness (mm)", float(m.group(1)), col("min_thickness")[-1], 4)
check("final thinning (%)", float(m.group(2)), col("max_thinning_percent")[-1], 1)
got = float(cell("max penetration over the run").split()[0])
expected = max(col("max_penetration"))
good = abs(got / expected - 1) < 1e-2
print(f"max penetration (mm): report {got}, history.csv {expected:.6g}: {'ok' if good else 'WRONG'}")
ok = ok and good
steps, newton, cuts = (int(v) for v in cell("steps, Newton iterations, time-step cuts").split(", "))
check("steps", steps, len(rows), 0)
check("Newton iterations", newton, sum(col("newton_iterations")), 0)
check("time-step cuts", cuts, sum(col("cutbacks")), 0)
check("largest thickening (%)", float(cell("largest thickening").split()[0]), col("max_thickening_percent")[-1], 1)
check("cup height (mm)", float(cell("cup height").split()[0]), col("cup_height")[-1], 2)
check("margin to the forming limit (%)", float(cell("margin to the forming limit").split()[0]),
      col("flc_margin_percent")[-1], 1)
oyane = max(col("max_oyane"))
stroke = cell("critical stroke")
good = ("no fracture" in stroke) == (oyane < 1)
print(f"critical stroke: '{stroke}', largest Oyane I {oyane:.3g}: {'ok' if good else 'WRONG'}")
ok = ok and good

pictures = re.findall(r"!\[[^]]*\]\(([^)]+)\)", text)
expected = {"force-travel.png", "thickness.png", "fld.png", "damage.png", "thickness-change.png", "penetration.png"}
if expected - set(pictures):
    print("not in report.md:", sorted(expected - set(pictures)))
    ok = False
import base64, html, io
import matplotlib.image
for p in pictures:
    path = os.path.join(report, p)
    good = os.path.exists(path) and open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    spread = float(matplotlib.image.imread(path).std()) if good else 0.0
    good = good and spread > 0.01
    print(f"{p}: {'ok' if good else 'MISSING OR BLANK'} (pixel spread {spread:.3f})")
    ok = ok and good
page = open(os.path.join(report, "report.html")).read()
rows = re.findall(r"^\| ([^|]+) \| (.*) \|$", text, re.M)
missing = [q for q, v in rows if q != "quantity" and q != "---" and
           f"<tr><td>{html.escape(q)}</td><td>{html.escape(v)}</td></tr>" not in page]
embedded = re.findall(r"src='data:image/png;base64,([^']+)'", page)
good = not missing and len(embedded) == len(pictures) and all(
    base64.b64decode(e) == open(os.path.join(report, p), "rb").read() for e, p in zip(embedded, pictures))
print(f"report.html: {len(rows) - 1} rows, {len(embedded)} embedded pictures: "
      f"{'ok' if good else 'DIFFERS: ' + str(missing)}")
ok = ok and good
sys.exit(0 if ok else 1)
