# Sourced by the benchmarks that measure the cost per Newton iteration over
# the first steps (or a draw whose figures in doc/ were measured from rest):
#   from_rest EXE   sets the array `rest` to the --set that starts the first
# step from rest (Nonlinear solver/First step start, a4144b7), or empty for
# a binary from before it. The first step started from the coarser mesh
# spends part of its time in iterations that are not counted in
# newton_iterations (coarse_start_iterations), so a time per Newton
# iteration over the first steps would no longer be that of the mesh.
from_rest() {
  rest=()
  # (an older build's library next to its executable, as in assembly_cost.sh)
  if LD_LIBRARY_PATH=$(dirname "$1") "$1" --print-parameters 2>/dev/null |
    grep -q "First step start"; then
    rest=(--set "Nonlinear solver/First step start=rest")
  fi
}
