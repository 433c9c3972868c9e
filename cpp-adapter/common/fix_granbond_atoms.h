// Which atoms the bond models have seen: per atom, its ID when a pass last
// saw it, 0 for an atom created since. Both engines keep a pair's history
// under the partner's atom ID and hand the ID of a deleted atom out again,
// so a record that names an atom never seen belongs to the atom that held
// the ID before, never to the new one (forgetRecordsOfNewborn). A value
// other than 0 and the atom's ID means the atoms were renumbered
// (countRenumbered).
//
// The values migrate, restart and reach the ghost atoms (border
// communication, so at every neighbour-list build) with their atoms;
// created atoms start at 0 (set_arrays). One class for both engines: it
// uses only the Fix interface LIGGGHTS 3.8 and LAMMPS (2021, 2025) share.
#ifndef GRANBOND_FIX_GRANBOND_ATOMS_H
#define GRANBOND_FIX_GRANBOND_ATOMS_H

#include "atom.h"
#include "comm.h"
#include "fix.h"
#include "memory.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace granbond {

// The fix's ID and style name, as the adapters create it.
inline const char *atomsFixId() { return "GRANBOND_ATOMS"; }
inline const char *atomsFixStyle() { return "granbond/atoms"; }

class FixGranbondAtoms : public LAMMPS_NS::Fix {
public:
    FixGranbondAtoms(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) :
        LAMMPS_NS::Fix(lmp, narg, arg), seen(nullptr), nmax_(0), restored_(false), primed_(false)
    {
        restart_global = 1;
        restart_peratom = 1;
        create_attribute = 1;
        comm_border = 1;
        grow_arrays(atom->nmax);
        // the engines' callback kinds: 0 grow, 1 restart, 2 border
        atom->add_callback(0);
        atom->add_callback(1);
        atom->add_callback(2);
    }

    ~FixGranbondAtoms()
    {
        atom->delete_callback(id, 0);
        atom->delete_callback(id, 1);
        atom->delete_callback(id, 2);
        memory->destroy(seen);
    }

    int setmask() { return 0; }

    // Whether a record naming a never-seen atom is stale. Not in the first
    // pass of a fix that did not come from a restart file: its atoms and
    // their records predate it (a restart file of a build without this fix,
    // or a new system, which has no records).
    bool judgesRecords() const { return restored_ || primed_; }
    // After the pass has marked its atoms seen.
    void primed() { primed_ = true; }

    void grow_arrays(int nmax)
    {
        memory->grow(seen, nmax, "granbond/atoms:seen");
        for (int i = nmax_; i < nmax; i++) seen[i] = 0.0;
        nmax_ = nmax;
    }
    void copy_arrays(int i, int j, int) { seen[j] = seen[i]; }
    void set_arrays(int i) { seen[i] = 0.0; }

    int pack_exchange(int i, double *buf)
    {
        buf[0] = seen[i];
        return 1;
    }
    int unpack_exchange(int nlocal, double *buf)
    {
        seen[nlocal] = buf[0];
        return 1;
    }

    int pack_border(int n, int *list, double *buf)
    {
        for (int k = 0; k < n; k++) buf[k] = seen[list[k]];
        return n;
    }
    int unpack_border(int n, int first, double *buf)
    {
        for (int k = 0; k < n; k++) seen[first + k] = buf[k];
        return n;
    }

    // Global restart: a marker that the per-atom values are there, and what
    // an engine's subclass keeps (globalState).
    void write_restart(FILE *fp)
    {
        double values[2 + kMaxGlobal];
        const int extra = globalState(values + 2);   // collective
        if (comm->me != 0) return;
        values[0] = kMarker;
        values[1] = extra;
        const int size = static_cast<int>((2 + extra) * sizeof(double));
        fwrite(&size, sizeof(int), 1, fp);
        fwrite(values, sizeof(double), 2 + extra, fp);
    }
    void restart(char *buf)
    {
        double head[2];
        std::memcpy(head, buf, sizeof head);
        restored_ = head[0] == kMarker;
        const int extra = restored_ ? static_cast<int>(head[1]) : 0;
        if (extra < 1 || extra > kMaxGlobal) return;
        double values[kMaxGlobal];
        std::memcpy(values, buf + sizeof head, extra * sizeof(double));
        restoreGlobalState(values, extra);
    }

    int pack_restart(int i, double *buf)
    {
        buf[0] = 3;   // the engines' convention: the count, itself included
        buf[1] = kMarker;
        buf[2] = seen[i];
        return 3;
    }
    void unpack_restart(int nlocal, int nth)
    {
        double **extra = atom->extra;
        int m = 0;
        for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
        // a row of another layout reads as not seen
        seen[nlocal] = extra[nlocal][m] == 3 && extra[nlocal][m + 1] == kMarker ? extra[nlocal][m + 2] : 0.0;
    }
    int size_restart(int) { return 3; }
    int maxsize_restart() { return 3; }

    double memory_usage() { return static_cast<double>(nmax_) * sizeof(double); }

    double *seen;

protected:
    static const int kMaxGlobal = 16;
    // Global values a subclass keeps in restart files: writes at most
    // kMaxGlobal to `values` (the same on every rank) and returns how many.
    // Called on every rank.
    virtual int globalState(double *) { return 0; }
    virtual void restoreGlobalState(const double *, int) {}

private:
    static constexpr double kMarker = 1.5e6 + 0.25;   // "granbond atoms" rows and restart data
    int nmax_;
    bool restored_;
    bool primed_;
};

// Of the atoms of a pass (owned and ghost), whether any was never seen.
inline bool anyNewborn(const double *seen, int nall)
{
    for (int i = 0; i < nall; i++)
        if (seen[i] == 0.0) return true;
    return false;
}

// At the first pass after a neighbour-list build (and a run's setup pass),
// before any bond forms: a pair's record that names an atom never seen is
// the record of the atom that held the ID before (an atom is seen in every
// such pass from its first on, and no bond forms before it). It is
// forgotten, contact history included, and its flag cleared; its bond was
// counted as vanished when that atom went. Then the owned atoms are marked
// seen under their current IDs. The list is the engine's half list with
// one record of `recordSize` doubles and one flag per neighbour.
template <class Tag>
void forgetRecordsOfNewborn(FixGranbondAtoms &atoms, int nlocal, int nghost, const Tag *tag, int inum,
                            const int *ilist, const int *numneigh, int *const *firstneigh, int *const *firstflag,
                            double *const *firstrecord, int recordSize)
{
    double *seen = atoms.seen;
    if (atoms.judgesRecords() && anyNewborn(seen, nlocal + nghost)) {
        for (int ii = 0; ii < inum; ii++) {
            const int i = ilist[ii];
            const int *jlist = firstneigh[i];
            int *flags = firstflag[i];
            double *records = firstrecord[i];
            for (int jj = 0; jj < numneigh[i]; jj++) {
                const int j = jlist[jj] & NEIGHMASK;
                if (!flags[jj] || (seen[i] != 0.0 && seen[j] != 0.0)) continue;
                flags[jj] = 0;
                std::fill_n(records + static_cast<size_t>(recordSize) * jj, recordSize, 0.0);
            }
        }
    }
    for (int i = 0; i < nlocal; i++) seen[i] = static_cast<double>(tag[i]);
    atoms.primed();
}

}

#endif
