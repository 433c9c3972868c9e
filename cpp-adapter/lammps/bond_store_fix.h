// fix granbond/bonds: the home of pair granbond's bonds in LAMMPS. It holds
// the core's bond store of this rank (docs/development.md, "Where a bond
// lives: the bond store") and hands it the engine's per-atom events, so a
// bond moves with the atom that owns it: arrays grown, atoms copied (sort,
// deletion, migration), created, packed for another rank or a restart file
// and unpacked there. It also carries the store's three communications:
// each atom's seen id to its ghost images (border), each atom's view row to
// them (forward), and the loads of bonds on ghost atoms back to their
// owners where the engine does not (reverse, newton off).
//
// The pair style makes it (or takes the one read_restart brought back) and
// is its only user; bond_style granbond has one of its own (`fix ID all
// granbond/bonds topology`), whose bonds the topology names. Translation
// only: every rule is the core's.
#ifndef GRANBOND_LAMMPS_BOND_STORE_FIX_H
#define GRANBOND_LAMMPS_BOND_STORE_FIX_H

#include "atom.h"
#include "fix.h"
#include "granbond.h"

#include <string>
#include <vector>

namespace granbond {
namespace lammps {

// The fix's ID and style name, as pair granbond (or, `topology`, bond_style
// granbond) creates it.
inline const char *bondsFixId(bool topology = false)
{
    return topology ? "GRANBOND_TOPOLOGY_BONDS" : "GRANBOND_BONDS";
}
inline const char *bondsFixStyle() { return "granbond/bonds"; }

class FixGranbondBonds : public LAMMPS_NS::Fix {
public:
    FixGranbondBonds(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
    ~FixGranbondBonds() override;

    int setmask() override { return LAMMPS_NS::FixConst::PRE_EXCHANGE; }
    // A run under another pair style: the bonds wait, and the deck is told.
    void init() override;
    void pre_exchange() override { sizeExchange(); }
    void setup_pre_exchange() override { sizeExchange(); }

    void grow_arrays(int nmax) override;
    void copy_arrays(int i, int j, int) override;
    void set_arrays(int i) override;
    int pack_exchange(int i, double *buf) override;
    int unpack_exchange(int nlocal, double *buf) override;
    int pack_restart(int i, double *buf) override;
    void unpack_restart(int nlocal, int nth) override;
    int size_restart(int i) override;
    int maxsize_restart() override;
    int pack_border(int n, int *list, double *buf) override;
    int unpack_border(int n, int first, double *buf) override;
    int pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc) override;
    void unpack_forward_comm(int n, int first, double *buf) override;
    int pack_reverse_comm(int n, int first, double *buf) override;
    void unpack_reverse_comm(int n, int *list, double *buf) override;
    void write_restart(FILE *fp) override;
    void restart(char *buf) override;
    double memory_usage() override;

    GbBondStore *store() const { return store_; }

    // The view: every atom's row to its ghost images, then asked by the
    // pair (granbond_bond_store_bonded). Collective.
    void sendView();
    // The loads the pass put on ghost atoms (ghostLoads(), 6 doubles a
    // ghost: force then torque) added to their owners, and cleared.
    // Collective; for newton off, where the engine leaves ghost forces.
    void returnGhostLoads();
    double *ghostLoads();
    // Counts of this rank; a restart file brings back the sums on rank 0.
    GbStoreCounts counts() const;
    // The room one atom's bonds take in exchange and restart buffers, over
    // all ranks, after bonds formed. Collective.
    void sizeExchange();

private:
    void fail(const char *what);

    // doubles of one page of a view row in a forward communication
    static const int kViewPage = 8;

    GbBondStore *store_;
    bool topology_;             // the bonds of bond_style granbond
    std::vector<double> ghostLoads_;
    std::vector<double> row_;   // one atom's whole view row, while paged
    int viewWidth_;             // doubles the widest view row takes, this exchange
    int page_;                  // the page in flight
};

// The ids of a rank's atoms (local, then ghost) as the core reads them.
GbAtomIds atomIdsOf(const LAMMPS_NS::Atom *atom);

// The per-atom arrays of a rank's atoms (local, then ghost) as the core reads them.
GbAtomArrays atomArraysOf(const LAMMPS_NS::Atom *atom);

// Ends the run on this rank with `message`, written to the screen and the
// log first (error->one aborts without flushing them).
[[noreturn]] void endRun(LAMMPS_NS::LAMMPS *lmp, const std::string &message);

// The input command LAMMPS carries out now ("run", "write_data", ...).
std::string currentCommand(LAMMPS_NS::LAMMPS *lmp);

// Registers the style with LAMMPS (once) and returns the fix pair granbond
// (or, `topology`, bond_style granbond) uses: the existing one (from
// read_restart, or an earlier run), or a new one.
FixGranbondBonds *bondsFix(LAMMPS_NS::LAMMPS *lmp, bool topology = false);

}
}

#endif
