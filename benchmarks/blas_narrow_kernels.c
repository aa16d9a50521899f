/* The BLAS kernels behind MUMPS's substitutions, one and two columns:
 * sgemm/dgemm with n = 1 and 2 against as many sgemv/dgemv calls, strsm with
 * n = 1 against strsv, on square m x m blocks (the fronts of the shipped 3-D
 * cup have up to a few hundred pivots). Linked with the system's libblas
 * (Debian's alternatives: OpenBLAS serial here). Prints microseconds per call;
 * built and run by benchmarks/narrow_blas.sh. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

void sgemm_(const char *, const char *, const int *, const int *, const int *, const float *,
            const float *, const int *, const float *, const int *, const float *, float *,
            const int *);
void sgemv_(const char *, const int *, const int *, const float *, const float *, const int *,
            const float *, const int *, const float *, float *, const int *);
void strsm_(const char *, const char *, const char *, const char *, const int *, const int *,
            const float *, const float *, const int *, float *, const int *);
void strsv_(const char *, const char *, const char *, const int *, const float *, const int *,
            float *, const int *);
void dgemm_(const char *, const char *, const int *, const int *, const int *, const double *,
            const double *, const int *, const double *, const int *, const double *, double *,
            const int *);
void dgemv_(const char *, const int *, const int *, const double *, const double *, const int *,
            const double *, const int *, const double *, double *, const int *);

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(void)
{
  const int sizes[] = {16, 64, 128, 256, 512};
  printf("m,sgemm_n1_us,sgemv_us,sgemm_n2_us,sgemv_x2_us,strsm_n1_us,strsv_us,dgemm_n1_us,dgemv_us\n");
  for (int s = 0; s < 5; ++s)
    {
      const int m = sizes[s], one = 1, two = 2;
      const float al = 1, be = 1;
      const double dal = 1, dbe = 1;
      float *a = malloc(sizeof(float) * m * m), *x = malloc(sizeof(float) * 2 * m),
            *y = malloc(sizeof(float) * 2 * m);
      double *da = malloc(sizeof(double) * m * m), *dx = malloc(sizeof(double) * m),
             *dy = malloc(sizeof(double) * m);
      for (int i = 0; i < m * m; ++i)
        da[i] = a[i] = 1.0f / (1 + i % 7);
      for (int i = 0; i < m; ++i)
        da[i + i * m] = a[i + i * m] = 10;
      for (int i = 0; i < 2 * m; ++i)
        x[i] = 1, y[i] = 0;
      for (int i = 0; i < m; ++i)
        dx[i] = 1, dy[i] = 0;
      const int reps = 20000000 / (m * m) + 10;
      double t[9];
      t[0] = now();
      for (int r = 0; r < reps; ++r)
        sgemm_("N", "N", &m, &one, &m, &al, a, &m, x, &m, &be, y, &m);
      t[1] = now();
      for (int r = 0; r < reps; ++r)
        sgemv_("N", &m, &m, &al, a, &m, x, &one, &be, y, &one);
      t[2] = now();
      for (int r = 0; r < reps; ++r)
        sgemm_("N", "N", &m, &two, &m, &al, a, &m, x, &m, &be, y, &m);
      t[3] = now();
      for (int r = 0; r < reps; ++r)
        {
          sgemv_("N", &m, &m, &al, a, &m, x, &one, &be, y, &one);
          sgemv_("N", &m, &m, &al, a, &m, x + m, &one, &be, y + m, &one);
        }
      t[4] = now();
      for (int r = 0; r < reps; ++r)
        strsm_("L", "L", "N", "U", &m, &one, &al, a, &m, x, &m);
      t[5] = now();
      for (int r = 0; r < reps; ++r)
        strsv_("L", "N", "U", &m, a, &m, x, &one);
      t[6] = now();
      for (int r = 0; r < reps; ++r)
        dgemm_("N", "N", &m, &one, &m, &dal, da, &m, dx, &m, &dbe, dy, &m);
      t[7] = now();
      for (int r = 0; r < reps; ++r)
        dgemv_("N", &m, &m, &dal, da, &m, dx, &one, &dbe, dy, &one);
      t[8] = now();
      printf("%d", m);
      for (int i = 0; i < 8; ++i)
        printf(",%.3g", 1e6 * (t[i + 1] - t[i]) / reps);
      printf("\n");
      free(a), free(x), free(y), free(da), free(dx), free(dy);
    }
  return 0;
}
