// SPDX-License-Identifier: BSD-3-Clause
// Threads for the per-vertex and per-edge loops (OpenMP). Every parallel loop writes only
// its own elements, and floating-point sums go through ordered_sum, so results are
// bit-identical for any number of threads. A loop body must not throw (an exception cannot leave an OpenMP
// region): anything that can fail, allocation included, happens before or after the loop.
// This header sits in the lowest layer because every layer loops.
#pragma once

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

} // namespace sfa
