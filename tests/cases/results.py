"""A run's step table: history.csv (the process) and solver.csv (how each
step was solved) merged row by row into one dict per step, history.csv's
columns first. read() takes an output folder, a history.csv with its
solver.csv beside it, or a stored reference (already merged)."""
import csv
import os


def read(path):
    if os.path.isdir(path):
        path = os.path.join(path, "history.csv")
    rows = list(csv.DictReader(open(path)))
    solver = os.path.join(os.path.dirname(path), "solver.csv")
    if os.path.basename(path) == "history.csv" and os.path.exists(solver):
        extra = list(csv.DictReader(open(solver)))
        if len(extra) != len(rows):
            raise SystemExit(f"FAIL: {solver} has {len(extra)} rows, history.csv {len(rows)}")
        for r, s in zip(rows, extra):
            if r["step"] != s["step"]:
                raise SystemExit(f"FAIL: step {s['step']} of solver.csv beside step {r['step']}")
            r.update((k, v) for k, v in s.items() if k not in r)
    return rows
