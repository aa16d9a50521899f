"""The run report: report/report.md and every PNG it embeds exist and are
non-empty PNG files, including the two rendered pictures."""
import os, re, sys

report = os.path.join(sys.argv[1], "report")
text = open(os.path.join(report, "report.md")).read()
pictures = re.findall(r"!\[[^]]*\]\(([^)]+)\)", text)
expected = {"force-travel.png", "thickness.png", "fld.png", "damage.png", "thinning.png", "penetration.png"}
missing = expected - set(pictures)
ok = not missing
for p in pictures:
    path = os.path.join(report, p)
    good = os.path.exists(path) and os.path.getsize(path) > 1000 and open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    print(f"{p}: {'ok' if good else 'MISSING OR EMPTY'}")
    ok = ok and good
if missing:
    print("not in report.md:", sorted(missing))
for key in ("peak punch force", "minimum thickness", "critical stroke", "max penetration"):
    ok = ok and key in text
sys.exit(0 if ok else 1)
