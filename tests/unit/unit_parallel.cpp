// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the library's default thread count: a process narrowed to one CPU after it
// started (as an MPI library binds its ranks in MPI_Init) runs its loops on one thread,
// the same process with its CPUs back uses them again, and OMP_NUM_THREADS, when set,
// is the user's choice and is kept. And the parallel stable counting sort and numbering of
// kept indices, against serial ones.
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <cstdlib>
#include <numeric>
#include <omp.h>
#include <sched.h>
#include <setjmp.h>
#include <vector>

#include "numbers.hpp" // before cmocka.h, whose fail() would break the standard headers it includes

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

// sort_into_parts orders the indices as a stable sort by part would,
// and says where each part begins, however many runs count and deal them, for parts
// many and few, some empty, and for no index at all.
void indices_are_sorted_into_parts_stably(void **)
{
    Numbers rng{20261205};
    for (const int32_t n : {0, 1, 5, 1000, 30000})
        for (const size_t parts : {size_t{1}, size_t{8}, size_t{1000}, size_t{100000}})
            for (int runs : {1, 2, 5}) {
                std::vector<size_t> part(static_cast<size_t>(n));
                for (size_t &p : part)
                    p = std::min(parts - 1, static_cast<size_t>(rng.uniform(0, static_cast<double>(parts))));
                std::vector<int32_t> part_start, order, expected(static_cast<size_t>(n));
                sort_into_parts(
                    n, parts, [&](int32_t i) { return part[static_cast<size_t>(i)]; }, runs, part_start, order);
                std::iota(expected.begin(), expected.end(), 0);
                std::stable_sort(expected.begin(), expected.end(),
                                 [&](int32_t a, int32_t b) { return part[static_cast<size_t>(a)] < part[static_cast<size_t>(b)]; });
                if (order != expected)
                    fail_msg("%d indices, %zu parts, %d runs: not in the order of a stable sort", n, parts, runs);
                assert_int_equal(part_start.size(), parts + 1);
                for (size_t p = 0; p < parts; ++p)
                    for (int32_t at = part_start[p]; at < part_start[p + 1]; ++at)
                        if (part[static_cast<size_t>(order[static_cast<size_t>(at)])] != p)
                            fail_msg("%d indices, %zu parts, %d runs: part %zu's run holds another", n, parts, runs, p);
                assert_int_equal(part_start[parts], n);
            }
}

// number_kept numbers the kept indices in order, across the blocks that threads take
// apart (4,096 indices each), for none kept, all kept and some, on 1 to 3 threads.
void kept_indices_are_numbered_in_order(void **)
{
    Numbers rng{20261206};
    for (const int32_t count : {0, 1, 4095, 4096, 4097, 30000})
        for (const double share : {0.0, 0.3, 1.0})
            for (int threads : {1, 2, 3}) {
                std::vector<char> keep(static_cast<size_t>(count));
                for (char &k : keep)
                    k = rng.uniform(0, 1) < share;
                const ThreadLimit limit(threads);
                std::vector<int32_t> number;
                const int32_t kept = number_kept(count, [&](int32_t i) { return keep[i] != 0; }, number);
                int32_t next = 0;
                for (int32_t i = 0; i < count; ++i)
                    if (number[i] != (keep[i] ? next++ : -1))
                        fail_msg("%d indices, %d threads: index %d numbered %d", count, threads, i, number[i]);
                assert_int_equal(kept, next);
            }
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
        cmocka_unit_test(indices_are_sorted_into_parts_stably),
        cmocka_unit_test(kept_indices_are_numbered_in_order),
    };
    return cmocka_run_group_tests_name("unit_parallel", tests, nullptr, nullptr);
}
