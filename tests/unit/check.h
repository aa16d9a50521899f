// Minimal checking helpers for the unit tests: print, count failures.
#pragma once

#include <cmath>
#include <iostream>
#include <string>

namespace test
{
  inline int failures = 0;

  inline void close(const std::string &what,
                    const double       got,
                    const double       expected,
                    const double       tol)
  {
    const bool ok = std::abs(got - expected) <= tol;
    std::cout << (ok ? "ok   " : "FAIL ") << what << ": got " << got
              << ", expected " << expected << " (tol " << tol << ")\n";
    failures += !ok;
  }

  inline int result()
  {
    std::cout << (failures == 0 ? "all checks passed" : "checks failed: ")
              << (failures ? std::to_string(failures) : "") << std::endl;
    return failures == 0 ? 0 : 1;
  }
} // namespace test
