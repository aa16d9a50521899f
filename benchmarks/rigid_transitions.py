#!/usr/bin/python3
"""Rigid-plastic transitions per step, from run logs written with
`Nonlinear solver/Log iterations = true` (the `rigid points: n (+a/-b)`
field; stress-velocity tangent).

Groups the steps by the last iteration in which a quadrature point crossed
the limiting strain rate (0: none after the step's first iterate; 4: four or
later) and prints, per group, the steps, their mean Newton iterations, the
mean last iteration that changed the contact set, and in how many steps the
last crossing came after the last contact change. A markdown row per log.

Usage: rigid_transitions.py LABEL=LOG [LABEL=LOG ...]
"""
import re
import sys

ITERATION = re.compile(r"^ +it +(\d+) .*rigid points: (\d+) \(\+(\d+)/-(\d+)\)")
STEP = re.compile(r"^step +(\d+) .*newton= *(\d+)")


def steps_of(path):
    steps, iterations = [], []
    with open(path) as log:
        for line in log:
            m = ITERATION.match(line)
            if m:
                it, _, to_rigid, to_plastic = (int(x) for x in m.groups())
                iterations.append(
                    (it, to_rigid + to_plastic, "contact set changed" in line))
                continue
            m = STEP.match(line)
            if m:
                steps.append((int(m.group(2)), iterations))
                iterations = []
    return steps


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    print("| run | iterations/step | steps by the last iteration with a "
          "rigid-plastic crossing: none / 1 / 2 / 3 / ≥ 4 | their mean "
          "iterations | crossing after the last contact change (steps) | "
          "crossings per step |")
    print("|---|---|---|---|---|---|")
    for argument in sys.argv[1:]:
        label, path = argument.split("=", 1)
        steps = steps_of(path)
        if not steps:
            sys.exit(f"{path}: no steps with 'rigid points' in the log")
        groups = {k: [] for k in range(5)}
        after = 0
        crossings = 0
        for newton, its in steps:
            last_cross = max([it for it, n, _ in its if n > 0 and it > 0],
                             default=0)
            last_contact = max([it for it, _, c in its if c], default=0)
            groups[min(last_cross, 4)].append(newton)
            after += last_cross > last_contact
            crossings += sum(n for it, n, _ in its if it > 0)
        total = sum(newton for newton, _ in steps)
        counts = " / ".join(str(len(groups[k])) for k in range(5))
        means = " / ".join(
            f"{sum(g) / len(g):.2f}" if g else "–" for g in groups.values())
        print(f"| {label} | {total / len(steps):.2f} | {counts} | {means} | "
              f"{after} | {crossings / len(steps):.0f} |")


if __name__ == "__main__":
    main()
