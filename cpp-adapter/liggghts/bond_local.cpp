#include "bond_local.h"
#include "core_message.h"
#include "bond_book.h"
#include "bond_columns.h"
#include "local_rows.h"
#include "bond_nonlinear_cohesion.h"
#include "core_bridge.h"
#include "run_checks.h"

#include "compute.h"
#include "domain.h"
#include "pair_gran.h"

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

namespace {

using LAMMPS_NS::LAMMPS;

class ComputePairGranLocalBond : public LAMMPS_NS::Compute {
public:
    ComputePairGranLocalBond(LAMMPS *lmp, int &iarg, int narg, char **arg) :
        Compute(lmp, iarg, narg, arg), inl_(narg == iarg)
    {
        // Without keywords, LIGGGHTS-INL's layout: both centres, both ids
        // and the periodic flag (inlHead), then the core's columns: the
        // loads, then the bond's state where INL has the pair's history
        // (which held its bond).
        const std::string wrong = columns_.parse(narg - iarg, arg + iarg, inl_);
        if (!wrong.empty()) endRun(error, FLERR, "compute pair/gran/local/bond: " + wrong);
        iarg = narg;
        local_flag = 1;
        size_local_rows = 0;
        size_local_cols = columns_.size() == 1 ? 0 : static_cast<int>(columns_.size());
        if (inl_) inlWidth();
    }
    ~ComputePairGranLocalBond()
    {
        use_.follow(lmp, 0);
        energyUse_.follow(lmp, 0);
    }

    void init()
    {
        use_.follow(lmp, bonds());
        if (columns_.wantsEnergy()) energyUse_.follow(lmp, bonds());
    }

    void compute_local()
    {
        invoked_local = update->ntimestep;
        BondNonlinearCohesion *model = bonds();
        GbBondStore *store = model->bondStore();
        if (store && !model->storeCurrent())
            endRun(error, FLERR, "compute pair/gran/local/bond: cohesion bond/nonlinear has no force pass at step " +
                                     std::to_string(static_cast<long long>(update->ntimestep)) +
                                     " for the present atoms (use it in a run's output, not between runs)");
        rows_.values.clear();
        const size_t n = store ? granbond_bond_store_len(store) : 0;
        const int *mask = atom->mask;
        const size_t head = inl_ ? kInlHead : 0;
        std::vector<double> row(head + columns_.size());
        // the record the core's fields read: the state, then the loads of
        // the latest force pass
        double record[GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN];
        const std::vector<GbBondOutput> &outs = model->bondOutputs();
        const bool energies = store && columns_.wantsEnergy();
        std::vector<double> energy(granbond_bond_energy_field_count(), 0.0);
        for (size_t k = 0; k < n; k++) {
            int32_t ends[2];
            int64_t partner = 0;
            if (granbond_bond_store_bond(store, k, ends, &partner, record) != GB_STATUS_OK)
                endRunOnThisRank(lmp, FLERR, "compute pair/gran/local/bond: " + coreReason());
            const int i = ends[0], j = ends[1];
            if (!(mask[i] & groupbit) || !(mask[j] & groupbit)) continue;
            GbBondOutput none;
            std::memset(&none, 0, sizeof none);
            const GbBondOutput &o = k < outs.size() ? outs[k] : none;
            const GbBondModel *m = model->model(atom->type[i], atom->type[j]);
            if (inl_) inlHead(i, j, row.data());
            if (energies) model->bondEnergy(k, energy.data());
            if (!m || granbond_bond_output_store(&o, record + GRANBOND_BOND_STATE_LEN) != GB_STATUS_OK ||
                columns_.row(m, record, static_cast<double>(atom->tag[i]), static_cast<double>(atom->tag[j]),
                             atom->x[i], atom->x[j], row.data() + head, energy.data()) != GB_STATUS_OK)
                endRunOnThisRank(lmp, FLERR,
                                 "compute pair/gran/local/bond: atoms " +
                                     std::to_string(static_cast<long long>(atom->tag[i])) + " and " +
                                     std::to_string(static_cast<long long>(atom->tag[j])) + ": " +
                                     (m ? coreReason() : std::string("no bond model for their types")));
            rows_.values.insert(rows_.values.end(), row.begin(), row.end());
        }
        rows_.publish(size_local_cols, size_local_rows, vector_local, array_local);
    }

    double memory_usage() { return rows_.bytes(); }

private:
    // LIGGGHTS-INL's first 9 columns: both centres (in the box), both ids,
    // 1 if either atom is a periodic image.
    static const size_t kInlHead = 9;
    void inlWidth() { size_local_cols = static_cast<int>(kInlHead + columns_.size()); }
    void inlHead(int i, int j, double *row)
    {
        double xi[3] = {atom->x[i][0], atom->x[i][1], atom->x[i][2]};
        double xj[3] = {atom->x[j][0], atom->x[j][1], atom->x[j][2]};
        domain->remap(xi);
        domain->remap(xj);
        std::copy(xi, xi + 3, row);
        std::copy(xj, xj + 3, row + 3);
        row[6] = static_cast<double>(atom->tag[i]);
        row[7] = static_cast<double>(atom->tag[j]);
        const int nlocal = atom->nlocal;
        row[8] = (i < nlocal && j < nlocal) ? 0.0 : (domain->is_periodic_ghost(i) || domain->is_periodic_ghost(j)) ? 1.0 : 0.0;
    }

    BondNonlinearCohesion *bonds() { return use_.need(lmp, "compute pair/gran/local/bond"); }

    // the model keeps its bonds' outputs only while a compute follows it,
    // and each bond's energies only while one asks for them
    PairBondsUse use_{&BondNonlinearCohesion::bondOutputUsers};
    PairBondsUse energyUse_{&BondNonlinearCohesion::energyOutputUsers};
    const bool inl_;   // no keywords: LIGGGHTS-INL's layout
    BondColumns columns_;
    LocalRows rows_;
};

}

LAMMPS_NS::Compute *createPairGranLocalBond(LAMMPS *lmp, int iarg, int narg, char **arg)
{
    return new ComputePairGranLocalBond(lmp, iarg, narg, arg);
}

}
}
