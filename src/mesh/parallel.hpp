// Threads for the per-vertex and per-edge loops (OpenMP). Every parallel loop writes only
// its own elements and reduces nothing in floating point, so results are bit-identical for
// any number of threads. A loop body must not throw (an exception cannot leave an OpenMP
// region): anything that can fail, allocation included, happens before or after the loop.
// This header sits in the lowest layer because every layer loops.
#pragma once

namespace sfa {

// The thread count for `#pragma omp parallel for num_threads(loop_threads())` in the
// current call: the limit a ThreadLimit set on this thread, else OpenMP's default; 1
// without OpenMP.
int loop_threads();

// Sets this thread's limit for its lifetime (0: OpenMP's default), and restores the
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

} // namespace sfa
