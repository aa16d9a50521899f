// The dense kernels under MUMPS. Debian 12's OpenBLAS (0.3.21) does not
// recognise recent Xeons (e.g. this machine's "Intel(R) Xeon(R) Processor"
// with AVX-512) and falls back to its generic Prescott (SSE3) kernels, which
// makes the sparse factorisation about 2x slower (doc/performance.md). It
// picks its kernels when the library loads, before main(): the cure is
// OPENBLAS_CORETYPE in the environment of the run, which scripts/formsolve-run
// sets. The program itself only says what it runs on and what would help.
#pragma once

#include <string>

namespace formsolve
{
  namespace app
  {
    /// The kernels in use, for the run header: e.g. "OpenBLAS SkylakeX
    /// (OPENBLAS_CORETYPE)", or "not OpenBLAS"; and ", narrow calls to
    /// BLAS-2" where libformsolve_narrow_blas is loaded.
    std::string blas_kernel();

    /// Where OpenBLAS runs its Prescott fallback on a CPU with AVX2 or
    /// AVX-512 and OPENBLAS_CORETYPE is not set: the setting that would use
    /// its kernels (e.g. "OPENBLAS_CORETYPE=Haswell"); else "".
    std::string blas_advice();
  } // namespace app
} // namespace formsolve
