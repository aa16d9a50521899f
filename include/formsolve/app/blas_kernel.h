// The dense kernels under MUMPS. Debian 12's OpenBLAS (0.3.21) does not
// recognise recent Xeons (e.g. this machine's "Intel(R) Xeon(R) Processor"
// with AVX-512) and falls back to its generic Prescott (SSE3) kernels, which
// makes the sparse factorisation about 2x slower (doc/performance.md). It
// picks its kernels when the library loads, before main(), so the only cure
// from inside the program is to set OPENBLAS_CORETYPE and start again.
#pragma once

#include <string>

namespace formsolve
{
  namespace app
  {
    /// Call first in main(), before MPI starts. If OpenBLAS chose Prescott
    /// on a CPU with AVX-512 or AVX2, sets OPENBLAS_CORETYPE to SkylakeX or
    /// Haswell and executes the program again with the same arguments (the
    /// same process, so mpirun does not notice). Does nothing if the user
    /// set OPENBLAS_CORETYPE, if the BLAS is not OpenBLAS, or under valgrind.
    /// Returns only if nothing was done or the new start failed.
    void select_blas_kernel(char **argv);

    /// The kernels in use, for the run header: e.g. "OpenBLAS SkylakeX
    /// (OPENBLAS_CORETYPE)", or "not OpenBLAS".
    std::string blas_kernel();
  } // namespace app
} // namespace formsolve
