// The space dimensions formsolve is built for, in one place: 2 (the
// axisymmetric r-z section) and 3. Every class or function templated on dim
// is instantiated in its .cc file through this macro:
//   #define INSTANTIATE(dim) template class Foo<dim>;
//   FORMSOLVE_FOR_EACH_DIM(INSTANTIATE)
#pragma once

#define FORMSOLVE_FOR_EACH_DIM(INSTANTIATE) INSTANTIATE(2) INSTANTIATE(3)
