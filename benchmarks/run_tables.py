"""Shared by the benchmark scripts: read a run's run-summary.txt and the timer
table of its log, write rows as CSV and print them as a Markdown table."""
import csv
import os
import re
import sys

# history.csv and solver.csv of a run merged, one dict per step (the tests'
# reader: tests/cases/results.py).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "cases"))
from results import read as steps  # noqa: E402


def summary(run_dir):
    """run-summary.txt as a dict of strings."""
    return dict(line.rstrip("\n").split(" = ", 1)
                for line in open(f"{run_dir}/run-summary.txt") if " = " in line)


def section(log, name):
    """(calls, seconds) of timer section @p name in a run's log; (0, 0) if absent."""
    m = re.search(r"\| " + re.escape(name) + r"\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s", log)
    return (int(m.group(1)), float(m.group(2))) if m else (0, 0.0)


def write(rows, csv_path, csv_digits=4, table_digits=3):
    """Rows (dicts with the same keys) to @p csv_path and as a table to stdout."""
    with open(csv_path, "w") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.{csv_digits}g}" if isinstance(v, float) else v) for k, v in r.items()})
    keys = list(rows[0])
    print("| " + " | ".join(keys) + " |")
    print("|" + "---|" * len(keys))
    for r in rows:
        print("| " + " | ".join(f"{r[k]:.{table_digits}g}" if isinstance(r[k], float) else str(r[k])
                                for k in keys) + " |")
