"""The springback of the plane-strain channel (channel-springback.prm):
- the release's load is the tools' forces of the last step, and the end
  stress is in equilibrium with them on the forming's element: the
  imbalance |g| / |int B^T sigma_end dV| <= 1e-9 (3e-12 measured; about 1
  when the stress is taken on the moved mesh instead of the step's own);
- the release converged (|r|/|f| <= 1e-8), held by the minimal support (one
  z at x = 0);
- the sprung part's file (springback_<step>.pvtu) is there;
- stored values: largest displacement component 1.9335233 mm and the
  volume fraction that yields again, 0.017244593, within 2e-3 relative (1
  rank; a change in the forming or the release moves them by far more, but
  round-off decides the contact status of this channel's flange, which
  moved its punch force by 4.9e-5 between 1 and 2 ranks: doc/plane-strain.md)."""
import glob, os, sys

out = sys.argv[1]
s = dict(l.split(" = ", 1) for l in open(os.path.join(out, "run-summary.txt")).read().splitlines()
         if " = " in l)
checks = [
    ("springback done", s.get("springback") == "done"),
    ("load: tool forces", s.get("springback_load") == "tool forces"),
    ("imbalance <= 1e-9", float(s["springback_imbalance"]) <= 1e-9),
    ("residual <= 1e-8", float(s["springback_residual"]) <= 1e-8),
    ("minimal support", s["springback_supports"].startswith("z at (x 0,")),
    ("springback file", len(glob.glob(os.path.join(out, "springback_*.pvtu"))) == 1),
    ("largest displacement as stored",
     abs(float(s["springback_max_displacement"]) / 1.9335233 - 1) <= 2e-3),
    ("yielded fraction as stored", abs(float(s["springback_yielded_fraction"]) / 0.017244593 - 1) <= 2e-3),
]
for what, ok in checks:
    print(("ok   " if ok else "FAIL ") + what)
print({k: v for k, v in s.items() if k.startswith("springback_")})
sys.exit(0 if all(ok for _, ok in checks) else 1)
