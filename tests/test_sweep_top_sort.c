/*
 * test_sweep_top_sort.c: the memory check's sort of its largest estimates
 * (gw_sweep_top_sort, common/sweep/gw_sweep_run.c) when there is no memory
 * for the copy of the pairs it sorts. That fallback was an insertion sort in
 * place, quadratic: for the million jobs a grid can be checked at (the heap
 * of estimates handed over in heap order), hours. It is a heap sort in place
 * now (gw_sweep_top_heapsort). Each case sorts the same pairs both ways and
 * checks the fallback's order is the qsort path's, pair for pair, and the
 * order asked for (decreasing estimate, the first case first among equal
 * ones), each case as a part in its own child under a limit of CPU seconds
 * (not a timing: a quadratic sort of 1e6 pairs never ends within it; the heap
 * sort takes well under a second, several under the sanitizer).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "gw_sweep_impl.h"
#include "gw_test_calls.h"

enum { BIG = 1000000 };

/* the pairs of a case: n estimates by pattern, each with a distinct case */
typedef enum { RANDOM_TIES, RISING, FALLING, EQUAL, HEAP_OF_RISING } pattern;

static void fill(double *b, long *k, long n, pattern p, uint64_t seed)
{
    uint64_t s = seed;
    for (long i = 0; i < n; i++) {
        k[i] = i;
        switch (p) {
        case RANDOM_TIES: b[i] = (double)(gw_test_xorshift(&s) % 997) * 1e6; break;
        case RISING: b[i] = (double)i; break;
        case FALLING: b[i] = (double)(n - i); break;
        case EQUAL: b[i] = 3.5e8; break;
        case HEAP_OF_RISING: b[i] = (double)(i / 3); break; /* three cases per estimate */
        }
    }
    /* the cases shuffled (Fisher-Yates): ties between any cases */
    for (long i = n - 1; i > 0; i--) {
        const long j = (long)(gw_test_xorshift(&s) % (uint64_t)(i + 1)), t = k[i];
        k[i] = k[j], k[j] = t;
    }
    if (p == HEAP_OF_RISING) /* equal estimates' cases in order: the reverse of the order asked but for ties */
        for (long i = 0; i < n; i++)
            k[i] = i;
}

static void cpu_limit(rlim_t seconds)
{
    struct rlimit rl = {seconds, seconds};
    setrlimit(RLIMIT_CPU, &rl);
}

static long case_n;
static pattern case_p;

static void sort_case(const char *dir)
{
    (void)dir;
    cpu_limit(30);
    const long n = case_n;
    double *b = malloc((size_t)(n > 0 ? n : 1) * sizeof *b), *b2 = malloc((size_t)(n > 0 ? n : 1) * sizeof *b2);
    long *k = malloc((size_t)(n > 0 ? n : 1) * sizeof *k), *k2 = malloc((size_t)(n > 0 ? n : 1) * sizeof *k2);
    unsigned char *seen = calloc((size_t)(n > 0 ? n : 1), 1);
    if (!b || !b2 || !k || !k2 || !seen) {
        GW_TEST_OK(0, "n %ld: no memory for the test's arrays", n);
        return;
    }
    fill(b, k, n, case_p, 0x9e3779b97f4a7c15ULL + (uint64_t)n);
    memcpy(b2, b, (size_t)n * sizeof *b);
    memcpy(k2, k, (size_t)n * sizeof *k);
    gw_sweep_top_sort(b, k, n);      /* the qsort path (the test has the memory) */
    gw_sweep_top_heapsort(b2, k2, n); /* the fallback, forced */
    long same = 0, ordered = 0, once = 0;
    for (long i = 0; i < n; i++) {
        same += b[i] == b2[i] && k[i] == k2[i];
        ordered += i == 0 || b2[i - 1] > b2[i] || (b2[i - 1] == b2[i] && k2[i - 1] < k2[i]);
        if (k2[i] >= 0 && k2[i] < n && !seen[k2[i]])
            seen[k2[i]] = 1, once++;
    }
    GW_TEST_OK(same == n, "pattern %d, n %ld: the fallback's order is the qsort path's (%ld of %ld pairs the same)",
               (int)case_p, n, same, n);
    GW_TEST_OK(ordered == n, "pattern %d, n %ld: decreasing estimate, first case first among equal ones (%ld of %ld)",
               (int)case_p, n, ordered, n);
    GW_TEST_OK(once == n, "pattern %d, n %ld: every case once (%ld of %ld)", (int)case_p, n, once, n);
    free(b), free(b2), free(k), free(k2), free(seen);
}

int main(void)
{
    const struct {
        long n;
        pattern p;
        const char *name;
    } cases[] = {
        {0, RANDOM_TIES, "no pairs"},
        {1, RANDOM_TIES, "one pair"},
        {2, EQUAL, "two equal estimates"},
        {3, FALLING, "three already in order"},
        {17, RANDOM_TIES, "17 with ties"},
        {1000, RISING, "1000 rising"},
        {BIG, RANDOM_TIES, "1e6 with ties (997 estimates)"},
        {BIG, RISING, "1e6 rising (the reverse of the order)"},
        {BIG, FALLING, "1e6 already in order"},
        {BIG, EQUAL, "1e6 equal estimates, cases shuffled"},
        {BIG, HEAP_OF_RISING, "1e6 rising in threes, cases in order"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        case_n = cases[i].n, case_p = cases[i].p;
        gw_test_part(cases[i].name, sort_case, "");
    }
    return gw_test_summary("test_sweep_top_sort");
}
