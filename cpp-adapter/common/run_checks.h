// The checks both adapters run at every `run` (and when the atom count
// changes): the core judges the time step and the bond's creation rules;
// this header only gathers what the core needs from the engine's atoms and
// keeps each warning from being printed twice.
#ifndef GRANBOND_RUN_CHECKS_H
#define GRANBOND_RUN_CHECKS_H

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

}

#endif
