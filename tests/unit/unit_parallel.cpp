// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the library's default thread count: a process narrowed to one CPU after it
// started (as an MPI library binds its ranks in MPI_Init) runs its loops on one thread,
// the same process with its CPUs back uses them again, and OMP_NUM_THREADS, when set,
// is the user's choice and is kept.
#include "mesh/parallel.hpp"

#include <cstdarg>
#include <cstddef>
#include <cstdlib>
#include <omp.h>
#include <sched.h>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

using namespace sfa;

namespace {

// The threads a parallel loop of the library really runs on, inside a call whose host
// set no thread count.
int threads_of_a_call()
{
    const ThreadLimit call(0);
    int seen = 0;
#pragma omp parallel num_threads(loop_threads())
    {
#pragma omp single
        seen = omp_get_num_threads();
    }
    return seen;
}

// The CPUs the process may run on now, and a set of the first of them alone.
void cpus_now_and_the_first(cpu_set_t &all, cpu_set_t &one)
{
    assert_int_equal(sched_getaffinity(0, sizeof all, &all), 0);
    int first = 0;
    while (!CPU_ISSET(first, &all))
        ++first;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
}

void narrowing_the_cpus_after_start_narrows_the_threads(void **)
{
    unsetenv("OMP_NUM_THREADS");
    cpu_set_t all, one;
    cpus_now_and_the_first(all, one);
    if (CPU_COUNT(&all) < 2 || omp_get_max_threads() < 2) {
        skip(); // one CPU: nothing to narrow
        return;
    }
    assert_int_equal(sched_setaffinity(0, sizeof one, &one), 0);
    const int narrowed = threads_of_a_call();
    assert_int_equal(sched_setaffinity(0, sizeof all, &all), 0);
    assert_int_equal(narrowed, 1);
    assert_int_equal(threads_of_a_call(), omp_get_max_threads());
}

void omp_num_threads_is_kept_when_set(void **)
{
    cpu_set_t all, one;
    cpus_now_and_the_first(all, one);
    setenv("OMP_NUM_THREADS", "2", 1);
    assert_int_equal(sched_setaffinity(0, sizeof one, &one), 0);
    const int chosen = default_threads();
    assert_int_equal(sched_setaffinity(0, sizeof all, &all), 0);
    unsetenv("OMP_NUM_THREADS");
    assert_int_equal(chosen, omp_get_max_threads());
}

void a_host_limit_wins(void **)
{
    const ThreadLimit call(1);
    assert_int_equal(loop_threads(), 1);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(narrowing_the_cpus_after_start_narrows_the_threads),
        cmocka_unit_test(omp_num_threads_is_kept_when_set),
        cmocka_unit_test(a_host_limit_wins),
    };
    return cmocka_run_group_tests_name("unit_parallel", tests, nullptr, nullptr);
}
