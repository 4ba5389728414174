/* Fill-in and cost of KLU on the iteration-matrix pattern of an n x n square net with compliant
 * knots and one element per thread (bench/net_scenes/): each thread element couples its 12
 * coordinates (r_A, r'_A, r_B, r'_B); each knot is a 3-coordinate point mass; each link couples a
 * thread end position (3) with its knot (3). The unknown counts match `ancfnet check`. Values are
 * random and diagonally dominant, so the pivots stay on the diagonal, as they do in the runs
 * (klu_refactor keeps its pivot order). Default KLU settings (BTF + AMD), as in
 * src/ancfnet/solvers/linear_solver.cpp. Stand-alone, not built by CMake:
 *   gcc -O2 -I/usr/include/suitesparse bench/net_klu_fill.c -o /tmp/klu_net_fill -lklu -lm
 *   for n in 10 20 40; do /tmp/klu_net_fill $n; done
 * Figures: docs/benchmarks.md, "Net deployment (issue 3)". */
#include <klu.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
typedef struct { int c, r; } P;
static int cmp(const void* a, const void* b) {
  const P *x = a, *y = b;
  return x->c != y->c ? x->c - y->c : x->r - y->r;
}
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(int argc, char** argv) {
  int n = atoi(argv[1]), nk = (n + 1) * (n + 1), ne = 2 * n * (n + 1);
  int N = 12 * ne + 3 * nk;
  size_t cap = (size_t)ne * 144 + (size_t)ne * 2 * 36 + (size_t)nk * 9, m = 0;
  P* p = malloc(cap * sizeof(P));
  int e = 0;
  for (int dir = 0; dir < 2; ++dir)
    for (int i = 0; i < (dir ? n + 1 : n); ++i)
      for (int j = 0; j < (dir ? n : n + 1); ++j, ++e) {
        int ka = dir ? i * (n + 1) + j : i * (n + 1) + j;
        int kb = dir ? i * (n + 1) + j + 1 : (i + 1) * (n + 1) + j;
        int b = 12 * e;
        for (int r = 0; r < 12; ++r) for (int c = 0; c < 12; ++c) p[m++] = (P){b + c, b + r};
        for (int end = 0; end < 2; ++end) {
          int q[6];
          for (int d = 0; d < 3; ++d) { q[d] = b + 6 * end + d; q[3 + d] = 12 * ne + 3 * (end ? kb : ka) + d; }
          for (int r = 0; r < 6; ++r) for (int c = 0; c < 6; ++c) p[m++] = (P){q[c], q[r]};
        }
      }
  for (int k = 0; k < nk; ++k)
    for (int r = 0; r < 3; ++r) for (int c = 0; c < 3; ++c) p[m++] = (P){12 * ne + 3 * k + c, 12 * ne + 3 * k + r};
  qsort(p, m, sizeof(P), cmp);
  int* Ap = calloc(N + 1, sizeof(int)); int* Ai = malloc(m * sizeof(int)); double* Ax = malloc(m * sizeof(double));
  size_t nnz = 0;
  srand(1);
  for (size_t t = 0; t < m; ++t) {
    if (t && p[t].c == p[t - 1].c && p[t].r == p[t - 1].r) continue;
    Ai[nnz] = p[t].r; Ax[nnz] = p[t].r == p[t].c ? 100.0 + rand() / (double)RAND_MAX : 2.0 * rand() / RAND_MAX - 1.0;
    Ap[p[t].c + 1]++; nnz++;
  }
  for (int c = 0; c < N; ++c) Ap[c + 1] += Ap[c];
  klu_common cm; klu_defaults(&cm);
  double t0 = now();
  klu_symbolic* S = klu_analyze(N, Ap, Ai, &cm);
  double t_an = now() - t0; t0 = now();
  klu_numeric* F = klu_factor(Ap, Ai, Ax, S, &cm);
  double t_f = now() - t0;
  klu_flops(S, F, &cm);
  int reps = n <= 10 ? 200 : n <= 20 ? 50 : 10;
  t0 = now(); for (int r = 0; r < reps; ++r) klu_refactor(Ap, Ai, Ax, S, F, &cm); double t_rf = (now() - t0) / reps;
  double* x = malloc(N * sizeof(double));
  t0 = now(); for (int r = 0; r < reps; ++r) { for (int i = 0; i < N; ++i) x[i] = 1.0; klu_solve(S, F, N, 1, x, &cm); } double t_s = (now() - t0) / reps;
  printf("%d x %d: elements %d, unknowns %d, nnz(A) %zu, nnz(L+U) %d (%.1f x nnz(A), %.1f per unknown), "
         "flops %.3g, analyze %.1f ms, factor %.2f ms, refactor %.2f ms (%.2f us/element), solve %.3f ms (%.3f us/element), offdiag pivots %d\n",
         n, n, ne, N, nnz, F->lnz + F->unz, (double)(F->lnz + F->unz) / nnz, (double)(F->lnz + F->unz) / N, cm.flops,
         1e3 * t_an, 1e3 * t_f, 1e3 * t_rf, 1e6 * t_rf / ne, 1e3 * t_s, 1e6 * t_s / ne, cm.noffdiag);
  return 0;
}
