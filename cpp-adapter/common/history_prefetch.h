// The history records of one atom's flagged pairs (bonds, touching
// contacts), requested from memory ahead of their use: both engines keep a
// record for every neighbour in their history pages, so the flagged ones lie
// apart and each first read would otherwise wait for memory.
#ifndef GRANBOND_HISTORY_PREFETCH_H
#define GRANBOND_HISTORY_PREFETCH_H

namespace granbond {

// The records of the `count` pairs of one atom, `size` doubles each, side by
// side from `records`; pair `jj` is requested if `flags[jj]` is 1 (a plain flagged pair). Always
// inlined: GCC deletes calls to a function whose only effect is prefetching.
__attribute__((always_inline)) inline void prefetchFlaggedRecords(const int *flags, const double *records,
                                                                   int count, int size)
{
    for (int jj = 0; jj < count; jj++)
        if (flags[jj] == 1)   // 2: a swept bond (bond_index.h), whose record the loop does not read
            for (int s = 0; s < size; s += 8) __builtin_prefetch(records + size * jj + s, 1);
}

}

#endif
