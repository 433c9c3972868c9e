// The engine-free half of GRANBOND_CHECK_STORE, the recount both adapters
// make after every pass (docs/development.md, "Where a bond lives"): each
// bond of a rank joins a local owner and a partner with the id it names;
// each bond is stored once over all ranks; created = broken + intact +
// lost over all ranks. The adapters add what their lists say (every listed
// pair flagged bonded exactly when the store or its view holds its bond).
// checkWallBonds does the same for a wall fix's bonds.
#ifndef GRANBOND_STORE_CHECK_H
#define GRANBOND_STORE_CHECK_H

#include "bond_ledger.h"
#include "core_message.h"
#include "granbond.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace granbond {

// The pairs of values `mine` (two a pair) of all ranks, sorted, so that a
// pair held twice lies next to itself. Collective.
inline std::vector<std::pair<double, double>> gatheredPairs(const std::vector<double> &mine, MPI_Comm world)
{
    int nprocs = 1;
    MPI_Comm_size(world, &nprocs);
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(nprocs), offsets(nprocs + 1, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int r = 0; r < nprocs; r++) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(static_cast<size_t>(offsets[nprocs]));
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, world);
    std::vector<std::pair<double, double>> pairs;
    for (size_t k = 0; k + 1 < all.size(); k += 2) pairs.emplace_back(all[k], all[k + 1]);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// The first pair of the sorted `pairs` that is held twice, or null.
inline const std::pair<double, double> *repeatedPair(const std::vector<std::pair<double, double>> &pairs)
{
    for (size_t k = 1; k < pairs.size(); k++)
        if (pairs[k] == pairs[k - 1]) return &pairs[k];
    return nullptr;
}

// What is wrong with the counts of all ranks (empty: nothing): `local` is
// this rank's (created, broken, intact, lost), `created` the words for the
// first. Collective, so every rank calls it whatever else it found.
inline std::string unbalancedCounts(const std::array<long long, 4> &local, const char *created, MPI_Comm world)
{
    std::array<long long, 4> sums = {};
    MPI_Allreduce(local.data(), sums.data(), 4, MPI_LONG_LONG, MPI_SUM, world);
    if (sums[0] == sums[1] + sums[2] + sums[3]) return std::string();
    return std::to_string(sums[0]) + " " + created + ", " + std::to_string(sums[1]) + " broken, " +
           std::to_string(sums[2]) + " intact, " + std::to_string(sums[3]) + " lost";
}

// What is wrong with the bonds of `store` on this rank (empty: nothing).
// `tag` are the ids of the rank's atoms (local, then ghost). Collective.
template <class Tag>
std::string checkStoredBonds(const GbBondStore *store, const Tag *tag, int nlocal, MPI_Comm world)
{
    std::string wrong;
    const size_t n = granbond_bond_store_len(store);
    std::vector<double> mine;
    for (size_t k = 0; k < n && wrong.empty(); k++) {
        int32_t e[2];
        int64_t partner = 0;
        double state[GRANBOND_BOND_STATE_LEN];
        if (granbond_bond_store_bond(store, k, e, &partner, state) != GB_STATUS_OK)
            wrong = "bond " + std::to_string(k) + ": " + coreReason();
        else if (e[0] < 0 || e[0] >= nlocal || e[1] < 0 || static_cast<int64_t>(tag[e[1]]) != partner)
            wrong = "bond " + std::to_string(k) + " does not join its owner and its partner " + std::to_string(partner);
        else {
            const double a = static_cast<double>(tag[e[0]]), b = static_cast<double>(partner);
            mine.push_back(std::min(a, b));
            mine.push_back(std::max(a, b));
        }
    }
    // every bond once: the pairs of all ranks, gathered
    const std::vector<std::pair<double, double>> pairs = gatheredPairs(mine, world);
    const std::pair<double, double> *twice = repeatedPair(pairs);
    if (wrong.empty() && twice)
        wrong = "the bond of atoms " + std::to_string(static_cast<long long>(twice->first)) + " and " +
                std::to_string(static_cast<long long>(twice->second)) + " is stored twice";
    GbStoreCounts c = {};
    granbond_bond_store_counts(store, &c);
    const std::string counts = unbalancedCounts({c.created, brokenCount(c), c.intact, lostCount(c)}, "bonds created", world);
    return wrong.empty() ? counts : wrong;
}

// The same for the wall bonds of `store` on this rank: each held by the
// rank owning its sphere (one of the `nlocal` local atoms, ids `tag`),
// each (sphere, wall) held once over all ranks, created + restored =
// broken + intact + lost over all ranks, where `restored` are the intact
// bonds this rank's store took from a restart file (their counts stayed
// with the file's totals). Collective.
template <class Tag>
std::string checkWallBonds(const GbWallStore *store, long long restored, const Tag *tag, int nlocal, MPI_Comm world)
{
    std::string wrong;
    const size_t n = granbond_wall_store_len(store);
    std::vector<int64_t> ids(n);
    std::vector<uint32_t> walls(n);
    size_t written = 0;
    if (granbond_wall_store_keys(store, ids.data(), walls.data(), n, &written) != GB_STATUS_OK)
        wrong = "listing the wall bonds: " + coreReason();
    std::vector<int64_t> local(tag, tag + nlocal);
    std::sort(local.begin(), local.end());
    std::vector<double> mine;
    for (size_t k = 0; k < written && wrong.empty(); k++) {
        if (!std::binary_search(local.begin(), local.end(), ids[k]))
            wrong = "the bond of sphere " + std::to_string(static_cast<long long>(ids[k])) + " and wall " +
                    std::to_string(walls[k]) + " is held by a rank without the sphere";
        mine.push_back(static_cast<double>(ids[k]));
        mine.push_back(static_cast<double>(walls[k]));
    }
    const std::vector<std::pair<double, double>> keys = gatheredPairs(mine, world);
    const std::pair<double, double> *twice = repeatedPair(keys);
    if (wrong.empty() && twice)
        wrong = "the bond of sphere " + std::to_string(static_cast<long long>(twice->first)) + " and wall " +
                std::to_string(static_cast<long long>(twice->second)) + " is held twice";
    GbStoreCounts c = {};
    granbond_wall_store_counts(store, &c);
    const std::string counts = unbalancedCounts({c.created + restored, brokenCount(c), c.intact, lostCount(c)},
                                                "wall bonds created or restored", world);
    return wrong.empty() ? counts : wrong;
}

}

#endif
