#!/usr/bin/env bash
# Magnitude checks and Siebel's force (--validate, nothing written):
# - Force = siebel on the default cup with R_m = 488 MPa gives the 2671 N its
#   .prm derives by hand; R_m from the flow curve at Considere's uniform
#   strain: Swift 829 (0.002 + eps)^0.2 -> 829 0.2^0.2 e^-0.198 = 492.9 MPa,
#   Voce 330.2 - 190 exp(-12.4 eps) -> 259.1 MPa;
# - lengths in metres, stresses in Pa or GPa, a speed in m/s, a holder force
#   far from Siebel's, mu > 0.5, a clearance below the thickness (ironing), a
#   step longer than the elements, one layer where the sheet bends, a tool
#   that can never reach the sheet, a Voce curve with Keeler-Brazier's FLC
#   each get one warning naming the entry; the shipped case none;
# - a blank diameter in metres is named as such in the error it leads to,
#   and Oyane's criterion without its constants is refused.
set -uo pipefail
exe=$1 prm=$2
fail=0
run() { "$exe" --validate "$prm" "$@" 2>&1; }
has() { # NAME PATTERN OUTPUT
  if grep -qF -- "$2" <<< "$3"; then echo "ok   $1"; else echo "FAIL $1: no '$2' in:"; echo "$3"; fail=1; fi
}
out=$(run --set "Tools/Blank holder/Force=siebel" --set "Material/Tensile strength=488")
has siebel_force "blank-holder force by Siebel's rule: 2671" "$out"
out=$(run --set "Tools/Blank holder/Force=siebel")
has considere_swift "R_m = 492.9" "$out"
out=$(run --set "Tools/Blank holder/Force=siebel" --set "Material/Flow curve=voce" \
  --set "Material/Voce saturation stress=330.2" --set "Material/Voce hardening amplitude=190" \
  --set "Material/Voce hardening rate=12.4")
has considere_voce "R_m = 259.1" "$out"
out=$(run)
if grep -q "warning" <<< "$out"; then echo "FAIL shipped case warns:"; echo "$out"; fail=1; else echo "ok   no warning for the shipped case"; fi
has metres "warning: Geometry/Thickness = 0.00078 mm is thinner than any sheet; lengths are in mm, not m" \
  "$(run --set "Geometry/Thickness=0.00078")"
has pascal "warning: Material/Strength coefficient = 8.29e+08 MPa is above 10 GPa" \
  "$(run --set "Material/Strength coefficient=829e6")"
has holder_kN "warning: Tools/Blank holder/Force = 2.6 N is far from Siebel's estimate" \
  "$(run --set "Tools/Blank holder/Force=2.6")"
has friction "warning: Tools/Die/Friction coefficient = 0.8 is above 0.5" \
  "$(run --set "Tools/Die/Friction coefficient=0.8")"
has ironing "warning: the clearance between punch and die (0.6 mm per side) is smaller than the sheet thickness (0.78 mm): the cup wall will be ironed by 23 % or more" \
  "$(run --set "Tools/Die/Diameter=41.2")"
has gigapascal "warning: Material/Strength coefficient = 0.829 MPa is below 50 MPa" \
  "$(run --set "Material/Strength coefficient=0.829")"
has metres_per_second "warning: Tools/Punch/Speed = 0.001 mm/s is below 0.01 mm/s; speeds are in mm/s, not m/s" \
  "$(run --set "Tools/Punch/Speed=0.001")"
has long_step "warning: Time stepping/Time step = 5 s moves the punch 5 mm per step, more than the smallest elements (0.602 mm in the plane)" \
  "$(run --set "Time stepping/Time step=5")"
has one_layer "warning: Mesh/Layers through thickness = 1: bending over the tool radii needs at least 4 layers of Q1 elements" \
  "$(run --set "Mesh/Layers through thickness=1")"
has unreachable_tool "warning: Tools/Punch: the tool is 10 mm from the sheet, farther than the run brings them together (8 mm: the punch's Stroke); it will never touch the sheet" \
  "$(run --set "Tools/Punch/Gap=10" --set "Tools/Punch/Stroke=8")"
has voce_flc "warning: Material/Forming limit table is empty: the forming limit is Keeler-Brazier's from Material/Hardening exponent = 0.2" \
  "$(run --set "Material/Flow curve=voce" --set "Material/Voce saturation stress=330.2" \
       --set "Material/Voce hardening amplitude=190" --set "Material/Voce hardening rate=12.4")"
has blank_in_metres "error: Parameter Geometry/Blank diameter: (0.077 mm) must exceed Tools/Die/Diameter (42.5 mm), or the blank falls through the die; lengths are in mm, not m" \
  "$(run --set "Geometry/Blank diameter=0.077")"
has blank_in_metres_siebel "error: Parameter Geometry/Blank diameter: (0.077 mm) is not larger than the blank holder's opening" \
  "$(run --set "Geometry/Blank diameter=0.077" --set "Tools/Blank holder/Force=siebel")"
has oyane_without_constants "error: Parameter Material/Oyane a: Fracture criterion = oyane needs Oyane's constants a and b of this sheet" \
  "$(run --set "Material/Oyane a=" --set "Material/Oyane b=")"
exit $fail
