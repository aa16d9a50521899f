"""The plane-strain section against its 3-D slice (channel-slice.prm, the same
draw with one element across a width b and symmetry on both y faces): per
unit width, the punch, die and holder forces of every step agree within
5e-4 of the step's die force (1.7e-4 measured), the minimum thickness within
1e-4 mm (3e-5) and the part height within 0.025 mm (7.7e-3).
Usage: compare_slice.py SLICE_DIR SECTION_DIR"""
import sys
import results

SECTION_WIDTH, SLICE_WIDTH = 35.0, 1.3671875
slice_rows, section_rows = list(results.read(sys.argv[1])), list(results.read(sys.argv[2]))
assert len(slice_rows) == len(section_rows) >= 3, f"{len(slice_rows)} against {len(section_rows)} steps"
worst = {"force": 0.0, "thickness": 0.0, "height": 0.0}
for a, b in zip(slice_rows, section_rows):
    die = float(b["force_die"]) / SECTION_WIDTH
    for k in ("force_punch", "force_die", "force_blank_holder"):
        d = abs(float(a[k]) / SLICE_WIDTH - float(b[k]) / SECTION_WIDTH) / die
        worst["force"] = max(worst["force"], d)
    worst["thickness"] = max(worst["thickness"], abs(float(a["min_thickness"]) - float(b["min_thickness"])))
    worst["height"] = max(worst["height"], abs(float(a["cup_height"]) - float(b["cup_height"])))
print(f"{len(slice_rows)} steps: forces per unit width within {worst['force']:.2e} of the die's, "
      f"minimum thickness within {worst['thickness']:.2e} mm, part height within {worst['height']:.2e} mm")
sys.exit(0 if worst["force"] <= 5e-4 and worst["thickness"] <= 1e-4 and worst["height"] <= 0.025 else 1)
