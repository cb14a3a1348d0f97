// SPDX-License-Identifier: BSD-3-Clause
// Threads for the per-vertex and per-edge loops (OpenMP). Every parallel loop writes only
// its own elements, and floating-point sums go through ordered_sum, so results are
// bit-identical for any number of threads. A loop body must not throw (an exception cannot leave an OpenMP
// region): anything that can fail, allocation included, happens before or after the loop.
// This header sits in the lowest layer because every layer loops.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

namespace sfa {

// The thread count for `#pragma omp parallel for num_threads(loop_threads())` in the
// current call: the limit a ThreadLimit set on this thread, else OpenMP's default; 1
// without OpenMP.
int loop_threads();

// The number of the calling thread in the current parallel loop, below loop_threads(); 0
// outside one and without OpenMP. It picks a thread's scratch space, allocated before the
// loop.
int thread_index();

// The threads a call uses when the host sets none: OMP_NUM_THREADS when it is set, else
// the CPUs the process may run on now (its affinity mask), at most OpenMP's default.
int default_threads();

// Sets this thread's limit for its lifetime (0: default_threads()), and restores the
// previous one after. The C boundary sets it from SFA_PARAM_THREADS around every call, so
// concurrent handles in different threads each keep their own.
class ThreadLimit {
public:
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit &) = delete;
    ThreadLimit &operator=(const ThreadLimit &) = delete;

private:
    int previous_;
};

// Carries the first exception out of a parallel loop whose body must allocate as it goes
// (scratch that grows with what it finds: the pairs of a broad phase): an exception that
// leaves an OpenMP region ends the program. Each iteration's work runs in run(), which
// does nothing more once one has failed; after the loop, rethrow() throws what failed.
class LoopFailure {
public:
    template <class Work>
    void run(Work &&work) noexcept
    {
        if (failed_.load(std::memory_order_relaxed))
            return;
        try {
            work();
        } catch (...) {
            if (!failed_.exchange(true))
                error_ = std::current_exception(); // the first failure only: one writer
        }
    }
    // Called after the loop, outside any parallel region.
    void rethrow() const
    {
        if (failed_.load())
            std::rethrow_exception(error_);
    }

private:
    std::atomic<bool> failed_{false};
    std::exception_ptr error_;
};

// The first i in [0, count) for which bad(i) holds, or count: a min-reduction, the same
// for any number of threads. bad must not throw.
template <class Bad>
int32_t first_where(int32_t count, Bad &&bad)
{
    int32_t first = count;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(min : first)
    for (int32_t i = 0; i < count; ++i)
        if (bad(i) && i < first)
            first = i;
    return first;
}

// The block of ordered_sum and ordered_group_sums.
inline constexpr int32_t ordered_sum_block = 4096;

// Per group g in [0, groups): term(i) over the i in [0, count) with group_of(i) == g,
// combined by combine(a, b) from `identity`, block by block in order and then the blocks'
// results in order, so that the result does not depend on the number of threads.
// Allocates blocks x groups partial results; group_of, term and combine must not throw.
template <class T, class GroupOf, class Term, class Combine>
std::vector<T> ordered_group_reduce(int32_t count, int32_t groups, const T &identity, GroupOf &&group_of, Term &&term,
                                    Combine &&combine)
{
    constexpr int32_t block = ordered_sum_block;
    const int32_t blocks = (count + block - 1) / block;
    std::vector<T> partial(static_cast<size_t>(blocks) * groups, identity);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t b = 0; b < blocks; ++b)
        for (int32_t i = b * block; i < count && i < (b + 1) * block; ++i) {
            T &into = partial[static_cast<size_t>(b) * groups + group_of(i)];
            into = combine(into, term(i));
        }
    std::vector<T> total(groups, identity);
    for (int32_t b = 0; b < blocks; ++b)
        for (int32_t g = 0; g < groups; ++g)
            total[g] = combine(total[g], partial[static_cast<size_t>(b) * groups + g]);
    return total;
}

// ordered_group_reduce's sums, rounded as ordered_sum rounds (with one group, its very
// result).
template <class T, class GroupOf, class Term>
std::vector<T> ordered_group_sums(int32_t count, int32_t groups, const T &zero, GroupOf &&group_of, Term &&term)
{
    return ordered_group_reduce(count, groups, zero, group_of, term, [](const T &a, const T &b) { return T(a + b); });
}

// The sum of term(i) for i in [0, count): fixed blocks summed in order, in parallel, and
// then the block sums in order, so that the rounding does not depend on the number of
// threads. T is double or a fixed-size Eigen vector; term must not throw.
template <class T, class Term>
T ordered_sum(int32_t count, const T &zero, Term &&term)
{
    constexpr int32_t block = ordered_sum_block;
    std::vector<T> partial((count + block - 1) / block, zero);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t b = 0; b < static_cast<int32_t>(partial.size()); ++b) {
        T sum = zero;
        for (int32_t i = b * block; i < count && i < (b + 1) * block; ++i)
            sum += term(i);
        partial[b] = sum;
    }
    T total = zero;
    for (const T &sum : partial)
        total += sum;
    return total;
}

// Sets number[i] to the number of i among the i in [0, count) that keep(i) holds for, in
// increasing order, or to -1 where it does not; returns how many are kept. Block by block
// in parallel: each block's count, then where each block's numbers start, then the
// numbers. keep must not throw.
template <class Keep>
int32_t number_kept(int32_t count, Keep &&keep, std::vector<int32_t> &number)
{
    constexpr int32_t block = ordered_sum_block;
    const int32_t blocks = (count + block - 1) / block;
    number.resize(static_cast<size_t>(count));
    std::vector<int32_t> start(static_cast<size_t>(blocks) + 1, 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t b = 0; b < blocks; ++b) {
        int32_t kept = 0;
        for (int32_t i = b * block; i < count && i < (b + 1) * block; ++i) {
            number[i] = keep(i) ? 1 : -1; // 1: kept, numbered below
            kept += number[i] > 0;
        }
        start[b + 1] = kept;
    }
    for (int32_t b = 0; b < blocks; ++b)
        start[b + 1] += start[b];
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t b = 0; b < blocks; ++b) {
        int32_t next = start[b];
        for (int32_t i = b * block; i < count && i < (b + 1) * block; ++i)
            if (number[i] > 0)
                number[i] = next++;
    }
    return start[blocks];
}

// Sets `order` to 0, ..., n - 1 sorted by part_of(i) (parts numbered from 0 to parts - 1),
// in increasing order within each part (a stable sort), and part_start[p] to the place
// where part p begins (part_start[parts] = n). A counting sort in `runs` runs of indices
// (loop_threads(), say), each counted and then dealt in parallel to the places its part
// has for it; at most two counters per index in all, whatever the number of parts.
// part_of must not throw.
template <class PartOf>
void sort_into_parts(int32_t n, size_t parts, PartOf &&part_of, int runs, std::vector<int32_t> &part_start,
                     std::vector<int32_t> &order)
{
    const size_t most_runs = std::max<size_t>(1, 2 * static_cast<size_t>(n) / std::max<size_t>(parts, 1));
    runs = static_cast<int>(std::clamp<size_t>(static_cast<size_t>(runs), 1, most_runs));
    const auto run_start = [&](int r) { return static_cast<int32_t>(static_cast<int64_t>(n) * r / runs); };
    // Run r's count of part p, then the place of its next index in part p: at r parts + p.
    std::vector<int32_t> place(static_cast<size_t>(runs) * parts, 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static, 1)
    for (int r = 0; r < runs; ++r)
        for (int32_t i = run_start(r), end = run_start(r + 1); i < end; ++i)
            ++place[static_cast<size_t>(r) * parts + part_of(i)];
    part_start.assign(parts + 1, 0);
    int32_t at = 0;
    for (size_t p = 0; p < parts; ++p) {
        part_start[p] = at;
        for (int r = 0; r < runs; ++r) {
            const int32_t count = place[static_cast<size_t>(r) * parts + p];
            place[static_cast<size_t>(r) * parts + p] = at;
            at += count;
        }
    }
    part_start[parts] = at;
    order.resize(static_cast<size_t>(n));
#pragma omp parallel for num_threads(loop_threads()) schedule(static, 1)
    for (int r = 0; r < runs; ++r)
        for (int32_t i = run_start(r), end = run_start(r + 1); i < end; ++i)
            order[static_cast<size_t>(place[static_cast<size_t>(r) * parts + part_of(i)]++)] = i;
}

} // namespace sfa
