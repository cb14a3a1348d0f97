/* SPDX-License-Identifier: BSD-3-Clause */
/* A host built only from what `make install` put in place, found through pkg-config. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <surfadapt.h>

int main(void)
{
    char want[64];
    snprintf(want, sizeof want, "%d.%d.%d", SFA_VERSION_MAJOR, SFA_VERSION_MINOR, SFA_VERSION_PATCH);
    if (strcmp(sfa_version_string(), want) != 0) {
        printf("library %s, installed header %s\n", sfa_version_string(), want);
        return 1;
    }

    /* Unit right tetrahedron, outward counter-clockwise triangles: volume 1/6. */
    static const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const int32_t tris[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    sfa_surface *s = NULL;
    double volume = 0.0;
    int rc = sfa_create(&s);
    if (rc == SFA_OK)
        rc = sfa_set_mesh(s, 4, xyz, 4, tris, 0);
    if (rc == SFA_OK)
        rc = sfa_measure(s, SFA_MEASURE_VOLUME, &volume);
    if (rc != SFA_OK || fabs(volume - 1.0 / 6.0) > 1e-15) {
        printf("status %d (%s), volume %.17g\n", rc, sfa_last_error(s), volume);
        sfa_destroy(s);
        return 1;
    }
    sfa_destroy(s);
    printf("surfadapt %s: tetrahedron volume %.17g\n", want, volume);
    return 0;
}
