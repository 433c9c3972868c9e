/* What this host gives a second process, for the speed-up of 2 MPI ranks
 * over 1 (bench/host_scaling.sh). One measurement per run:
 *
 *   host_scaling compute REPS   arithmetic alone (eight independent chains
 *                               of multiply-adds in registers): G operations/s
 *   host_scaling MIB REPS       an array of MIB MiB read and written back in
 *                               order, as the core steps the rows of bonds:
 *                               GB/s (bytes read plus bytes written)
 *
 * Prints the best of REPS timings.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* 8 chains x `n` multiply-adds; the result keeps the compiler from
 * dropping the work */
static double compute(long n, double seed)
{
    double c[8];
    for (int k = 0; k < 8; k++) c[k] = seed + k;
    for (long i = 0; i < n; i++)
        for (int k = 0; k < 8; k++) c[k] = c[k] * 0.9999999 + 1e-7;
    double s = 0.0;
    for (int k = 0; k < 8; k++) s += c[k];
    return s;
}

int main(int argc, char **argv)
{
    if (argc != 3 || atoi(argv[2]) < 1) {
        fprintf(stderr, "usage: host_scaling compute|MIB REPS\n");
        return 2;
    }
    const int reps = atoi(argv[2]);
    double best = 1e300, work = 0.0, check = 0.0;
    if (strcmp(argv[1], "compute") == 0) {
        const long n = 50000000;
        for (int r = 0; r < reps; r++) {
            const double t0 = now();
            check += compute(n, (double)r);
            const double t = now() - t0;
            if (t < best) best = t;
        }
        work = 8.0 * (double)n;
    } else {
        const double mib = atof(argv[1]);
        const size_t n = (size_t)(mib * 1024.0 * 1024.0 / sizeof(double));
        if (n < 1024) {
            fprintf(stderr, "host_scaling: MIB must be at least 0.01\n");
            return 2;
        }
        double *a = malloc(n * sizeof(double));
        if (!a) {
            fprintf(stderr, "host_scaling: cannot allocate %s MiB\n", argv[1]);
            return 1;
        }
        for (size_t i = 0; i < n; i++) a[i] = (double)(i & 1023);
        /* enough passes over a small array that each timing lasts a while */
        const size_t passes = n < ((size_t)1 << 25) ? ((size_t)1 << 25) / n : 1;
        for (int r = 0; r < reps; r++) {
            const double t0 = now();
            for (size_t p = 0; p < passes; p++)
                for (size_t i = 0; i < n; i++) a[i] = a[i] * 0.999999 + 1.0;
            const double t = now() - t0;
            if (t < best) best = t;
        }
        for (size_t i = 0; i < n; i += 4096) check += a[i];
        work = 2.0 * (double)n * sizeof(double) * (double)passes;
        free(a);
    }
    printf("%.2f %g\n", work / best / 1e9, check);
    return 0;
}
