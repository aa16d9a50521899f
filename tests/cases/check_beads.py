"""Equivalent draw beads (Tools/Draw beads) on the plane-strain channel.
Usage: check_beads.py RUN_DIR forces NO_BEAD_DIR F_R F_O WIDTH
         the run with a bead of F_R, F_O N/mm on a strip WIDTH mm wide (both
         flanges: the full strip carries 2 beads): the restraining work equals
         the bead's force times the material drawn across it, the rim's
         draw-in (<= 1 %); the force is F_R per unit length at full slip
         (<= 0.5 % once 0.5 mm is drawn in); the holder presses with its set
         force less the opening force (5e-5 of it,
         the force control's tolerance); the bead holds the flange back
         (draw-in falls, punch force rises, against NO_BEAD_DIR).
       check_beads.py RUN_DIR same NO_BEAD_DIR
         a bead with zero forces changes nothing: every column of history.csv
         and solver.csv but the wall time within 1e-9 (relative to the
         column's largest magnitude) of the run without a bead."""
import sys
import results

run, mode, plain = list(results.read(sys.argv[1])), sys.argv[2], list(results.read(sys.argv[3]))
key = [k for k in run[0] if k.startswith("bead_") and k.endswith("_force")][0][: -len("_force")]
fail = []
if mode == "same":
    assert len(run) == len(plain) >= 3, f"{len(run)} against {len(plain)} steps"
    worst, where = 0.0, ""
    for k in plain[0]:
        if k in ("wall_time",) or k not in run[0]:
            continue
        scale = max(max(abs(float(r[k])) for r in plain), 1e-30)
        for a, b in zip(run, plain):
            d = abs(float(a[k]) - float(b[k])) / scale
            if d > worst:
                worst, where = d, f"{k} at step {b['step']}"
    print(f"{len(run)} steps: largest difference {worst:.2e} ({where or 'none'})")
    if worst > 1e-9:
        fail.append(f"a zero-force bead changed {where} by {worst:.2e}")
    if any(float(r[key + "_force"]) != 0 or float(r[key + "_work"]) != 0 for r in run):
        fail.append("a zero-force bead reports a force or work")
else:
    f_r, f_o, width = map(float, sys.argv[4:7])
    full = 2 * f_r * width  # both flanges' beads
    work, prev_f, prev_d, worst_f = 0.0, 0.0, 0.0, 0.0
    for r in run:
        f, d = float(r[key + "_force"]), float(r["draw_in"])
        work += 0.5 * (f + prev_f) * (d - prev_d)
        prev_f, prev_d = f, d
        if d > 0.5:
            worst_f = max(worst_f, abs(f / full - 1))
    w = float(run[-1][key + "_work"])
    print(f"work {w:.6g} N mm against force x draw-in {work:.6g} N mm ({w / work - 1:+.2e}); "
          f"force within {worst_f:.2e} of {full:g} N at full slip")
    if abs(w / work - 1) > 0.01:
        fail.append(f"restraining work {w} differs from force x drawn {work} by more than 1 %")
    if worst_f > 0.005:
        fail.append(f"the bead force departs {worst_f:.2e} from {full} N")
    drawn = float(run[-1][key + "_drawn"])
    if abs(drawn - prev_d) > 0.01 * prev_d:
        fail.append(f"drawn across {drawn} mm against the rim's draw-in {prev_d} mm")
    opening = 2 * f_o * width
    worst_h = 0.0
    for r in run:
        if abs(float(r[key + "_opening"]) - opening) > 1e-9 * opening:
            fail.append(f"opening force {r[key + '_opening']} N, not {opening} N")
            break
        if int(float(r["holder_engaged"])):
            worst_h = max(worst_h, abs(float(r["force_blank_holder"]) - (19600 - opening)) / 19600)
    print(f"opening force {opening:g} N; holder force within {worst_h:.1e} of the set force less it")
    if worst_h > 5e-5:
        fail.append(f"the holder's force departs {worst_h:.2e} from 19600 N less the opening force")
    a, b = run[-1], plain[-1]
    print(f"at {a['punch_travel']} mm: draw-in {float(a['draw_in']):.4f} mm with the bead, "
          f"{float(b['draw_in']):.4f} without; punch force {float(a['punch_force']):.1f} N, "
          f"{float(b['punch_force']):.1f} without")
    if not (float(a["draw_in"]) < float(b["draw_in"]) and float(a["punch_force"]) > float(b["punch_force"])):
        fail.append("the bead does not hold the flange back")
for f in fail:
    print("FAIL:", f)
sys.exit(1 if fail else 0)
