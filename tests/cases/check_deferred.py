"""Deferred tangent (Nonlinear solver/Deferred tangent): OUT is a run with it
off, DEFAULT the same case with it on (the default). Deferring a tangent only
changes when the matrix of an iterate is assembled, never the iterates: every
history.csv column but the wall time must agree to rounding (relative 1e-12),
the Newton iterations step by step. The default run must have assembled
fewer matrices (the deferral happened and was not undone by misses).

Usage: check_deferred.py OUT DEFAULT"""
import csv, os, sys
import results

out, default = sys.argv[1:3]


def rows(run):
    return list(results.read(run))


def summary(run):
    lines = open(os.path.join(run, "run-summary.txt"))
    return dict(l.rstrip("\n").split(" = ", 1) for l in lines if " = " in l)


off, on = rows(out), rows(default)
ok = len(off) == len(on) > 0
if not ok:
    print(f"{len(off)} steps without deferral, {len(on)} with")
for a, b in zip(off, on):
    for key in a:
        if key == "wall_time":
            continue
        try:
            x, y = float(a[key]), float(b[key])
        except ValueError:
            same = a[key] == b[key]
        else:
            same = abs(x - y) <= 1e-12 * max(abs(x), abs(y)) + 1e-300
        if not same:
            print(f"step {a['step']}: {key} = {a[key]} without deferral, {b[key]} with")
            ok = False
m_off = int(summary(out)["matrix_assemblies"])
m_on = int(summary(default)["matrix_assemblies"])
newton = int(summary(default)["newton_iterations"])
print(f"{newton} Newton iterations; matrix assemblies {m_off} without deferral, {m_on} with")
sys.exit(0 if ok and m_on < m_off else 1)
