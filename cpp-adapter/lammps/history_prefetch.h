// The history records of one atom's flagged pairs (touching contacts, bonds
// whose contact goes on under them), requested from memory ahead of their
// use by the contact loop: fix neigh/history keeps a record for every
// neighbour in its pages, so the flagged ones lie apart and each first read
// would otherwise wait for memory.
#ifndef GRANBOND_HISTORY_PREFETCH_H
#define GRANBOND_HISTORY_PREFETCH_H

namespace granbond {

// The records of the `count` pairs of one atom, `size` doubles each, side by
// side from `records`; pair `jj` is requested if its flag is set and is not
// `skip` (kSweptMark: a swept bond, whose record the loop reads only where
// its contact goes on under it). Always inlined: GCC deletes calls to a function whose only
// effect is prefetching.
__attribute__((always_inline)) inline void prefetchFlaggedRecord(const int *flags, const double *records, int jj,
                                                                  int size, int skip)
{
    if (flags[jj] && flags[jj] != skip)
        for (int s = 0; s < size; s += 8) __builtin_prefetch(records + size * jj + s, 1);
}

// Every pair of the atom.
__attribute__((always_inline)) inline void prefetchFlaggedRecords(const int *flags, const double *records,
                                                                   int count, int size, int skip)
{
    for (int jj = 0; jj < count; jj++) prefetchFlaggedRecord(flags, records, jj, size, skip);
}

// The same for the pairs at slots `slots[0 .. count)` of one atom's records.
__attribute__((always_inline)) inline void prefetchFlaggedSlots(const int *flags, const double *records,
                                                                 const int *slots, int count, int size, int skip)
{
    for (int s = 0; s < count; s++) prefetchFlaggedRecord(flags, records, slots[s], size, skip);
}

}

#endif
