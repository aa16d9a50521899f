"""Run: what the report reads of an output folder (run-summary.txt,
history.csv, solver.csv, flc.csv, the sheet's columns, the VTU output to
render), cut at --travel."""
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

from .readers import column, fail, number, read_csv, read_summary
from .vtu import sheet_from_vtu
from .zones import ZONES, zone_key


class Run:
    """What the report reads of an output folder, cut at --travel."""

    def __init__(self, args):
        d = self.directory = args.directory
        for name in ("history.csv", "run-summary.txt"):
            if not os.path.exists(os.path.join(d, name)):
                fail(f"{d} has no {name}: not a formsolve output folder")
        self.summary = read_summary(os.path.join(d, "run-summary.txt"))
        self.model = self.summary.get("model", "")
        self.axisymmetric = self.model == "axisymmetric"
        self.plane_strain = self.model == "plane strain"
        self.section = self.axisymmetric or self.plane_strain  # a 2-D model
        history = read_csv(os.path.join(d, "history.csv"))
        solver_csv = os.path.join(d, "solver.csv")
        solver = read_csv(solver_csv) if os.path.exists(solver_csv) else []
        self.final_travel = float(history[-1]["punch_travel"]) if history else 0.0
        self.as_of = args.travel
        if self.as_of is not None and self.as_of > self.final_travel + 1e-9:
            print(f"formsolve-report: --travel {self.as_of:g}: the run ended at punch travel "
                  f"{self.final_travel:g} mm", file=sys.stderr)
            sys.exit(2)
        keep = (lambda r: True) if self.as_of is None else \
            (lambda r: float(r["punch_travel"]) <= self.as_of + 1e-6)
        self.history = [r for r in history if keep(r)]
        self.solver = [r for r in solver if keep(r)]
        self.travel = float(self.history[-1]["punch_travel"]) if self.history else 0.0
        self.choose_output()
        self.read_flc()
        self.sheet, self.sheet_source, self.sheet_travel = self.read_sheet()

    def step_travel(self, step):
        if step == 0:
            return 0.0
        for r in self.history:
            if int(r["step"]) == step:
                return float(r["punch_travel"])
        return None  # past --travel or not a recorded step

    def choose_output(self):
        """The last VTU output at or before the report's travel, and the
        revolved copy and tools written with it."""
        self.vtu = self.revolved = self.tools = None
        self.vtu_step, self.vtu_travel = None, None
        pvd = os.path.join(self.directory, "solution.pvd")
        if not os.path.exists(pvd):
            return
        for ds in ET.parse(pvd).getroot().iter("DataSet"):
            name = ds.get("file")
            m = re.search(r"_(\d+)\.p?vtu$", name)
            step = int(m.group(1)) if m else None
            travel = self.step_travel(step) if step is not None else None
            if travel is not None and os.path.exists(os.path.join(self.directory, name)):
                self.vtu, self.vtu_step, self.vtu_travel = name, step, travel
        if self.vtu is None:
            return
        for attr, name in (("revolved", f"revolved_{self.vtu_step:05d}.pvtu"),
                           ("tools", f"tools_{self.vtu_step:05d}.vtu")):
            if os.path.exists(os.path.join(self.directory, name)):
                setattr(self, attr, name)

    def read_flc(self):
        path = os.path.join(self.directory, "flc.csv")
        self.flc = None
        if os.path.exists(path):
            rows = read_csv(path)
            self.flc = (column(rows, "minor_strain"), column(rows, "major_strain"))

    def summary_flc0(self):
        """run-summary.txt's flc0, the program's own value; None in older
        folders (no key) and when it is NaN."""
        value = number(self.summary, "flc0")
        return value if value is not None and math.isfinite(value) else None

    def flc0_source(self):
        return "run-summary.txt's flc0" if self.summary_flc0() is not None else "flc.csv at minor strain 0"

    def flc0(self):
        """The FLC's true major strain at minor strain 0: run-summary.txt's
        flc0, else interpolated in flc.csv."""
        if self.summary_flc0() is not None:
            return self.summary_flc0()
        if self.flc is None:
            return None
        xs, ys = self.flc
        for k in range(1, len(xs)):
            if xs[k - 1] <= 0 <= xs[k]:
                w = (0 - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 0
                return ys[k - 1] + w * (ys[k] - ys[k - 1])
        return None

    def read_sheet(self):
        """(rows as sheet.csv's, where they come from, their punch travel)."""
        d = self.directory
        if self.as_of is None:
            path = os.path.join(d, "sheet.csv")
            if os.path.exists(path):
                return self.numeric(read_csv(path)), "sheet.csv", self.travel
            return [], "no sheet.csv", None
        for name in os.listdir(d):
            m = re.fullmatch(r"sheet_([0-9.eE+-]+)mm\.csv", name)
            if m and abs(float(m.group(1)) - self.as_of) < 1e-6:
                return self.numeric(read_csv(os.path.join(d, name))), name, self.as_of
        if self.vtu is None:
            return [], f"no sheet_{self.as_of:g}mm.csv and no VTU output before it", None
        try:
            rows = sheet_from_vtu(os.path.join(d, self.vtu), self.section)
        except ImportError:
            return [], f"no sheet_{self.as_of:g}mm.csv, and python3-vtk9 is missing to read {self.vtu}", None
        return rows, f"{self.vtu} (its nodal fields; no sheet_{self.as_of:g}mm.csv)", self.vtu_travel

    @staticmethod
    def numeric(rows):
        out = []
        for r in rows:
            row = {k: float(v) for k, v in r.items() if k != "zone_name"}
            row["zone"] = int(row["zone"])
            out.append(row)
        return out

    def zone_counts(self):
        counts = [0] * len(ZONES)
        for r in self.sheet:
            counts[r["zone"]] += 1
        return counts

    def expected_zone_counts(self):
        """The program's own counts for the sheet shown: run-summary.txt at
        the end, history.csv's row of the sheet's step at a travel."""
        if self.as_of is None:
            source, values = "run-summary.txt", self.summary
        else:
            rows = [r for r in self.history if abs(float(r["punch_travel"]) - (self.sheet_travel or 0)) < 1e-6]
            if not rows:
                return None, None
            source, values = f"history.csv (step {rows[-1]['step']})", rows[-1]
        try:
            return source, [int(float(values["columns_" + zone_key(n)])) for n, _ in ZONES]
        except KeyError:
            return None, None
