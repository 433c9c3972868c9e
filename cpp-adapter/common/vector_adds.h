// Loads added to the engines' per-atom sums (blocks of 3 doubles per atom),
// the first two components of each 3-vector in one 16-byte SSE2 operation.
// Each lane computes the scalar operation, so the sums are the same bits as
// one component at a time.
#ifndef GRANBOND_VECTOR_ADDS_H
#define GRANBOND_VECTOR_ADDS_H

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace granbond {

// to += from
inline void add3(double *to, const double *from)
{
#if defined(__SSE2__)
    _mm_storeu_pd(to, _mm_add_pd(_mm_loadu_pd(to), _mm_loadu_pd(from)));
#else
    to[0] += from[0];
    to[1] += from[1];
#endif
    to[2] += from[2];
}

// to -= from
inline void subtract3(double *to, const double *from)
{
#if defined(__SSE2__)
    _mm_storeu_pd(to, _mm_sub_pd(_mm_loadu_pd(to), _mm_loadu_pd(from)));
#else
    to[0] -= from[0];
    to[1] -= from[1];
#endif
    to[2] -= from[2];
}

}

#endif
