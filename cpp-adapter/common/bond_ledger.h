// What both adapters count and warn about for the bonds of a store: the
// counts by outcome (created, broken by mode, intact, lost by cause), the
// row the LAMMPS styles' computes give, and the bonds a link lost with
// their causes in words. The break log's events are break_log.h's.
#ifndef GRANBOND_BOND_LEDGER_H
#define GRANBOND_BOND_LEDGER_H

#include "granbond.h"

#include <mpi.h>

#include <string>

namespace granbond {

inline long long brokenCount(const GbStoreCounts &c)
{
    return c.broken_distance + c.broken_tension + c.broken_compression + c.broken_shear;
}

inline long long lostCount(const GbStoreCounts &c)
{
    return c.lost_owner_gone + c.lost_partner_unreached + c.lost_id_reused + c.lost_no_model;
}

// The counts as the LAMMPS styles' computes give them: created, broken,
// intact, broken by distance, tension, compression and shear, lost.
inline void countsRow(const GbStoreCounts &c, double row[8])
{
    const long long values[8] = {c.created,           brokenCount(c),       c.intact,          c.broken_distance,
                                 c.broken_tension,    c.broken_compression, c.broken_shear,    lostCount(c)};
    for (int k = 0; k < 8; k++) row[k] = static_cast<double>(values[k]);
}

// Lost bonds' causes in words ("N because ...; ..."), each count with its
// cause, those of 0 left out.
inline std::string lostCauses(const long long all[4], const std::string why[4])
{
    std::string causes;
    for (int c = 0; c < 4; c++)
        if (all[c] > 0) causes += (causes.empty() ? "" : "; ") + std::to_string(all[c]) + " because " + why[c];
    return causes;
}

// The bonds a link of a pair style's store lost, summed over the ranks
// (collective): their number, and their causes in words in `causes` ("N
// because ...; ..."), `noModel` adding what takes a type pair's bond model
// away in this engine.
inline long long lostBonds(const GbLinkReport &report, MPI_Comm world, const std::string &noModel,
                           std::string &causes)
{
    const long long mine[4] = {report.owner_gone, report.partner_unreached, report.id_reused, report.no_model};
    long long all[4];
    MPI_Allreduce(mine, all, 4, MPI_LONG_LONG, MPI_SUM, world);
    const std::string why[4] = {
        "their atom left the system (deleted, or lost through a boundary)",
        "their partner was not among the atoms within the communication cutoff (deleted, lost, or moved "
        "farther than the bond's reach between runs)",
        "an atom's id was taken over by a new atom", "their atoms' types have no bond model any more" + noModel};
    causes = lostCauses(all, why);
    return all[0] + all[1] + all[2] + all[3];
}

}

#endif
