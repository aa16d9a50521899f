"""The reference cups of the three steels (`doc/reference-scenes.md` (section
1)) with Hosford's isotropic non-quadratic criterion at a = 6 beside the
Hill48 normal-anisotropy runs of forming_results.py: same scene, mesh (128 x 4),
time step (0.25 s), holder at Siebel's force, mu = 0.1, Oyane's criterion.
Hosford is isotropic (r = 1): its fracture constants are used as published
(the normal-anisotropy conversion k is 1 at r = 1), a choice the data do not
fix. Written into doc/forming-results.md between the hosford markers.

Usage: hosford_steels.py [--force]; runs are kept in results/forming/."""
import argparse

import forming_results as fr

HOSFORD = {"Material/Yield criterion": "Hosford", "Material/Yield exponent": 6}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--force", action="store_true")
    args = ap.parse_args()
    lines = ["| case | criterion | critical stroke (mm), through-thickness average | "
             "critical stroke (mm), local maximum | min thickness (mm) | peak punch force (kN) | end |",
             "|---|---|---|---|---|---|---|"]
    for m, d0, rp in fr.CASES:
        for label, extra in (("Hill48, r as published", None), ("Hosford, a = 6", HOSFORD)):
            name = f"{m}-d{d0}-rp{rp}-ref6-l4-dt0.25" + ("-hosford6" if extra else "")
            s = fr.run(name, m, d0, rp, 6, 4, 0.25, force=args.force, extra=extra)
            cs = float(s.get("critical_stroke_through_thickness", -1))
            cl = float(s.get("critical_stroke_local", -1))
            lines.append(f"| {m}, d0 = {d0}, r_p = {rp} | {label} | "
                         f"{fr.fmt(cs) if cs >= 0 else 'none'} | {fr.fmt(cl) if cl >= 0 else 'none'} | "
                         f"{fr.fmt(s.get('min_thickness', 'nan'), 4)} | "
                         f"{fr.fmt(float(s.get('peak_punch_force', 'nan')) / 1000)} | {s.get('end_reason', '')} |")
    fr.write_block("hosford", lines)


if __name__ == "__main__":
    main()
