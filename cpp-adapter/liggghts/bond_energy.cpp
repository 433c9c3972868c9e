// compute ID all granbond/energy
//
// Global vector of 4 (J), summed over the ranks: the energy the pair bonds
// store now, the energy they dissipated by damping and by hysteresis, and
// the energy breaks released (what the broken bonds stored), since the
// budget was first kept. The bonds keep the budget from a run's start while
// such a compute exists; it costs nothing without one. Kinetic energy plus
// these four is constant in free flight (docs/reference/compute_granbond_energy.md).
#include "bond_energy.h"
#include "bond_book.h"
#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"

#include "compute.h"

#include <string>

namespace granbond {
namespace liggghts {

namespace {

using LAMMPS_NS::LAMMPS;

class ComputeGranbondEnergy : public LAMMPS_NS::Compute {
public:
    ComputeGranbondEnergy(LAMMPS *lmp, int &iarg, int narg, char **arg) : Compute(lmp, iarg, narg, arg)
    {
        if (iarg < narg)
            endRun(error, FLERR, std::string("compute granbond/energy: unknown keyword '") + arg[iarg] +
                                     "' (it takes none)");
        // the sums are over all bonds: a group would promise less
        if (igroup != 0)
            endRun(error, FLERR, "compute granbond/energy sums over all bonds: use the group all");
        vector_flag = 1;
        size_vector = BondNonlinearCohesion::kEnergyTerms;
        extvector = 1;
        vector = values_;
        for (int k = 0; k < size_vector; k++) values_[k] = 0.0;
    }
    ~ComputeGranbondEnergy() { use_.follow(lmp, 0); }

    // before the run's setup pass, where the bonds start keeping the budget
    void init() { use_.follow(lmp, bonds()); }

    void compute_vector()
    {
        invoked_vector = update->ntimestep;
        BondNonlinearCohesion *model = bonds();
        if (model->bondStore() && !model->storeCurrent())
            endRun(error, FLERR, "compute granbond/energy: cohesion bond/nonlinear has no force pass at step " +
                                     std::to_string(static_cast<long long>(update->ntimestep)) +
                                     " for the present atoms (use it in a run's output, not between runs)");
        double local[BondNonlinearCohesion::kEnergyTerms];
        model->energyTerms(local);
        MPI_Allreduce(local, values_, BondNonlinearCohesion::kEnergyTerms, MPI_DOUBLE, MPI_SUM, world);
    }

private:
    BondNonlinearCohesion *bonds() { return use_.need(lmp, "compute granbond/energy"); }

    // the model keeps the budget only while a compute follows it
    PairBondsUse use_{&BondNonlinearCohesion::energyUsers};
    double values_[BondNonlinearCohesion::kEnergyTerms];
};

}

LAMMPS_NS::Compute *createGranbondEnergy(LAMMPS *lmp, int iarg, int narg, char **arg)
{
    return new ComputeGranbondEnergy(lmp, iarg, narg, arg);
}

}
}
