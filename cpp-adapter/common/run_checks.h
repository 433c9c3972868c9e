// The checks both adapters run at every `run` (and when the atom count
// changes): the core judges the time step, the bond's creation rules, the
// periodic box and renumbered ids, and words them; this header only
// gathers what the core needs from the engine's atoms and keeps each
// warning from being printed twice.
#ifndef GRANBOND_RUN_CHECKS_H
#define GRANBOND_RUN_CHECKS_H

#include "core_message.h"
#include "granbond.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace granbond {

// Smallest and largest radius and lightest mass of each atom type over all
// ranks (collective; index 0 unused, a type without atoms keeps infinite
// minima).
inline std::vector<GbTypeBodies> gatherTypeBodies(int ntypes, int nlocal, const int *type, const double *radius,
                                                  const double *rmass, MPI_Comm world)
{
    const double inf = std::numeric_limits<double>::infinity();
    // minima of radius, mass and -radius (the maximum), one MPI call
    std::vector<double> local(3 * (ntypes + 1), inf), all(3 * (ntypes + 1), inf);
    for (int i = 0; i < nlocal; i++) {
        const int t = type[i];
        if (t < 1 || t > ntypes) continue;
        local[3 * t] = std::min(local[3 * t], radius[i]);
        local[3 * t + 1] = std::min(local[3 * t + 1], rmass[i]);
        local[3 * t + 2] = std::min(local[3 * t + 2], -radius[i]);
    }
    MPI_Allreduce(local.data(), all.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_MIN, world);
    std::vector<GbTypeBodies> bodies(ntypes + 1);
    for (int t = 0; t <= ntypes; t++) {
        bodies[t].radius_min = all[3 * t];
        bodies[t].mass_min = all[3 * t + 1];
        bodies[t].radius_max = std::isinf(all[3 * t + 2]) ? 0.0 : -all[3 * t + 2];
    }
    return bodies;
}

// When a time-step report is printed: at a run's start, and within a run
// only when the atoms that arrived set a new limit.
class TimestepWarning {
public:
    bool due(const GbCheckReport &report, bool runStart)
    {
        const bool say = report.level > 0 && (runStart || report.critical != last_);
        last_ = report.critical;
        return say;
    }

private:
    double last_ = 0.0;
};

// Findings already printed, so that one repeated at every run is said
// once.
class SaidOnce {
public:
    // The lines of the report's message (one finding each) not printed yet.
    std::vector<std::string> fresh(const GbCheckReport &report)
    {
        std::vector<std::string> lines;
        const std::string all(report.message);
        for (size_t start = 0; start < all.size();) {
            size_t end = all.find('\n', start);
            if (end == std::string::npos) end = all.size();
            const std::string line = all.substr(start, end - start);
            if (said_.insert(line).second) lines.push_back(line);
            start = end + 1;
        }
        return lines;
    }

private:
    std::set<std::string> said_;
};

// Engines keep a pair's history under the partner's atom ID, so renumbered
// IDs (`delete_atoms ... compress yes`, its default) hand a bond's state to
// a pair that never bonded. `seen` is the per-atom value of
// FixGranbondAtoms: the ID an atom had when last seen (0: not seen yet).
// Returns how many atoms changed their ID, over all ranks (collective).
template <class Tag>
long long countRenumbered(int nlocal, const Tag *tag, const double *seen, MPI_Comm world)
{
    long long mine = 0, all = 0;
    for (int i = 0; i < nlocal; i++)
        if (seen[i] != 0.0 && seen[i] != static_cast<double>(tag[i])) mine++;
    MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
    return all;
}

// The error that ends a run after renumbering while bonds exist (the
// core's words).
inline std::string renumberedMessage(const char *style, long long renumbered)
{
    const int64_t counts[4] = {renumbered, 0, 0, 0};
    GbCheckReport report;
    if (granbond_ledger_notice(GRANBOND_NOTICE_RENUMBERED, counts, 0, style, &report) != GB_STATUS_OK)
        return std::string(style) + ": " + coreReason();
    return report.message;
}

// The core's check of a periodic direction too short for the engines'
// per-pair history (granbond_thin_periodic_box_check). `step` >= 0: the
// box changed during a run (fix deform) and is checked at that step.
// Returns the error naming the first such direction, or "".
inline std::string thinPeriodicBox(const char *style, int dimension, const int periodic[3], const double length[3],
                                   double listReach, double skin, long long step = -1)
{
    const int32_t flags[3] = {periodic[0], periodic[1], periodic[2]};
    GbCheckReport report;
    if (granbond_thin_periodic_box_check(style, dimension, flags, length, listReach, skin, step, &report) !=
        GB_STATUS_OK)
        return std::string(style) + ": " + coreReason();
    return report.message;
}

}

#endif
