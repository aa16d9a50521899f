#!/usr/bin/env bash
# Installs formsolve's build and test dependencies from Debian 12 packages.
# Idempotent: does nothing when everything is present. Needs root (or sudo).
set -euo pipefail
packages=(
  cmake make g++ libdeal.ii-dev     # deal.II 9.4 with Trilinos, p4est, PETSc, MPI, gmsh
  libmumps-dev libmetis-dev         # MUMPS C interface and METIS, called directly
  libcgal-dev                       # AABB trees of triangulated tool surfaces
  libeigen3-dev                     # Levenberg-Marquardt of the Yld2004-18p fit
  libgmsh-dev                       # gmsh.h: tool surfaces from .msh, .geo, STEP, IGES
  libopenblas0-serial               # optimised BLAS for MUMPS (reference libblas3 is ~4x slower)
  openmpi-bin                       # mpirun
  gmsh                              # meshing .geo planforms and tool solids
  numdiff                           # regression comparisons
  python3-vtk9 python3-numpy        # VTU read-back test
  python3-matplotlib                # benchmark charts, run report
  xvfb                              # offscreen X server for the report's VTK pictures
  valgrind                          # memcheck test of a tiny case
  clang-format                      # the format check of scripts/run-tests.sh
)
missing=()
for p in "${packages[@]}"; do
  [[ $p == \#* ]] && continue
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "dependencies: all installed"
  exit 0
fi
echo "dependencies: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" > /tmp/formsolve-apt.log 2>&1 \
  || { tail -30 /tmp/formsolve-apt.log; exit 1; }
echo "dependencies: done"
