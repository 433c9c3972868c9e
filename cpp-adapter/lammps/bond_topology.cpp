// bond_style granbond: a bond that breaks leaves LAMMPS's topology as BPM's
// bonds do, so that thermo `bonds`, compute nbond/atom, compute bond/local,
// delete_bonds and write_data see only intact bonds, and the pair meets the
// pair style as a contact: its entry leaves both atoms' bond lists and their
// special lists, the neighbour lists forget that the pair is special, the
// engine's bond list stops naming it until it is built again, and the
// bond count drops. Engine bookkeeping only: the core decided the break.
#include "bond_granbond.h"
#include "bond_store_fix.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <map>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

// Takes the entry naming `other` out of local atom i's bond list.
void dropBondEntry(Atom *atom, int i, tagint other)
{
    int &n = atom->num_bond[i];
    for (int m = 0; m < n; m++)
        if (atom->bond_atom[i][m] == other) {
            atom->bond_atom[i][m] = atom->bond_atom[i][n - 1];
            atom->bond_type[i][m] = atom->bond_type[i][n - 1];
            n--;
            return;
        }
}

// Takes `other` out of local atom i's 1-2 special list (the 1-3 and 1-4
// lists are empty: their weights are 1).
void dropSpecial(Atom *atom, int i, tagint other)
{
    tagint *s = atom->special[i];
    int *ns = atom->nspecial[i];
    for (int m = 0; m < ns[0]; m++)
        if (s[m] == other) {
            for (int k = m; k < ns[0] - 1; k++) s[k] = s[k + 1];
            ns[0]--;
            ns[1] = ns[2] = ns[0];
            return;
        }
}

// The pairs of `partners` (per local atom, the ids it no longer bonds) are
// no special pairs in the neighbour lists now; each list read through its
// own atoms (a skip list holds only some).
void clearSpecialBits(Neighbor *neighbor, const tagint *tag, const std::map<int, std::vector<tagint>> &partners)
{
    for (int l = 0; l < neighbor->nlist; l++) {
        NeighList *list = neighbor->lists[l];
        if (!list || list->copy || !list->ilist) continue;
        for (int ii = 0; ii < list->inum; ii++) {
            const int i = list->ilist[ii];
            const auto found = partners.find(i);
            if (found == partners.end()) continue;
            int *jlist = list->firstneigh[i];
            for (int jj = 0; jj < list->numneigh[i]; jj++) {
                const int j = jlist[jj] & NEIGHMASK;
                for (tagint other : found->second)
                    if (tag[j] == other) jlist[jj] = j;
            }
        }
    }
}

}

void BondGranbond::dropBroken(const std::vector<tagint> &mine)
{
    // every rank learns every break: an atom's partner may live elsewhere
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(comm->nprocs), offsets(comm->nprocs + 1, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int r = 0; r < comm->nprocs; r++) offsets[r + 1] = offsets[r] + counts[r];
    if (offsets[comm->nprocs] == 0) return;
    std::vector<tagint> all(static_cast<size_t>(offsets[comm->nprocs]));
    MPI_Allgatherv(mine.data(), count, MPI_LMP_TAGINT, all.data(), counts.data(), offsets.data(), MPI_LMP_TAGINT,
                   world);
    const int nlocal = atom->nlocal;
    const tagint *tag = atom->tag;
    std::map<int, std::vector<tagint>> partners;
    for (size_t k = 0; k + 1 < all.size(); k += 2) {
        const tagint a = all[k], b = all[k + 1];
        const tagint ends[2] = {a, b};
        for (int side = 0; side < 2; side++) {
            const int i = atom->map(ends[side]);
            if (i < 0 || i >= nlocal) continue;
            const tagint other = ends[1 - side];
            dropBondEntry(atom, i, other);
            if (clearsSpecial_) {
                dropSpecial(atom, i, other);
                partners[i].push_back(other);
            }
        }
    }
    if (!partners.empty()) clearSpecialBits(neighbor, tag, partners);
    // the bond list names the bond until the next build: type 0 is skipped
    for (int n = 0; n < neighbor->nbondlist; n++) {
        int *e = neighbor->bondlist[n];
        const tagint ti = tag[e[0]], tj = tag[e[1]];
        for (size_t k = 0; k + 1 < all.size(); k += 2)
            if ((ti == all[k] && tj == all[k + 1]) || (ti == all[k + 1] && tj == all[k])) e[2] = 0;
    }
    atom->nbonds -= static_cast<bigint>(all.size() / 2);
    bonds_->sendView();
}

}
}
