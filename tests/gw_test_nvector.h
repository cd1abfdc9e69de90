/*
 * gw_test_nvector.h: a check shared by the tests that run the same vector
 * operations on two sets of serial vectors and require the same bits.
 */
#ifndef GW_TEST_NVECTOR_H
#define GW_TEST_NVECTOR_H

#include <string.h>

#include <nvector/nvector_serial.h>

/* 1 when each of the nv vectors a[k] holds the same n doubles, bit for bit, as b[k] */
static inline int gw_test_same_vectors(const N_Vector *a, const N_Vector *b, int nv, long n)
{
    for (int k = 0; k < nv; k++)
        if (memcmp(N_VGetArrayPointer(a[k]), N_VGetArrayPointer(b[k]), (size_t)n * sizeof(double)) != 0)
            return 0;
    return 1;
}

#endif
