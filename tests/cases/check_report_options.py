"""formsolve-report's command line: check_report_options.py REPORT_TOOL RUN.

--help prints the usage and exits 0; an unknown option or a bad value is
one line on stderr and exit status 2; a travel past the run's end too.
--travel T (T: half the run's final travel) with --view section, --range and
--no-tools writes RUN/report-<T>mm/, which check_report.py then checks
against history.csv up to T; --output writes the report elsewhere."""
import csv
import os
import subprocess
import sys

tool, run = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
ok = True


def call(*args):
    return subprocess.run([tool, *args], capture_output=True, text=True)


def verdict(what, good, detail=""):
    global ok
    print(f"{what}: {detail}{': ' if detail else ''}{'ok' if good else 'WRONG'}")
    ok = ok and good


done = call("--help")
verdict("--help", done.returncode == 0 and "usage: formsolve-report" in done.stdout and "--travel" in done.stdout)
for bad in (["--bogus", run], ["--view", "front", run], ["--range", "5", "1", run], ["--travel", "1e9", run], []):
    done = call(*bad)
    lines = done.stderr.strip().splitlines()
    verdict(" ".join(bad) or "no folder", done.returncode == 2 and len(lines) == 1, lines[-1] if lines else "")

rows = list(csv.DictReader(open(os.path.join(run, "history.csv"))))
travel = round(float(rows[len(rows) // 2]["punch_travel"]), 2) if rows else 0.0
done = call(run, "--travel", f"{travel:g}", "--view", "section", "--range", "0", "20", "--no-tools")
verdict(f"--travel {travel:g}", done.returncode == 0, done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "")
report = os.path.join(run, f"report-{travel:g}mm")
done = subprocess.run([sys.executable, os.path.join(here, "check_report.py"), run, report],
                      capture_output=True, text=True)
print(done.stdout, end="")
verdict("check_report.py on it", done.returncode == 0)
elsewhere = os.path.join(run, "report-elsewhere")
done = call(run, "--output", elsewhere, "--view", "top")
verdict("--output", done.returncode == 0 and os.path.exists(os.path.join(elsewhere, "report.html")))
sys.exit(0 if ok else 1)
