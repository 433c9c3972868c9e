// What both adapters count and warn about for the bonds of a store: the
// core composes the row and the words (granbond_store_counts_row,
// granbond_ledger_notice); this sums this rank's numbers over the ranks.
// The break log's events are break_log.h's.
#ifndef GRANBOND_BOND_LEDGER_H
#define GRANBOND_BOND_LEDGER_H

#include "core_message.h"
#include "granbond.h"

#include <mpi.h>

#include <string>

namespace granbond {

// The warning the core composes as `notice` (GRANBOND_NOTICE_*) from this
// rank's `mine` summed over the ranks at `step`, `name` where the notice
// names a wall fix or a style; empty when no bond is concerned. Collective.
inline std::string ledgerNotice(int32_t notice, const int64_t mine[4], long long step, const char *name,
                                MPI_Comm world)
{
    int64_t all[4];
    MPI_Allreduce(mine, all, 4, MPI_INT64_T, MPI_SUM, world);
    GbCheckReport report;
    if (granbond_ledger_notice(notice, all, step, name, &report) != GB_STATUS_OK)
        return "the bonds' ledger: " + coreReason();
    return report.level > 0 ? std::string(report.message) : std::string();
}

// The warning of the bonds a link of a pair style's store lost, with their
// causes (collective).
inline std::string linkLosses(int32_t notice, const GbLinkReport &report, long long step, MPI_Comm world)
{
    const int64_t mine[4] = {report.owner_gone, report.partner_unreached, report.id_reused, report.no_model};
    return ledgerNotice(notice, mine, step, nullptr, world);
}

}

#endif
