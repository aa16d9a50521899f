#!/usr/bin/env bash
# Bad input: exit non-zero with one clear message naming the entry or file, and
# leave an existing output folder exactly as it was. With RANKS=2 every case
# runs under mpirun -np 2 and must print its message once.
set -uo pipefail
exe=$1 cases=$2 work=$3
ranks=${RANKS:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$work"; mkdir -p "$work"
base="$cases/penetration.prm"
out="$work/existing-results"
mkdir -p "$out"
echo "earlier results" > "$out/history.csv"
echo "keep me" > "$out/checkpoint.dat"
# A checkpoint written by another case (its parameters differ).
mkdir -p "$out/checkpoint"
echo complete > "$out/checkpoint/complete"
printf 'subsection Geometry\n  set Thickness = 3\nend\n' > "$out/checkpoint/parameters.prm"
snapshot() { (cd "$out" && ls -lR --time-style=+%s && find . -type f | sort | xargs cat) | md5sum; }
before=$(snapshot)
fail=0

# expect NAME PATTERN PRM [ARGS...]
expect() {
  local name=$1 pattern=$2 prm=$3; shift 3
  local err="$work/$name.err"
  if [ "$ranks" -gt 1 ]; then
    timeout 120 mpirun -np "$ranks" "$exe" "$prm" --set "Output/Output directory=$out" "$@" > "$work/$name.out" 2> "$err"
  else
    "$exe" "$prm" --set "Output/Output directory=$out" "$@" > "$work/$name.out" 2> "$err"
  fi
  local rc=$?
  # mpirun adds its own banner: count formsolve's lines only.
  local lines; lines=$(grep -c "formsolve" "$err")
  if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -qF -- "$pattern" "$err" && [ "$lines" -eq 1 ]; then
    echo "ok   $name: exit $rc: $(head -c 300 "$err" | tr '\n' ' ')"
  else
    echo "FAIL $name: exit $rc, expected a message naming '$pattern', got:"; cat "$err"; fail=1
  fi
  local now; now=$(snapshot)
  if [ "$now" != "$before" ]; then echo "FAIL $name: the existing output folder changed"; fail=1; fi
}

sed 's/set Thickness    = 10/set Thicknes    = 10/' "$base" > "$work/unknown.prm"
expect unknown_entry "Thicknes" "$work/unknown.prm"
# In the user's words: the line, the closest declared names, plain ranges.
expect did_you_mean_entry "unknown.prm, line" "$work/unknown.prm"
expect did_you_mean_entry_name 'did you mean `Thickness`?' "$work/unknown.prm"
printf 'include %s\nsubsection Tools\n  subsection Blankholder\n  end\nend\n' "$(realpath "$base")" > "$work/subsection.prm"
expect did_you_mean_subsection 'no subsection `Blankholder` in subsection `Tools`; did you mean `Blank holder`?' \
  "$work/subsection.prm"
expect did_you_mean_override '--set "Tool/Punch/Stroke=5": there is no subsection `Tool` at the top level; did you mean `Tools`?' \
  "$base" --set "Tool/Punch/Stroke=5"
expect decimal_comma 'Geometry/Thickness=1,0": `1,0` is not accepted; it takes a number, in mm (write decimals with a point' \
  "$base" --set "Geometry/Thickness=1,0"
expect range_in_words 'it takes a number from 0 to 1' "$base" --set "Material/Hardening exponent=2"
printf 'include %s\nsubsection Geometry\n' "$(realpath "$base")" > "$work/unclosed.prm"
expect unclosed_subsection 'subsection `Geometry` is not closed by `end`' "$work/unclosed.prm"
sed 's/set Thickness    = 10/set Thickness    = ten/' "$base" > "$work/type.prm"
expect wrong_type "Thickness" "$work/type.prm"
expect unknown_override "Geometry/Thicknes" "$base" --set "Geometry/Thicknes=1"
expect zero_thickness "Geometry/Thickness" "$base" --set "Geometry/Thickness=0"
expect negative_thickness "Geometry/Thickness" "$base" --set "Geometry/Thickness=-1"
expect missing_mesh "no-such-blank.msh" "$base" --set "Geometry/Blank shape=gmsh" \
  --set "Geometry/Mesh file=no-such-blank.msh"
expect missing_input "does-not-exist.prm" "$work/does-not-exist.prm"
expect blank_inside_tool "Tools/Punch" "$base" --set "Tools/Punch/Gap=-0.5"
expect voce_unset "Material/Voce saturation stress" "$base" --set "Material/Flow curve=voce"
expect voce_negative_yield "Material/Voce hardening amplitude" "$base" \
  --set "Material/Flow curve=voce" --set "Material/Voce saturation stress=300" \
  --set "Material/Voce hardening amplitude=400"
expect zero_time_step "Time stepping/Time step" "$base" --set "Time stepping/Time step=0"
expect negative_time_step "Time stepping/Time step" "$base" --set "Time stepping/Time step=-1"
printf 'include no-such-include.prm\n' > "$work/include.prm"
expect missing_include "no-such-include.prm" "$work/include.prm"
expect refinement_layers "Mesh refinement/Punch level" "$base" --set "Mesh refinement/Interval=2" \
  --set "Mesh refinement/Punch level=1" --set "Mesh/Layers through thickness=1"
expect refinement_no_criterion "Mesh refinement/Interval" "$base" --set "Mesh refinement/Interval=2"
expect al_no_passes "Contact/Max strict passes" "$base" --set "Contact/Penalty strategy=augmented-lagrangian" \
  --set "Contact/Max strict passes=0"
expect strict_check_range "Strict check residual" "$base" --set "Contact/Strict check residual=2"
# Process model (issue 8): model, holder control, step control, end of run.
expect unknown_model "Model" "$base" --set "Geometry/Model=octant"
expect axisymmetric_rectangle "Geometry/Blank shape" "$base" --set "Geometry/Model=axisymmetric"
expect axisymmetric_square_punch "Tools/Punch/Shape" "$base" --set "Geometry/Model=axisymmetric" \
  --set "Geometry/Blank shape=round" --set "Tools/Punch/Shape=rounded rectangle"
expect revolved_in_3d "Output/Revolved copy" "$base" --set "Output/Revolved copy=true"
# The plane-strain section: a rectangular strip, a straight punch, no revolved
# copy, a strip longer than the die opening.
channel="$cases/channel-short.prm"
expect plane_strain_round "Geometry/Blank shape: must be rectangle" "$channel" \
  --set "Geometry/Blank shape=round"
expect plane_strain_square_punch "Tools/Punch/Shape" "$channel" \
  --set "Tools/Punch/Shape=rounded rectangle"
expect plane_strain_revolved "Output/Revolved copy" "$channel" --set "Output/Revolved copy=true"
expect plane_strain_short_strip "Geometry/Blank length" "$channel" --set "Geometry/Blank length=70"
# Springback: no elastic constants; a support with the wrong number of
# coordinates; supports that leave the part free to move (checked before
# any step).
expect springback_no_modulus "Material/Young's modulus: must be given for springback" \
  "$channel" --set "Springback/Enabled=true"
expect springback_support_coordinates "Springback/Supports: a point has 3 coordinates" \
  "$channel" --set "Springback/Enabled=true" --set "Material/Young's modulus=206000" \
  --set "Springback/Supports=0, 0, 0: z"
expect springback_support_free "Springback/Supports: leave the part free to move (translation along z)" \
  "$channel" --set "Springback/Enabled=true" --set "Material/Young's modulus=206000" \
  --set "Springback/Supports=10, 0: x"
expect springback_measure_point "Springback/Measure points: 'ten, 0' is not a point" \
  "$channel" --set "Springback/Enabled=true" --set "Material/Young's modulus=206000" \
  --set "Springback/Measure points=ten, 0"
# Trimming: a half-space that is none, a coordinate the model has not, a
# curve in a section, a missing file, a curve that misses the blank, a
# closed curve kept on one side, a slit outside the half model.
expect trim_plane_text "Trimming/Planes: 'z >> 3' is not a half-space" \
  "$channel" --set "Trimming/Planes=z >> 3"
expect trim_plane_letter "Trimming/Planes: 'y < 3' names y, not a coordinate of Geometry/Model = plane strain" \
  "$channel" --set "Trimming/Planes=y < 3"
printf '0, 0\n10, 0\n10, 10\n0, 0\n' > "$work/triangle.csv"
expect trim_curve_section "Trimming/Curve file: a curve in plan view needs a 3-D model" \
  "$channel" --set "Trimming/Curve file=$work/triangle.csv"
expect trim_curve_missing "$work/none.csv" \
  "$cases/cup-quarter.prm" --set "Trimming/Curve file=$work/none.csv"
printf '500, 500\n510, 500\n510, 510\n500, 500\n' > "$work/far.csv"
expect trim_curve_misses "Trimming/Curve file: the curve in $work/far.csv misses the blank: it keeps none of it" \
  "$cases/cup-quarter.prm" --set "Trimming/Curve file=$work/far.csv"
expect trim_curve_side "Trimming/Curve keeps: the curve in $work/triangle.csv is closed" \
  "$cases/cup-quarter.prm" --set "Trimming/Curve file=$work/triangle.csv" --set "Trimming/Curve keeps=left"
expect slit_model "Springback/Slit: the slit lies in the symmetry plane x = 0 of Geometry/Model = half" \
  "$cases/cup-quarter.prm" --set "Springback/Enabled=true" --set "Material/Young's modulus=206000" \
  --set "Springback/Slit=true" --set "Trimming/Planes=z < -1"
expect slit_untrimmed "Springback/Slit: slits a ring trimmed from the part" \
  "$cases/cup-quarter.prm" --set "Geometry/Model=half" --set "Springback/Enabled=true" \
  --set "Material/Young's modulus=206000" --set "Springback/Slit=true"
expect density_negative "Material/Density: must be positive" "$base" --set "Material/Density=-1"
expect slice_round "Geometry/Blank shape: must be rectangle for Model = slice" "$cases/channel-slice.prm" \
  --set "Geometry/Blank shape=round"
expect zero_holder_force "Tools/Blank holder/Force" "$base" --set "Tools/Blank holder/Enabled=true" \
  --set "Tools/Blank holder/Force=0"
expect holder_curve_order "Tools/Blank holder/Force: the punch travels must increase: 10 is followed by 5" "$base" \
  --set "Tools/Blank holder/Enabled=true" --set "Tools/Blank holder/Force=0:1000, 10:2000, 5:3000"
expect holder_curve_item "Tools/Blank holder/Force: '10 2000' is not 'travel:force' with finite numbers" "$base" \
  --set "Tools/Blank holder/Enabled=true" --set "Tools/Blank holder/Force=0:1000, 10 2000"
expect holder_curve_zero "Tools/Blank holder/Force: must be positive (N), got 0" "$base" \
  --set "Tools/Blank holder/Enabled=true" --set "Tools/Blank holder/Force=0:1000, 10:0"
expect flat_holder_force "Tools/Blank holder/Control" "$base" --set "Tools/Blank holder/Enabled=true" \
  --set "Tools/Blank holder/Shape=flat"
# Draw beads (Tools/Draw beads) that cannot act, on the channel and the quarter cup.
bead="$cases/channel-bead.prm"
expect bead_negative_force "Tools/Draw beads/flange/Restraining force=-5\": \`-5\` is not accepted" "$bead" \
  --set "Tools/Draw beads/flange/Restraining force=-5"
expect bead_off_holder "Tools/Draw beads/flange/Line: the point (30) of the bead lies outside the face of Die" \
  "$bead" --set "Tools/Draw beads/flange/Line=30"
expect bead_off_blank "Tools/Draw beads/flange/Line: the point (200) of the bead lies outside the blank" \
  "$bead" --set "Tools/Draw beads/flange/Line=200"
expect bead_too_high "Tools/Draw beads/flange/Height: (9 mm) must stay below Bead radius + Shoulder radius" \
  "$bead" --set "Tools/Draw beads/flange/Model=geometry" --set "Tools/Draw beads/flange/Height=9"
expect bead_above_gap "Tools/Draw beads/flange/Height: (3 mm): the holder stays at Tools/Blank holder/Gap = 4 mm" \
  "$bead" --set "Tools/Blank holder/Control=gap" --set "Tools/Blank holder/Gap=4"
expect bead_without_holder "Tools/Draw beads/flange/Line: a draw bead acts between die and blank holder" \
  "$bead" --set "Tools/Blank holder/Enabled=false"
expect bead_without_line "Tools/Draw beads/other/Line: must be given" "$bead" \
  --set "Tools/Draw beads/Names=flange, other"
expect bead_line_in_section "Tools/Draw beads/flange/Line: takes one number" "$bead" \
  --set "Tools/Draw beads/flange/Line=1:2, 3:4"
expect bead_point_in_3d "Tools/Draw beads/ring/Line: takes two or more points" "$cases/cup-quarter-bead.prm" \
  --set "Tools/Draw beads/ring/Line=34"
expect minimum_above_step "Time stepping/Minimum time step" "$base" --set "Time stepping/Minimum time step=1"
expect release_without_holder "Time stepping/End of run" "$base" --set "Time stepping/End of run=holder release"
expect draw_through_flat_die "Time stepping/End of run" "$base" --set "Time stepping/End of run=draw-through"
expect nan_thickness "Geometry/Thickness" "$base" --set "Geometry/Thickness=nan"
# Scenes that do not fit together (issue 12), on the cup.
cup="$cases/cup-axisymmetric.prm"
expect punch_wider_than_die "Tools/Punch/Diameter" "$cup" --set "Tools/Punch/Diameter=45"
expect holder_inside_die "Tools/Blank holder/Diameter" "$cup" --set "Tools/Blank holder/Diameter=40"
expect holder_beyond_blank "Tools/Blank holder/Diameter" "$cup" --set "Tools/Blank holder/Diameter=90"
expect mesh_too_large "Mesh/Planform refinements" "$cases/drawing.prm" --set "Mesh/Planform refinements=12"
touch "$work/a-file"
expect unwritable_output "Output/Output directory" "$base" --set "Output/Output directory=$work/a-file/results"
# Linear solver settings that cannot work together.
expect low_rank_refinement "Low-rank tolerance" "$base" --set "Linear solver/Low-rank tolerance=1e-8" \
  --set "Linear solver/Refinement steps=2"
expect out_of_core_missing "Out-of-core directory" "$base" \
  --set "Linear solver/Out-of-core directory=$work/no-such-directory"
expect out_of_core_file "Out-of-core directory" "$base" \
  --set "Linear solver/Out-of-core directory=$work/a-file"
# Non-finite numbers, a truncated file, binary garbage as input.
expect inf_stroke "Tools/Punch/Stroke" "$base" --set "Tools/Punch/Stroke=inf"
expect nan_friction "Friction coefficient" "$base" --set "Tools/Die/Friction coefficient=nan"
head -c 1500 "$cases/../fuzz/seed-axisymmetric-refined.prm" > "$work/truncated.prm"
expect truncated_prm "truncated.prm" "$work/truncated.prm"
head -c 2000 /dev/urandom > "$work/garbage.prm"
expect binary_garbage "garbage.prm" "$work/garbage.prm"
# gmsh planforms that cannot be used: empty, triangles, a 3-D mesh, garbage.
: > "$work/empty.msh"
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 30 0 0\n3 0 30 0\n$EndNodes\n$Elements\n1\n1 2 2 0 1 1 2 3\n$EndElements\n' > "$work/triangles.msh"
printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 30 0 0\n3 30 30 0\n4 0 30 0\n5 0 0 1\n6 30 0 1\n7 30 30 1\n8 0 30 1\n$EndNodes\n$Elements\n1\n1 5 2 0 1 1 2 3 4 5 6 7 8\n$EndElements\n' > "$work/hexahedra.msh"
head -c 3000 /dev/urandom > "$work/garbage.msh"
for m in empty triangles hexahedra garbage; do
  expect "gmsh_$m" "Geometry/Mesh file" "$base" --set "Geometry/Blank shape=gmsh" \
    --set "Geometry/Mesh file=$work/$m.msh"
done
# Meshed tools (3-D quarter cup): missing, empty, truncated, garbage files; a
# file in metres; an open surface the sheet cannot see; a tool placed into
# the blank. Tools from meshes/tools/make-tools.sh at coarse facets.
base3d="$cases/cup-quarter.prm"
bash "$cases/../../meshes/tools/make-tools.sh" cup 4 "$work/tools" stl > /dev/null
# expect_die NAME PATTERN FILE [ARGS...]: the die from FILE.
expect_die() {
  local name=$1 pattern=$2 file=$3; shift 3
  expect "$name" "$pattern" "$base3d" --set "Tools/Die/Shape=mesh" --set "Tools/Die/Mesh file=$file" "$@"
}
: > "$work/empty.stl"
head -c 2000 "$work/tools/die.stl" > "$work/truncated.stl"
head -c 3000 /dev/urandom > "$work/garbage.stl"
awk '$1 == "vertex" { printf "vertex %g %g %g\n", $2 / 1000, $3 / 1000, $4 / 1000; next } { print }' \
  "$work/tools/die.stl" > "$work/metres.stl"
printf 'solid wall\nfacet normal 1 0 0\nouter loop\nvertex 30 -40 -20\nvertex 30 40 -20\nvertex 30 40 -1\nendloop\nendfacet\nendsolid wall\n' \
  > "$work/wall.stl"
for m in no-such-die empty truncated garbage; do
  expect_die "mesh_$m" "Tools/Die/Mesh file: tool surface file '$work/$m.stl'" "$work/$m.stl"
done
expect_die mesh_metres "lengths are in mm" "$work/metres.stl"
expect_die mesh_open_no_side "the sheet sees nothing" "$work/wall.stl"
expect mesh_into_blank "Tools/Punch: the blank starts inside this tool" "$base3d" \
  --set "Tools/Punch/Shape=mesh" --set "Tools/Punch/Mesh file=$work/tools/punch.stl" \
  --set "Tools/Punch/Mesh offset=0, 0, -0.3"
# The axisymmetric model takes profiles: a surface file, a 3-D curve, an
# open profile of which the sheet sees nothing, each named.
expect mesh_axisymmetric "Tools/Die/Mesh file: tool profile file '$work/tools/die.stl': unknown kind" \
  "$cases/cup-axisymmetric.prm" --set "Tools/Die/Shape=mesh" --set "Tools/Die/Mesh file=$work/tools/die.stl"
printf 'Point(1) = {20, 1, 0};\nPoint(2) = {60, 0, 3};\nLine(1) = {1, 2};\n' > "$work/skew.geo"
expect profile_not_planar "Tools/Die/Mesh file: tool profile file '$work/skew.geo': the profile must lie" \
  "$cases/cup-axisymmetric.prm" --set "Tools/Die/Shape=mesh" --set "Tools/Die/Mesh file=$work/skew.geo"
printf '21.25, -1\n21.25, -45\n' > "$work/wall.csv"
expect profile_no_side "Tools/Die/Mesh file: $work/wall.csv: an open profile of which the sheet sees nothing" \
  "$cases/cup-axisymmetric.prm" --set "Tools/Die/Shape=mesh" --set "Tools/Die/Mesh file=$work/wall.csv"
# A die whose normals all point inwards is turned, and the log says so.
awk '$1 == "outer" { n = 0; print; next } $1 == "vertex" { v[n++] = $0; if (n == 3) { print v[0]; print v[2]; print v[1] } next } { print }' \
  "$work/tools/die.stl" > "$work/inside-out.stl"
if "$exe" "$base3d" --validate --set "Tools/Die/Shape=mesh" \
     --set "Tools/Die/Mesh file=$work/inside-out.stl" > "$work/inside-out.out" 2>&1 &&
   grep -q "closed parts were inside out: turned to face outwards" "$work/inside-out.out"; then
  echo "ok   mesh_inside_out: turned and said"
else
  echo "FAIL mesh_inside_out:"; cat "$work/inside-out.out"; fail=1
fi
# Additional tools: a subsection of a tool not listed, a name taken twice or
# by a standard tool, a direction the model cannot follow, no set force.
counter="$cases/cup-counter-punch-force.prm"
expect tool_not_listed "must be named in Tools/Additional tools" "$counter" \
  --set "Tools/Additional tools="
expect tool_named_twice "Tools/Additional tools: \`counter_punch\` is named twice" "$counter" \
  --set "Tools/Additional tools=Counter punch, counter_punch"
expect tool_named_die "Tools/Additional tools: \`die\` cannot name an additional tool" "$counter" \
  --set "Tools/Additional tools=Counter punch, die"
expect tool_direction_axisymmetric "Tools/Counter punch/Direction: must lie along z" "$counter" \
  --set "Tools/Counter punch/Direction=1, 0, 1"
expect tool_direction_zero "Tools/Counter punch/Direction: must not be zero" "$counter" \
  --set "Tools/Counter punch/Direction=0, 0, 0"
expect tool_no_force "Tools/Counter punch/Force: must be positive" "$counter" \
  --set "Tools/Counter punch/Force=0"
expect tool_direction_symmetry "Tools/Pad/Direction: must lie in the model's symmetry planes" "$base3d" \
  --set "Tools/Additional tools=Pad" --set "Tools/Pad/Motion=prescribed" \
  --set "Tools/Pad/Direction=1, 0, -1"
# A tabulated flow curve.
expect flow_curve_no_file "Material/Flow curve file: must name a CSV" "$base" \
  --set "Material/Flow curve=table"
expect flow_curve_missing_file "Material/Flow curve file: cannot read" "$base" \
  --set "Material/Flow curve=table" --set "Material/Flow curve file=$work/no-such-curve.csv"
printf 'strain,stress\n0,300\n0.2,420\n0.4,410\n' > "$work/softening.csv"
expect flow_curve_softening "softening.csv, line 4: the stress falls" "$base" \
  --set "Material/Flow curve=table" --set "Material/Flow curve file=$work/softening.csv"
# Non-quadratic yield.
expect yld_coefficient_count "Material/Yld2004-18p C1=1, 1, 1\": \`1, 1, 1\` is not accepted; it takes 7 to 9 numbers" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p C1=1, 1, 1"
expect yld_not_strictly_convex "Material/Yld2004-18p C1, C2 (with Yield exponent = 8) give a yield function that is not strictly convex" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p C1=1, 1, 1, 1, 1, 1, 0" \
  --set "Material/Yld2004-18p C2=1, 1, 1, 1, 1, 1, 0"
expect yld_no_yield_stress "Material/Yld2004-18p C1, C2 give no yield stress in uniaxial tension along RD" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p C1=0, 0, 0, 0, 0, 0, 0" \
  --set "Material/Yld2004-18p C2=0, 0, 0, 0, 0, 0, 0"
expect yld_exponent_range "Material/Yield exponent=1\": \`1\` is not accepted; it takes a number from 2 to 30" "$base" \
  --set "Material/Yield criterion=Hosford" --set "Material/Yield exponent=1"
expect yld_planar_axisymmetric "Material/Yld2004-18p C1: planar anisotropy" "$cases/cup-axisymmetric.prm" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p C1=1, 1, 1, 1, 1, 1, 1.2"
expect yld_fit_too_few_data "Material/Yld2004-18p fit/Stress ratios: the fit of Yld2004-18p's 14 coefficients needs at least as many data, got 5" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p coefficients=fitted" \
  --set "Material/Yld2004-18p fit/Angles=0, 45, 90" --set "Material/Yld2004-18p fit/Stress ratios=1, 0.9, 0.95" \
  --set "Material/Yld2004-18p fit/R-values=0.5, 0.3, 0.6"
expect yld_fit_count "Material/Yld2004-18p fit/R-values: needs one value per angle of Material/Yld2004-18p fit/Angles (7), got 3" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p coefficients=fitted" \
  --set "Material/Yld2004-18p fit/R-values=0.5, 0.3, 0.6"
expect yld_fit_angle "Material/Yld2004-18p fit/Angles: must lie in 0 to 90 degrees, got 120" "$base" \
  --set "Material/Yield criterion=Yld2004-18p" --set "Material/Yld2004-18p coefficients=fitted" \
  --set "Material/Yld2004-18p fit/Angles=0, 45, 120"
expect hosford_springback "Material/Yield criterion: is Hosford, a = 8: the springback release returns to a quadratic yield surface" "$base" \
  --set "Material/Yield criterion=Hosford" --set "Springback/Enabled=true" --set "Material/Young's modulus=2e5"
expect gap_from_part_negative "Tools/Die/Gap: must not be negative with 'Gap measured from' = part" "$base" \
  --set "Tools/Die/Gap measured from=part" --set "Tools/Die/Gap=-1"
# Checkpoint and restart.
expect resume_other_case "written by another case" "$base" --resume
expect resume_names_entry "Geometry/Thickness = '3' in the checkpoint, '10' now" "$base" --resume
expect resume_no_checkpoint "no complete checkpoint" "$base" --resume \
  --set "Output/Output directory=$work/no-checkpoint"
[ ! -e "$work/no-checkpoint" ] || { echo "FAIL: resume_no_checkpoint created $work/no-checkpoint"; fail=1; }
exit $fail
