// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/parallel.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sfa {
namespace {
thread_local int thread_limit = 0;
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

ThreadLimit::ThreadLimit(int threads) : previous_(thread_limit) { thread_limit = threads; }

ThreadLimit::~ThreadLimit() { thread_limit = previous_; }

} // namespace sfa
