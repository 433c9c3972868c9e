// The gathering half of GRANBOND_CHECK_STORE, the recount both adapters
// make after every pass (docs/development.md, "Where a bond lives"): the
// core checks that each bond of a rank joins a local owner and a partner
// with the id it names (granbond_bond_store_check_keys), that each bond is
// stored once over all ranks and that created = broken + intact + lost
// over all ranks (granbond_store_check_findings); this gathers the keys
// and sums the counts. The adapters walk their lists for the core's check
// of each pair's flag (flagFinding: flagged bonded exactly when the store
// or its view holds its bond). checkWallBonds does the same for a wall
// fix's bonds.
#ifndef GRANBOND_STORE_CHECK_H
#define GRANBOND_STORE_CHECK_H

#include "core_message.h"
#include "granbond.h"

#include <mpi.h>

#include <string>
#include <vector>

namespace granbond {

// The core's findings over all ranks (empty: nothing): a key held twice
// among every rank's `mine` (two values a key), else counts that do not
// balance, `c` this rank's counts and `restored` the bonds it took from a
// restart file. `walls`: the keys are (sphere, wall), else (atom, atom).
// Collective, so every rank calls it whatever else it found.
inline std::string storeFindings(const std::vector<double> &mine, const GbStoreCounts &c, long long restored,
                                 bool walls, MPI_Comm world)
{
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(nprocs), offsets(nprocs + 1, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int r = 0; r < nprocs; r++) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(static_cast<size_t>(offsets[nprocs]));
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
    double row[GRANBOND_COUNTS_ROW_LEN];
    granbond_store_counts_row(&c, row);
    const int64_t local[4] = {c.created + restored, static_cast<int64_t>(row[1]), c.intact,
                              static_cast<int64_t>(row[7])};
    int64_t sums[4];
    MPI_Allreduce(local, sums, 4, MPI_INT64_T, MPI_SUM, world);
    GbCheckReport report;
    if (granbond_store_check_findings(all.data(), all.size() / 2, sums, walls ? 1 : 0, &report) != GB_STATUS_OK)
        return "the store check's findings: " + coreReason();
    return report.level > 0 ? std::string(report.message) : std::string();
}

// What is wrong with the flag `flagged` of the listed pair of local atom i
// and atom j in the engine's contact history against the store and its
// view (the core's words), or "".
inline std::string flagFinding(const GbBondStore *store, int i, int j, const GbAtomIds &ids, bool flagged)
{
    GbCheckReport found;
    if (granbond_bond_store_check_flag(store, static_cast<size_t>(i), static_cast<size_t>(j), &ids, flagged ? 1 : 0,
                                       &found) != GB_STATUS_OK)
        return coreReason();
    return found.level > 0 ? std::string(found.message) : std::string();
}

// This rank's keys and finding as the core gives them (`check`: one of
// granbond_bond_store_check_keys, granbond_wall_store_check_keys), then
// the findings over all ranks: this rank's own first. Collective.
template <class Check>
std::string checkedKeys(size_t bonds, Check check, const GbStoreCounts &c, long long restored, bool walls,
                        MPI_Comm world)
{
    std::vector<double> keys(2 * bonds);
    size_t written = 0;
    GbCheckReport here;
    std::string wrong;
    if (check(keys.data(), keys.size(), &written, &here) != GB_STATUS_OK)
        wrong = coreReason();
    else if (here.level > 0)
        wrong = here.message;
    keys.resize(2 * written);
    const std::string found = storeFindings(keys, c, restored, walls, world);
    return wrong.empty() ? found : wrong;
}

// What is wrong with the bonds of `store` on this rank (empty: nothing):
// `ids` those of the rank's atoms (local, then ghost). Collective.
inline std::string checkStoredBonds(const GbBondStore *store, const GbAtomIds &ids, int nlocal, MPI_Comm world)
{
    GbStoreCounts c = {};
    granbond_bond_store_counts(store, &c);
    return checkedKeys(
        granbond_bond_store_len(store),
        [&](double *keys, size_t capacity, size_t *written, GbCheckReport *here) {
            return granbond_bond_store_check_keys(store, &ids, static_cast<size_t>(nlocal), keys, capacity, written,
                                                  here);
        },
        c, 0, false, world);
}

// The same for the wall bonds of `store`, `ids` those of the rank's local
// atoms: each held by the rank of its sphere, each (sphere, wall) held
// once over all ranks, created + restored = broken + intact + lost over
// all ranks, where `restored` are the intact bonds this rank's store took
// from a restart file (their counts stayed with the file's totals).
// Collective.
inline std::string checkWallBonds(const GbWallStore *store, long long restored, const GbAtomIds &ids,
                                  MPI_Comm world)
{
    GbStoreCounts c = {};
    granbond_wall_store_counts(store, &c);
    return checkedKeys(
        granbond_wall_store_len(store),
        [&](double *keys, size_t capacity, size_t *written, GbCheckReport *here) {
            return granbond_wall_store_check_keys(store, &ids, keys, capacity, written, here);
        },
        c, restored, true, world);
}

}

#endif
