// SPDX-License-Identifier: BSD-3-Clause
// A std::vector for a buffer that a loop fills right after it is made: its elements are
// default-initialized rather than value-initialized. A value-initialized aggregate (a
// struct of Eigen vectors, std::array<Vec3, 2>) is zeroed first; for the per-triangle
// buffers of collision-safe motion's search that was about 180 bytes a triangle every
// step, some 5 % of bench_collision's instructions.
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace sfa {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U> &) noexcept {}
    template <class U>
    void construct(U *at) noexcept(noexcept(U()))
    {
        ::new (static_cast<void *>(at)) U; // default-initialized: no zeroing
    }
    template <class U, class... Args>
    void construct(U *at, Args &&...args)
    {
        ::new (static_cast<void *>(at)) U(std::forward<Args>(args)...);
    }
};

template <class T>
using FillBuffer = std::vector<T, DefaultInitAllocator<T>>;

} // namespace sfa
