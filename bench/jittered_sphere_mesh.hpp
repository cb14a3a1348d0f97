// SPDX-License-Identifier: BSD-3-Clause
// The jittered sphere of jittered_sphere.h as the library's own mesh, for the benchmarks
// that link the library's internals.
#pragma once

#include "mesh/validate.hpp"

extern "C" {
#include "jittered_sphere.h"
}

#include <cstdlib>
#include <new>

inline sfa::TriMesh jittered_sphere_mesh(int frequency)
{
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
    if (jittered_sphere(frequency, &nverts, &xyz, &ntris, &tris) != 0)
        throw std::bad_alloc(); // out of memory: the benchmarks' frequencies are in range
    sfa::TriMesh mesh = sfa::validated_mesh(sfa::MeshInput{nverts, xyz, ntris, tris, 0, false});
    std::free(xyz);
    std::free(tris);
    return mesh;
}
