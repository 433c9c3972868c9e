#ifdef GRANBOND_ENGINE_LIGGGHTS
#include "liggghts_engine.h"
#endif
#include "fix_granbond_bonds.h"
#include "core_message.h"
#include "vector_adds.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

#include <algorithm>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace granbond {

namespace {

// The engines' callback kinds: 0 grow, 1 restart, 2 border.
const int kGrow = 0, kRestart = 1, kBorder = 2;

}

BondStoreFix::BondStoreFix(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), store_(nullptr), viewWidth_(1), page_(0), mostPacked_(0)
{
    if (granbond_bond_store_new(&store_) != GB_STATUS_OK) fail("making the bond store");
    restart_global = 1;
    restart_peratom = 1;
    create_attribute = 1;
    comm_border = 1;
    comm_forward = kViewPage;
    comm_reverse = 6;
#ifndef GRANBOND_ENGINE_LIGGGHTS
    maxexchange_dynamic = 1;
#endif
    mostPacked_ = static_cast<int>(granbond_bond_store_most_packed_len(store_));
    grow_arrays(atom->nmax);
    atom->add_callback(kGrow);
    atom->add_callback(kRestart);
    atom->add_callback(kBorder);
}

BondStoreFix::~BondStoreFix()
{
    atom->delete_callback(id, kGrow);
    atom->delete_callback(id, kRestart);
    atom->delete_callback(id, kBorder);
    granbond_bond_store_free(store_);
}

int BondStoreFix::setmask() { return FixConst::PRE_EXCHANGE; }

void BondStoreFix::fail(const char *what)
{
    error->one(FLERR, (std::string("fix granbond/bonds: ") + what + ": " + coreReason()).c_str());
}

// The most doubles one atom's bonds take, over all ranks: the exchange and
// restart buffers' room per atom. Collective.
void BondStoreFix::sizeExchange()
{
    int mine = static_cast<int>(granbond_bond_store_most_packed_len(store_)), all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
    mostPacked_ = all;
#ifdef GRANBOND_ENGINE_LIGGGHTS
    // LIGGGHTS keeps one room for every fix's data, as its own fixes raise it
    comm->maxexchange_fix = std::max(comm->maxexchange_fix, all);
#else
    maxexchange = all;
#endif
}

void BondStoreFix::finishPass(bool formedHere, bool newtonOff, std::vector<GbBondOutput> *kept)
{
    if (granbond_bond_store_finish_pass(store_) != GB_STATUS_OK) fail("the pass");
    // in store order: the bonds that broke have left it
    if (kept)
        kept->erase(std::remove_if(kept->begin(), kept->end(),
                                   [](const GbBondOutput &o) { return o.status != GB_BOND_STATUS_INTACT; }),
                    kept->end());
    if (newtonOff) returnGhostLoads();
    int mine = formedHere, any = 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (!any) return;
    sendView();
    sizeExchange();
}

// The store's rows follow the atoms it is told of, not the engine's room
// (granbond_bond_store_grow): nothing to grow here.
void BondStoreFix::grow_arrays(int) {}

void BondStoreFix::copy_arrays(int i, int j, int)
{
    granbond_bond_store_copy(store_, static_cast<size_t>(i), static_cast<size_t>(j));
}

void BondStoreFix::set_arrays(int i) { granbond_bond_store_clear(store_, static_cast<size_t>(i)); }

int BondStoreFix::pack_exchange(int i, double *buf)
{
    size_t written = 0;
    const size_t room = granbond_bond_store_packed_len(store_, static_cast<size_t>(i));
    if (granbond_bond_store_pack(store_, static_cast<size_t>(i), 1, buf, room, &written) != GB_STATUS_OK)
        fail("packing an atom's bonds for another rank");
    return static_cast<int>(written);
}

int BondStoreFix::unpack_exchange(int nlocal, double *buf)
{
    // the head of the atom's bonds says their length (a negative count
    // has a third double); the core reads it and checks the rest
    size_t n = 0, read = 0;
    if (granbond_bond_store_packed_len_in(buf, buf[1] < 0.0 ? 3 : 2, &n) != GB_STATUS_OK ||
        granbond_bond_store_unpack(store_, static_cast<size_t>(nlocal), buf, n, &read) != GB_STATUS_OK)
        fail("unpacking the bonds of an atom from another rank");
    return static_cast<int>(read);
}

int BondStoreFix::pack_restart(int i, double *buf)
{
    size_t written = 0;
    const size_t room = granbond_bond_store_packed_len(store_, static_cast<size_t>(i));
    if (granbond_bond_store_pack(store_, static_cast<size_t>(i), 0, buf + 1, room, &written) != GB_STATUS_OK)
        fail("packing an atom's bonds for a restart file");
    buf[0] = static_cast<double>(written + 1);
    return static_cast<int>(written + 1);
}

void BondStoreFix::unpack_restart(int nlocal, int nth)
{
    double **extra = atom->extra;
    int m = 0;
    for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
    const size_t n = static_cast<size_t>(extra[nlocal][m]) - 1;
    size_t read = 0;
    if (granbond_bond_store_unpack(store_, static_cast<size_t>(nlocal), &extra[nlocal][m + 1], n, &read) !=
        GB_STATUS_OK)
        fail("reading an atom's bonds from the restart file");
}

int BondStoreFix::size_restart(int i)
{
    return static_cast<int>(granbond_bond_store_packed_len(store_, static_cast<size_t>(i)) + 1);
}

int BondStoreFix::maxsize_restart() { return mostPacked_ + 1; }

int BondStoreFix::pack_border(int n, int *list, double *buf)
{
    for (int k = 0; k < n; k++)
        buf[k] = static_cast<double>(granbond_bond_store_seen(store_, static_cast<size_t>(list[k])));
    return n;
}

int BondStoreFix::unpack_border(int n, int first, double *buf)
{
    for (int k = 0; k < n; k++)
        granbond_bond_store_set_seen(store_, static_cast<size_t>(first + k), static_cast<int64_t>(buf[k]));
    return n;
}

// The rows go in pages of kViewPage doubles (the count in the page, then
// partner ids), as many as the widest row needs: the engine sizes its
// forward buffers by comm_forward when a run starts, and bonds may form
// during it.
bool BondStoreFix::viewAfterBreaks(bool brokeHere)
{
    int mine = brokeHere, any = 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any) sendView();
    return any != 0;
}

void BondStoreFix::sendView()
{
    int mine = static_cast<int>(granbond_bond_store_view_width(store_)), all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
    viewWidth_ = all;
    row_.assign(static_cast<size_t>(all), 0.0);
    if (granbond_bond_store_clear_view(store_) != GB_STATUS_OK) fail("the view");
    const int perPage = kViewPage - 1;
    const int pages = std::max(1, (all - 1 + perPage - 1) / perPage);
    for (page_ = 0; page_ < pages; page_++) {
#if defined(GRANBOND_ENGINE_LIGGGHTS)
        comm->forward_comm_fix(this);
#elif defined(GRANBOND_LAMMPS_COMM_FIX_OVERLOAD)
        comm->forward_comm(this, kViewPage);
#else
        comm->forward_comm_fix(this, kViewPage);
#endif
    }
    if (granbond_bond_store_finish_view(store_) != GB_STATUS_OK) fail("the view");
}

int BondStoreFix::packView(int n, const int *list, double *buf)
{
    const size_t w = static_cast<size_t>(viewWidth_);
    const int perPage = kViewPage - 1;
    for (int k = 0; k < n; k++) {
        if (granbond_bond_store_pack_view(store_, static_cast<size_t>(list[k]), row_.data(), w) != GB_STATUS_OK)
            fail("packing the view");
        const int count = static_cast<int>(row_[0]);
        const int first = page_ * perPage, inPage = std::max(0, std::min(perPage, count - first));
        double *out = buf + static_cast<size_t>(k) * kViewPage;
        std::fill(out, out + kViewPage, 0.0);
        out[0] = inPage;
        std::copy(row_.begin() + 1 + first, row_.begin() + 1 + first + inPage, out + 1);
    }
    return n * kViewPage;
}

void BondStoreFix::unpackView(int n, int first, const double *buf)
{
    const GbAtomIds ids = atomIdsOf(atom);
    for (int k = 0; k < n; k++)
        if (granbond_bond_store_unpack_view(store_, static_cast<size_t>(first + k), buf + static_cast<size_t>(k) * kViewPage,
                                            kViewPage, &ids, static_cast<size_t>(atom->nlocal)) != GB_STATUS_OK)
            fail("unpacking the view");
}

#ifdef GRANBOND_ENGINE_LIGGGHTS
int BondStoreFix::pack_comm(int n, int *list, double *buf, int, int *)
{
    packView(n, list, buf);
    return kViewPage;   // LIGGGHTS: doubles per atom
}
void BondStoreFix::unpack_comm(int n, int first, double *buf) { unpackView(n, first, buf); }
#else
int BondStoreFix::pack_forward_comm(int n, int *list, double *buf, int, int *) { return packView(n, list, buf); }
void BondStoreFix::unpack_forward_comm(int n, int first, double *buf) { unpackView(n, first, buf); }
#endif

// The reverse communication reads every ghost's row once and clears it as
// it sends it, so a pass starts on cleared rows; a second sweep over all
// ghosts here would cost, per pass, about as much as the communication.
// Rows a pass left unsent are cleared here in full.
double *BondStoreFix::ghostLoads()
{
    const size_t n = 6 * static_cast<size_t>(atom->nghost);
    if (ghostLoads_.size() < n) ghostLoads_.resize(n);
    if (!ghostsClear_) std::fill(ghostLoads_.begin(), ghostLoads_.end(), 0.0);
    ghostsClear_ = false;
    return ghostLoads_.data();
}

void BondStoreFix::returnGhostLoads()
{
#if defined(GRANBOND_ENGINE_LIGGGHTS)
    comm->reverse_comm_fix(this);
#elif defined(GRANBOND_LAMMPS_COMM_FIX_OVERLOAD)
    comm->reverse_comm(this, 6);
#else
    comm->reverse_comm_fix(this, 6);
#endif
    ghostsClear_ = true;
}

void BondStoreFix::returnGhostShares(double *table, int width, int column)
{
    sharesTable_ = table;
    sharesWidth_ = width;
    sharesColumn_ = column;
    returnGhostLoads();
    sharesTable_ = nullptr;
}

int BondStoreFix::pack_reverse_comm(int n, int first, double *buf)
{
    const int nlocal = atom->nlocal;
    for (int k = 0; k < n; k++) {
        double *g = ghostLoads_.data() + 6 * static_cast<size_t>(first + k - nlocal);
        std::copy(g, g + 6, buf + 6 * k);
        std::fill(g, g + 6, 0.0);
    }
#ifdef GRANBOND_ENGINE_LIGGGHTS
    return 6;   // LIGGGHTS: doubles per atom
#else
    return 6 * n;
#endif
}

// Every ghost comes back each pass, most without a load: the returned
// shares have their own loop, and the forces and torques are the engine's
// contiguous rows of 3.
void BondStoreFix::unpack_reverse_comm(int n, int *list, double *buf)
{
    if (n <= 0) return;
    const int nlocal = atom->nlocal;
    double *const ghosts = ghostLoads_.data();
    if (sharesTable_) {
        for (int k = 0; k < n; k++) {
            const int i = list[k];
            double *row = i < nlocal ? sharesTable_ + static_cast<size_t>(i) * sharesWidth_ + sharesColumn_
                                     : ghosts + 6 * static_cast<size_t>(i - nlocal);
            for (int c = 0; c < 6; c++) row[c] += buf[6 * k + c];
        }
        return;
    }
    double *const f0 = atom->f[0], *const t0 = atom->torque[0];
    for (int k = 0; k < n; k++) {
        const int i = list[k];
        const double *b = buf + 6 * static_cast<size_t>(k);
        if (i < nlocal) {
            add3(f0 + 3 * static_cast<size_t>(i), b);
            add3(t0 + 3 * static_cast<size_t>(i), b + 3);
        } else {
            // a ghost that is an image of another ghost's atom on this rank
            double *g = ghosts + 6 * static_cast<size_t>(i - nlocal);
            add3(g, b);
            add3(g + 3, b + 3);
        }
    }
}

GbStoreCounts BondStoreFix::counts() const
{
    GbStoreCounts c;
    std::memset(&c, 0, sizeof c);
    granbond_bond_store_counts(store_, &c);
    return c;
}

// The counts and the energy sums summed over the ranks, and the layout of
// the bonds' state, in the core's record (granbond_store_record_write):
// the engines read the global part before the per-atom one, so a file
// whose bonds have another layout is refused before a bond is read.
void BondStoreFix::write_restart(FILE *fp)
{
    GbStoreCounts mine = counts(), all;
    MPI_Allreduce(&mine, &all, sizeof(GbStoreCounts) / sizeof(int64_t), MPI_INT64_T, MPI_SUM, world);
    GbEnergySums myEnergy, allEnergy;
    std::memset(&myEnergy, 0, sizeof myEnergy);
    granbond_bond_store_energy_sums(store_, &myEnergy);
    MPI_Allreduce(&myEnergy, &allEnergy, sizeof(GbEnergySums) / sizeof(double), MPI_DOUBLE, MPI_SUM, world);
    uint8_t record[GRANBOND_STORE_RECORD_LEN];
    if (granbond_store_record_write(&all, &allEnergy, record, sizeof record) != GB_STATUS_OK)
        error->all(FLERR, ("fix granbond/bonds: " + coreReason()).c_str());
    if (comm->me != 0) return;
    const int size = static_cast<int>(sizeof record);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(record, 1, sizeof record, fp);
}

void BondStoreFix::restart(char *buf)
{
    GbStoreCounts c;
    GbEnergySums e;
    if (granbond_store_record_read(reinterpret_cast<const uint8_t *>(buf), &c, &e) != GB_STATUS_OK)
        error->all(FLERR, ("fix granbond/bonds: " + coreReason()).c_str());
    if (comm->me != 0) return;
    granbond_bond_store_restore_counts(store_, &c);
    granbond_bond_store_restore_energy_sums(store_, &e);
}

double BondStoreFix::memory_usage()
{
    return static_cast<double>(granbond_bond_store_bytes(store_)) +
           static_cast<double>(ghostLoads_.capacity() * sizeof(double));
}

}
