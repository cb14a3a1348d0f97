// SPDX-License-Identifier: BSD-3-Clause
// Replacement global operator new/delete with a failure countdown (see alloc_hook.h).
#include "alloc_hook/alloc_hook.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

// Atomic because the library may allocate from its own worker threads.
std::atomic<long> countdown{-1};
std::atomic<int> fired{0};

// True for exactly the one allocation the countdown selects.
bool should_fail()
{
    long n = countdown.load(std::memory_order_relaxed);
    while (n >= 0) {
        if (countdown.compare_exchange_weak(n, n - 1, std::memory_order_relaxed)) {
            if (n == 0) {
                fired.store(1, std::memory_order_relaxed);
                return true;
            }
            return false;
        }
    }
    return false;
}

void *allocate(std::size_t size)
{
    if (should_fail())
        return nullptr;
    return std::malloc(size ? size : 1);
}

void *allocate_aligned(std::size_t size, std::align_val_t alignment)
{
    if (should_fail())
        return nullptr;
    const std::size_t a = static_cast<std::size_t>(alignment);
    // aligned_alloc wants a size that is a multiple of the alignment.
    const std::size_t rounded = ((size ? size : 1) + a - 1) / a * a;
    return std::aligned_alloc(a, rounded);
}

void *or_throw(void *p)
{
    if (!p)
        throw std::bad_alloc();
    return p;
}

} // namespace

extern "C" void sfa_test_fail_allocation_after(long n)
{
    fired.store(0, std::memory_order_relaxed);
    countdown.store(n, std::memory_order_relaxed);
}

extern "C" int sfa_test_allocation_failed(void) { return fired.load(std::memory_order_relaxed); }

void *operator new(std::size_t size) { return or_throw(allocate(size)); }
void *operator new[](std::size_t size) { return or_throw(allocate(size)); }
void *operator new(std::size_t size, const std::nothrow_t &) noexcept { return allocate(size); }
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept { return allocate(size); }
void *operator new(std::size_t size, std::align_val_t a) { return or_throw(allocate_aligned(size, a)); }
void *operator new[](std::size_t size, std::align_val_t a) { return or_throw(allocate_aligned(size, a)); }
void *operator new(std::size_t size, std::align_val_t a, const std::nothrow_t &) noexcept
{
    return allocate_aligned(size, a);
}
void *operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t &) noexcept
{
    return allocate_aligned(size, a);
}

// Every delete frees what malloc or aligned_alloc gave.
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t, const std::nothrow_t &) noexcept { std::free(p); }
