/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark of the full adaptation: one sfa_adapt call on jittered geodesic spheres of
 * about 10k, 100k and 1M vertices at their own mean edge length (all default threads),
 * to see that the time per vertex stays flat as the mesh grows. One JSON line per size:
 * the median of the runs, in seconds and microseconds per vertex, and the peak memory.
 *
 * Each size runs in a process of its own, so that the peak resident size the kernel
 * reports (getrusage) is that size's alone. Two memory figures per vertex of the input:
 * the whole process's peak (the host's arrays included), and the library's part of it,
 * the peak less the resident size just before sfa_create (the handle, its mesh and
 * everything one sfa_adapt call allocates). */
#define _POSIX_C_SOURCE 199309L
#include "jittered_sphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

/* The resident size now, in bytes (the second field of /proc/self/statm, in pages). */
static double resident_bytes(void)
{
    long pages = 0;
    FILE *statm = fopen("/proc/self/statm", "r");
    if (statm) {
        if (fscanf(statm, "%*s %ld", &pages) != 1)
            pages = 0;
        fclose(statm);
    }
    return (double)pages * (double)sysconf(_SC_PAGESIZE);
}

/* The process's peak resident size, in bytes (Linux reports ru_maxrss in KiB). */
static double peak_resident_bytes(void)
{
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return 1024.0 * (double)usage.ru_maxrss;
}

static int bench_size(int frequency, int runs)
{
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
    if (jittered_sphere(frequency, &nverts, &xyz, &ntris, &tris) != 0)
        return 1;
    const double resident_before = resident_bytes();
    double samples[5];
    int32_t out_verts = 0, out_tris = 0;
    for (int r = 0; r < runs; ++r) {
        sfa_surface *s;
        if (sfa_create(&s) != SFA_OK || sfa_set_mesh(s, nverts, xyz, ntris, tris, 0) != SFA_OK)
            return 1;
        const double t0 = now();
        if (sfa_adapt(s) != SFA_OK) {
            fprintf(stderr, "sfa_adapt: %s\n", sfa_last_error(s));
            return 1;
        }
        samples[r] = now() - t0;
        sfa_get_counts(s, &out_verts, &out_tris);
        sfa_destroy(s);
    }
    const double seconds = median(samples, runs), peak = peak_resident_bytes();
    printf("{\"bench\":\"adapt\",\"vertices\":%d,\"vertices_after\":%d,\"median_s\":%.4f,"
           "\"us_per_vertex\":%.2f,\"runs\":%d,\"peak_rss_mb\":%.1f,"
           "\"peak_bytes_per_vertex\":%.0f,\"library_peak_bytes_per_vertex\":%.0f}\n",
           nverts, out_verts, seconds, 1e6 * seconds / nverts, runs, peak / 1048576.0,
           peak / nverts, (peak - resident_before) / nverts);
    fflush(stdout);
    free(xyz);
    free(tris);
    return 0;
}

int main(void)
{
    const int frequencies[] = {32, 100, 316}, runs[] = {5, 3, 1};
    for (int k = 0; k < 3; ++k) {
        fflush(stdout);
        const pid_t child = fork();
        if (child < 0)
            return 1;
        if (child == 0)
            _exit(bench_size(frequencies[k], runs[k]));
        int status;
        if (waitpid(child, &status, 0) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
            return 1;
    }
    return 0;
}
