/* SPDX-License-Identifier: BSD-3-Clause */
/* Provoking std::bad_alloc inside the library from C tests.
 *
 * The test executables define the global operator new (alloc_hook.cpp); being linked
 * dynamically, theirs takes the place of the library's, so every allocation the library
 * makes through new goes through the countdown below. Builds that cannot interpose
 * (the sanitizer build links everything statically, and ASan owns operator new) define
 * SFA_NO_ALLOC_HOOK, and the tests that need the hook skip. */
#ifndef SURFADAPT_TEST_ALLOC_HOOK_H
#define SURFADAPT_TEST_ALLOC_HOOK_H

#ifdef __cplusplus
extern "C" {
#endif

/* n >= 0: n more allocations succeed, the one after fails (n = 0: the next one fails),
 * and so do none after that (the countdown disarms itself once it has fired).
 * n < 0: no allocation fails. */
void sfa_test_fail_allocation_after(long n);

/* 1 if the countdown has fired since it was last set. */
int sfa_test_allocation_failed(void);

#ifdef __cplusplus
}
#endif

#endif
