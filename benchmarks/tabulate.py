"""Table of run-summary.txt and history.csv of benchmark runs (Markdown)."""
import csv, sys
from run_tables import steps  # noqa: E402

out, levels = sys.argv[1], sys.argv[2:]
rows = []
for l in levels:
    s = dict(line.split(" = ") for line in open(f"{out}/level-{l}/run-summary.txt").read().splitlines())
    s = {k: float(v) for k, v in s.items()}
    h = steps(f"{out}/level-{l}")
    rows.append((l, s, h))
print("| planform refinements | DoFs | ranks | steps | Newton it./step | linear it./solve | wall time (s) | µs per Newton it. per DoF | peak memory, all ranks (MB) | kB per DoF | peak punch force (kN) | max penetration (mm) |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for l, s, h in rows:
    us = s["newton_wall_time"] / s["newton_iterations"] / s["dofs"] * 1e6
    print(f"| {l} | {int(s['dofs'])} | {int(s['ranks'])} | {int(s['steps'])} | "
          f"{s['newton_iterations'] / s['steps']:.1f} | {s['linear_iterations'] / s['newton_iterations']:.1f} | "
          f"{s['wall_time']:.0f} | {us:.1f} | {s['peak_memory_kb_all_ranks'] / 1024:.0f} | "
          f"{s['peak_memory_kb_all_ranks'] / s['dofs']:.1f} | "
          f"{max(float(r['punch_force']) for r in h) / 1000:.2f} | "
          f"{max(float(r['max_penetration']) for r in h):.2e} |")
if len(rows) >= 2:
    (l0, s0, _), (l1, s1, _) = rows[0], rows[-1]
    slope = (s1["peak_memory_kb_all_ranks"] - s0["peak_memory_kb_all_ranks"]) / (s1["dofs"] - s0["dofs"])
    print(f"\nMarginal memory between refinements {l0} and {l1}: {slope:.2f} kB per additional DoF "
          "(the rest is the fixed cost of loading deal.II, Trilinos, PETSc and MPI).")
