// bond_style granbond: the granbond core's bond laws (bond/nonlinear, and
// every later bond law) for the bonds of LAMMPS's topology: create_bonds, a
// data file's Bonds section, molecule templates. The topology says which
// pairs are bonded; each bond's state lives in the core's bond store behind
// its own fix granbond/bonds (bond_store_fix.h), keyed by atom ids and
// stepped by the core's pass, as pair granbond's bonds are
// (docs/development.md, "Topology bonds: the same store"). A bond that
// breaks leaves the topology (bond_topology.cpp), and its pair meets the
// pair style as a contact.
//
//   bond_style granbond
//   bond_coeff N <bond/nonlinear keywords of pair_coeff, no create_*>
#ifndef GRANBOND_LAMMPS_BOND_GRANBOND_H
#define GRANBOND_LAMMPS_BOND_GRANBOND_H

#include "bond.h"
#include "bond_source.h"
#include "break_log.h"
#include "granbond.h"

#include <string>
#include <vector>

namespace granbond {
namespace lammps {
class FixGranbondBonds;

class BondGranbond : public LAMMPS_NS::Bond, public BondSource {
public:
    explicit BondGranbond(LAMMPS_NS::LAMMPS *lmp);
    ~BondGranbond() override;

    void compute(int eflag, int vflag) override;
    void settings(int narg, char **arg) override;
    void coeff(int narg, char **arg) override;
    void init_style() override;
    double equilibrium_distance(int type) override;
    void write_restart(FILE *fp) override;
    void read_restart(FILE *fp) override;
    double single(int type, double rsq, int i, int j, double &fforce) override;
    double memory_usage() override;

    // What the outputs read (bond_source.h); a bond's kind is its type.
    GbBondStore *bondStore() const override;
    const GbBondModel *bondModel(size_t kind) const override
    {
        return kind < models_.size() ? models_[kind] : nullptr;
    }
    size_t bondKind(int i, int j, size_t k) const override;
    bool storeCurrent() const override;
    const std::vector<GbBondOutput> &bondOutputs() const override { return outputs_; }
    std::vector<BreakEvent> &breakEvents() override { return breaks_; }
    const GbBondModel *const *bondModels() const override { return models_.data(); }
    size_t bondKinds() const override { return models_.size(); }
    GbAtomArrays atomArrays() const override;
    // The store's counts summed over ranks: created, broken, intact, broken
    // by distance, tension, compression, shear, lost. Collective.
    void counts(double *values) const;

private:
    void allocate();
    void checkSettings();
    void linkTopology();
    void stepBonds(bool advance);
    // bond_topology.cpp: the bonds broken on any rank leave the topology
    // of every rank (bond lists, special lists, the neighbour lists'
    // special bits, the bond count). Collective.
    void dropBroken(const std::vector<LAMMPS_NS::tagint> &pairs);
    void takeBroken(bool advance);
    [[noreturn]] void failBond(int i, int j, const std::string &what);

    std::vector<GbBondParams> params_;      // per bond type
    std::vector<GbBondModel *> models_;     // per bond type (kind), null where unset
    std::vector<GbBondOutput> outputs_;
    std::vector<BreakEvent> breaks_;
    FixGranbondBonds *bonds_ = nullptr;
    double *ghostLoads_ = nullptr;
    std::string message_;
    LAMMPS_NS::bigint passStep_ = -1, passAtoms_ = -1;
    bool clearsSpecial_ = false;            // bonded pairs' contacts off (special lj 0): the bit goes at a break
};

}
}

#endif
