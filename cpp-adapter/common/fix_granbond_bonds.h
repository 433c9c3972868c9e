// fix granbond/bonds: the home of the bonds in both engines. It holds the
// core's bond store of this rank (docs/development.md, "Where a bond lives:
// the bond store") and hands it the engine's per-atom events, so a bond
// moves with the atom that owns it: arrays grown, atoms copied (sort,
// deletion, migration), created, packed for another rank or a restart file
// and unpacked there. It also carries the store's three communications:
// each atom's seen id to its ghost images (border), each atom's view row to
// them (forward), and the loads of bonds on ghost atoms back to their
// owners where the engine does not (reverse, newton off); and the store's
// counts in restart files.
//
// One class for LIGGGHTS 3.8 and LAMMPS (2021, 2025), compiled with each
// engine's headers (fix_granbond_bonds.cpp); GRANBOND_ENGINE_LIGGGHTS names the
// few calls whose names or conventions differ. Each engine's bond style
// makes it and is its only user. Translation only: every rule is the core's.
#ifndef GRANBOND_FIX_GRANBOND_BONDS_H
#define GRANBOND_FIX_GRANBOND_BONDS_H

#include "atom.h"
#include "fix.h"
#include "granbond.h"

#include <cstdio>
#include <type_traits>
#include <vector>

namespace granbond {

// The fix's ID and style name, as the bond styles create it.
inline const char *bondsFixId() { return "GRANBOND_BONDS"; }
inline const char *bondsFixStyle() { return "granbond/bonds"; }

// The ids of a rank's atoms (local, then ghost) as the core reads them.
inline GbAtomIds atomIdsOf(const LAMMPS_NS::Atom *atom)
{
    typedef typename std::remove_pointer<decltype(atom->tag)>::type Tag;
    GbAtomIds ids;
    ids.narrow = sizeof(Tag) == 4 ? reinterpret_cast<const int32_t *>(atom->tag) : nullptr;
    ids.wide = sizeof(Tag) == 8 ? reinterpret_cast<const int64_t *>(atom->tag) : nullptr;
    ids.count = static_cast<size_t>(atom->nlocal + atom->nghost);
    return ids;
}

class BondStoreFix : public LAMMPS_NS::Fix {
public:
    BondStoreFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg);
    ~BondStoreFix();

    int setmask();
    void pre_exchange() { sizeExchange(); }
    void setup_pre_exchange() { sizeExchange(); }

    void grow_arrays(int nmax);
    void copy_arrays(int i, int j, int);
    void set_arrays(int i);
    int pack_exchange(int i, double *buf);
    int unpack_exchange(int nlocal, double *buf);
    int pack_restart(int i, double *buf);
    void unpack_restart(int nlocal, int nth);
    int size_restart(int i);
    int maxsize_restart();
    int pack_border(int n, int *list, double *buf);
    int unpack_border(int n, int first, double *buf);
    // the view rows: LIGGGHTS 3.8 names the forward communication
    // pack_comm/unpack_comm and counts its doubles per atom
#ifdef GRANBOND_ENGINE_LIGGGHTS
    int pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc);
    void unpack_comm(int n, int first, double *buf);
#else
    int pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc);
    void unpack_forward_comm(int n, int first, double *buf);
#endif
    int pack_reverse_comm(int n, int first, double *buf);
    void unpack_reverse_comm(int n, int *list, double *buf);
    void write_restart(FILE *fp);
    void restart(char *buf);
    double memory_usage();

    GbBondStore *store() const { return store_; }

    // The view: every atom's row to its ghost images, then asked by the
    // style (granbond_bond_store_bonded). Collective.
    void sendView();
    // Where any rank broke a bond in the pass so far (`brokeHere` on this
    // one), the view goes round again; returns whether it did. Collective.
    bool viewAfterBreaks(bool brokeHere);
    // The loads the pass put on ghost atoms (ghostLoads(), 6 doubles a
    // ghost: force then torque) added to their owners, and cleared.
    // Collective; for newton off, where the engine leaves ghost forces.
    void returnGhostLoads();
    double *ghostLoads();
    // The same buffer's 6 doubles a ghost added instead to the owners' rows
    // of a per-atom `table` (`width` doubles an atom, from `column`): the
    // atoms' shares of their bonds' damping loads. Collective.
    void returnGhostShares(double *table, int width, int column);
    // Counts of this rank; a restart file brings back the sums on rank 0.
    GbStoreCounts counts() const;
    // The room one atom's bonds take in exchange and restart buffers, over
    // all ranks, after bonds formed. Collective.
    void sizeExchange();
    // A pass's end, after the style stepped the bonds formed in it: the
    // broken bonds leave the store (and their outputs `kept`, if not null),
    // the ghosts' loads go home under newton off, and where any rank formed
    // a bond (`formedHere` on this one) the view goes round again and the
    // exchange room follows. Collective.
    void finishPass(bool formedHere, bool newtonOff, std::vector<GbBondOutput> *kept);

protected:
    void fail(const char *what);

private:
    // doubles of one page of a view row in a forward communication
    static const int kViewPage = 8;
    int packView(int n, const int *list, double *buf);
    void unpackView(int n, int first, const double *buf);

    GbBondStore *store_;
    std::vector<double> ghostLoads_;
    bool ghostsClear_ = false;   // every row of ghostLoads_ zero (the last pass's sent)
    double *sharesTable_ = nullptr;   // returnGhostShares' table while it runs
    int sharesWidth_ = 0, sharesColumn_ = 0;
    std::vector<double> row_;   // one atom's whole view row, while paged
    int viewWidth_;             // doubles the widest view row takes, this exchange
    int page_;                  // the page in flight
    int mostPacked_;            // doubles one atom's bonds take at most, over all ranks
};

}

#endif
