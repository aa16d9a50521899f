#!/usr/bin/env bash
# Meshed copies of the analytic tools of a shipped case, as STL and .msh:
#   meshes/tools/make-tools.sh cup|square-cup|cup-profile FACET_SIZE_MM OUTDIR [FORMATS]
# FORMATS: "stl msh" (default), or one of them.
# cup: prm/cup-drawing.prm (punch 40/8, die 42.5/8, holder 58.5 with a sharp
# edge, t0 0.78);
# square-cup: prm/square-cup.prm (punch 40 x 40, corners 10, nose 6; die
# 42.5 x 42.5, corners 11.25, entry 8; holder 58.5 x 58.5, corners 19.25).
# cup-profile: the cup's tools as r-z profiles for the axisymmetric model
# (gmsh lines, .msh only; profiles/*.geo).
# Each tool is placed where the analytic one starts (punch and holder faces
# on the sheet's top surface z = t0, the die face at z = 0).
set -euo pipefail
case=$1 size=$2 out=$3 formats=${4:-stl msh}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
dimension=2
mesh() { # name geo settings...
  local name=$1 geo=$2; shift 2
  for format in $formats; do
    gmsh -$dimension "$here/$geo" -setnumber size "$size" "$@" -format "$format" \
      -o "$out/$name.$format" > "$out/$name.$format.log" 2>&1 ||
      { echo "gmsh failed on $name ($out/$name.$format.log)"; exit 1; }
  done
}
case "$case" in
  cup)
    mesh punch punch.geo -setnumber d 40 -setnumber rp 8 -setnumber z0 0.78
    mesh die die.geo -setnumber d 42.5 -setnumber rd 8
    mesh holder holder.geo -setnumber d 58.5 -setnumber rh 0 -setnumber z0 0.78 ;;
  square-cup)
    mesh punch punch.geo -setnumber shape 1 -setnumber length 40 -setnumber width 40 \
      -setnumber rc 10 -setnumber rp 6 -setnumber z0 0.78
    mesh die die.geo -setnumber shape 1 -setnumber length 42.5 -setnumber width 42.5 \
      -setnumber rc 11.25 -setnumber rd 8
    mesh holder holder.geo -setnumber shape 1 -setnumber length 58.5 -setnumber width 58.5 \
      -setnumber rc 19.25 -setnumber rh 0 -setnumber z0 0.78 ;;
  cup-profile)
    dimension=1 formats=msh
    mesh punch profiles/punch.geo -setnumber d 40 -setnumber rp 8 -setnumber z0 0.78
    mesh die profiles/die.geo -setnumber d 42.5 -setnumber rd 8
    mesh holder profiles/holder.geo -setnumber d 58.5 -setnumber z0 0.78 ;;
  *) echo "usage: make-tools.sh cup|square-cup|cup-profile FACET_SIZE_MM OUTDIR [FORMATS]"; exit 2 ;;
esac
echo "$case tools at facet size $size mm in $out"
