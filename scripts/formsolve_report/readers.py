"""formsolve's text outputs as the report reads them: run-summary.txt's
"key = value" lines, the CSV files (history, solver, sheet, flc, earing),
and the error exit for what cannot be read."""
import csv
import sys


def fail(message):
    """Exit status 1: no report can be written (no output folder, no matplotlib)."""
    print("formsolve-report: " + message, file=sys.stderr)
    sys.exit(1)


def read_summary(path):
    with open(path) as f:
        return dict(l.rstrip("\n").split(" = ", 1) for l in f if " = " in l)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(row for row in f if not row.startswith("#")))


def column(rows, name):
    return [float(r[name]) for r in rows]


def number(summary, key):
    """A run-summary value as a float; None if absent or not a number."""
    try:
        return float(summary[key])
    except (KeyError, ValueError):
        return None


def reached(summary, key, upto=None):
    """A travel of run-summary.txt; None for its -1 (never happened) and for
    one past the report's travel."""
    value = number(summary, key)
    if value is None or value < 0 or (upto is not None and value > upto + 1e-9):
        return None
    return value
