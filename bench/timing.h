/* SPDX-License-Identifier: BSD-3-Clause */
/* Timing helpers shared by the benchmark drivers: a monotonic clock and the median of
 * repeated runs (the figure every benchmark reports). */
#ifndef SURFADAPT_BENCH_TIMING_H
#define SURFADAPT_BENCH_TIMING_H

#include <stdlib.h>
#include <time.h>

static inline double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorts the samples in place. */
static inline double median(double *samples, int count)
{
    qsort(samples, (size_t)count, sizeof *samples, compare_doubles);
    return samples[count / 2];
}

#endif
