"""Bounded random-mutation fuzzing of the .prm-to-scene set-up path.

Each case mutates a complete, valid parameter file (a seed) and runs
`formsolve case.prm --validate`, which parses, validates, builds the mesh and
tools and checks the initial scene, then stops. The outcome must be either
acceptance (exit 0) or one clean rejection: exit 1 and exactly one line
"formsolve: error: ..." on standard error. Anything else -- a signal, an
abort, another exit status, a hang beyond the time limit, a message spread
over several lines -- is a finding; its input is kept in OUTDIR/findings/.

Usage: fuzz_prm.py FORMSOLVE OUTDIR [--seconds S] [--cases N] [--seed K]
                   [--seed-file PRM]...
Exit status 1 if there are findings."""
import argparse, os, random, re, subprocess, sys, time

SPECIAL = ["nan", "NaN", "inf", "-inf", "1e308", "-1e308", "1e-308", "0", "-0",
           "-1", "1", "2147483648", "-2147483649", "99999999999999999999", "",
           "abc", "true", "1,2", "0x10", "1e", "--1", "\u00e9", "x" * 5000,
           "1.5.2", "  ", "3 4"]


def mutate(lines, rng):
    lines = list(lines)
    sets = [i for i, l in enumerate(lines) if l.strip().startswith("set ")]
    kind = rng.choice(["value", "value", "value", "value", "scale", "delete",
                       "duplicate", "truncate", "garbage", "swap", "name"])
    if kind in ("value", "scale") and sets:
        i = rng.choice(sets)
        head, _, value = lines[i].partition("=")
        value = value.strip()
        if kind == "scale" and re.fullmatch(r"[-+0-9.eE]+", value or "x"):
            try:
                v = float(value) * rng.choice([-1, 0, 1e-6, 1e-3, 0.1, 10, 1e3, 1e6])
                value = repr(v)
            except ValueError:
                value = rng.choice(SPECIAL)
        else:
            value = rng.choice(SPECIAL)
        lines[i] = head + "= " + value
        what = f"{head.strip()}= {value[:40]!r}"
    elif kind == "delete" and lines:
        i = rng.randrange(len(lines))
        what = f"deleted line {i}: {lines[i].strip()[:60]!r}"
        del lines[i]
    elif kind == "duplicate" and lines:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
        what = f"duplicated line {i}"
    elif kind == "swap" and len(lines) > 1:
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
        what = f"swapped lines {i} and {j}"
    elif kind == "name" and sets:
        i = rng.choice(sets)
        lines[i] = lines[i].replace("set ", "set X", 1)
        what = f"renamed the entry of line {i}"
    elif kind == "truncate":
        text = "\n".join(lines)
        cut = rng.randrange(len(text) + 1)
        return text[:cut], f"truncated at character {cut}"
    else:
        i = rng.randrange(len(lines) + 1)
        junk = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 200)))
        lines.insert(i, junk.decode("latin-1"))
        what = f"binary garbage at line {i}"
    return "\n".join(lines) + "\n", what


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("out")
    ap.add_argument("--seconds", type=float, default=60)
    ap.add_argument("--cases", type=int, default=10 ** 9)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seed-file", action="append", default=[])
    ap.add_argument("--timeout", type=float, default=30)
    a = ap.parse_args()
    os.makedirs(os.path.join(a.out, "findings"), exist_ok=True)
    rng = random.Random(a.seed)
    seeds = [open(f, encoding="latin-1").read().splitlines() for f in a.seed_file]
    if not seeds:
        seeds = [subprocess.run([a.exe, "--print-parameters"], capture_output=True,
                                text=True, check=True).stdout.splitlines()]
    start, n, counts, findings = time.time(), 0, {}, []
    while time.time() - start < a.seconds and n < a.cases:
        n += 1
        # One to three mutations of one seed.
        text, what = "\n".join(rng.choice(seeds)) + "\n", []
        for _ in range(rng.choice([1, 1, 2, 3])):
            text, w = mutate(text.splitlines(), rng)
            what.append(w)
        case = os.path.join(a.out, "case.prm")
        with open(case, "w", encoding="latin-1") as f:
            f.write(text)
        try:
            r = subprocess.run([a.exe, case, "--validate",
                                "--set", f"Output/Output directory={a.out}/never-written"],
                               capture_output=True, timeout=a.timeout)
            # formsolve's messages are UTF-8; a terminal breaks lines at
            # '\n' only.
            err = r.stderr.decode("utf-8", errors="replace")
            lines = [l for l in err.split("\n") if l.strip()]
            if r.returncode == 0:
                outcome = "accepted"
            elif (r.returncode == 1 and len(lines) == 1 and "\ufffd" not in err
                  and lines[0].startswith("formsolve: error: ")):
                outcome = "rejected"
            else:
                outcome = f"FINDING exit {r.returncode}"
        except subprocess.TimeoutExpired:
            outcome, err = f"FINDING hang > {a.timeout} s", ""
        counts[outcome.split(" exit")[0].split(" hang")[0]] = counts.get(outcome.split(" exit")[0].split(" hang")[0], 0) + 1
        if outcome.startswith("FINDING"):
            path = os.path.join(a.out, "findings", f"finding-{n}.prm")
            with open(path, "w", encoding="latin-1") as f:
                f.write(text)
            findings.append((path, outcome, "; ".join(what), err[-500:]))
    if os.path.exists(os.path.join(a.out, "never-written")):
        findings.append(("-", "FINDING", "--validate wrote the output folder", ""))
    took = time.time() - start
    print(f"{n} cases in {took:.0f} s (seed {a.seed}): " +
          ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for path, outcome, what, err in findings:
        print(f"{outcome}: {path}: {what}\n    {err.strip()[:400]}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
