// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/parallel.hpp"

#include <cstdlib>

#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef __linux__
#include <sched.h>
#endif

namespace sfa {
namespace {
thread_local int thread_limit = 0;
}

int default_threads()
{
#ifdef _OPENMP
    const int openmp = omp_get_max_threads();
    // OMP_NUM_THREADS is the user's explicit choice: kept as it is.
    if (std::getenv("OMP_NUM_THREADS"))
        return openmp;
#ifdef __linux__
    // OpenMP counts the CPUs the process may use once, when it starts. An MPI library that
    // binds each rank to its cores in MPI_Init, or a batch system that narrows the mask
    // later, would leave every rank with threads for the whole machine: ranks × threads
    // above the cores, which made a remesh three times slower on a busy two-core
    // machine. So the mask is read again at each call of the library (one system call).
    cpu_set_t mask;
    if (sched_getaffinity(0, sizeof mask, &mask) == 0) {
        const int usable = CPU_COUNT(&mask);
        if (usable >= 1 && usable < openmp)
            return usable;
    }
#endif
    return openmp;
#else
    return 1;
#endif
}

int loop_threads()
{
#ifdef _OPENMP
    return thread_limit > 0 ? thread_limit : omp_get_max_threads();
#else
    return 1;
#endif
}

int thread_index()
{
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

ThreadLimit::ThreadLimit(int threads) : previous_(thread_limit)
{
    thread_limit = threads > 0 ? threads : default_threads();
}

ThreadLimit::~ThreadLimit() { thread_limit = previous_; }

} // namespace sfa
