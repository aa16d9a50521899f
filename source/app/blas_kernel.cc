#include <formsolve/app/blas_kernel.h>

#include <dlfcn.h>
#include <strings.h>

#include <cstdlib>
#include <cstring>

namespace formsolve
{
  namespace app
  {
    namespace
    {
      /// OpenBLAS's own report of its kernels, nullptr for another BLAS.
      const char *openblas_core()
      {
        using Function = char *(*)();
        const auto f   = reinterpret_cast<Function>(
          dlsym(RTLD_DEFAULT, "openblas_get_corename"));
        return f ? f() : nullptr;
      }

      /// The OpenBLAS kernel family for this CPU, nullptr if Prescott is
      /// right (no AVX2).
      const char *kernel_for_this_cpu()
      {
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx512f") &&
            __builtin_cpu_supports("avx512vl") &&
            __builtin_cpu_supports("avx512bw") &&
            __builtin_cpu_supports("avx512dq"))
          return "SkylakeX";
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
          return "Haswell";
        return nullptr;
      }

    } // namespace

    std::string blas_kernel()
    {
      const char *core = openblas_core();
      if (core == nullptr)
        return "not OpenBLAS";
      std::string s = std::string("OpenBLAS ") + core;
      if (std::getenv("OPENBLAS_CORETYPE"))
        s += " (OPENBLAS_CORETYPE)";
      if (dlsym(RTLD_DEFAULT, "formsolve_narrowed_blas_calls") != nullptr)
        s += ", narrow calls to BLAS-2";
      return s;
    }

    std::string blas_advice()
    {
      const char *core   = openblas_core();
      const char *kernel = kernel_for_this_cpu();
      if (core == nullptr || strcasecmp(core, "prescott") != 0 ||
          std::getenv("OPENBLAS_CORETYPE") || kernel == nullptr)
        return "";
      return std::string("OPENBLAS_CORETYPE=") + kernel;
    }
  } // namespace app
} // namespace formsolve
