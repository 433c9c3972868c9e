// bond_style granbond's commands and pass (bond_granbond.h): bond_coeff
// words to the core's table, the store linked from the engine's bond list
// after every list build, its chunks stepped and their loads added to the
// atoms. Every rule is the core's; this file finds the bonds in the
// engine's lists and adds the loads.
#include "bond_granbond.h"
#include "bond_ledger.h"
#include "bond_store_fix.h"
#include "core_message.h"
#include "restart_rows.h"
#include "atom_loads.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

std::string shortNumber(double v)
{
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return s;
}
}

BondGranbond::BondGranbond(LAMMPS *lmp) : Bond(lmp)
{
    // the coefficients are keywords of the core's table: write_data has
    // no place for them (the deck gives bond_coeff again after read_data)
    writedata = 0;
    const GbLayout expected = granbond_header_layout();
    if (granbond_check_layout(&expected) != GB_STATUS_OK)
        error->all(FLERR, "bond_style granbond: the adapter was built against another granbond.h than the core it "
                          "links: " + coreReason());
}

BondGranbond::~BondGranbond()
{
    for (GbBondModel *m : models_) granbond_bond_model_free(m);
    if (allocated) memory->destroy(setflag);
}

void BondGranbond::allocate()
{
    allocated = 1;
    const int n = atom->nbondtypes;
    memory->create(setflag, n + 1, "bond:setflag");
    for (int t = 0; t <= n; t++) setflag[t] = 0;
    params_.assign(static_cast<size_t>(n + 1), GbBondParams());
    models_.assign(static_cast<size_t>(n + 1), nullptr);
}

void BondGranbond::settings(int narg, char **arg)
{
    if (narg != 0)
        error->all(FLERR, std::string("bond_style granbond takes no arguments (got '") + arg[0] +
                              "'); each bond type's law is set with bond_coeff N <bond/nonlinear keywords>");
}

// bond_coeff N <keywords>: pair_coeff's bond/nonlinear words, from the same
// table and phrases, without the rows that say when bonds form.
void BondGranbond::coeff(int narg, char **arg)
{
    if (!allocated) allocate();
    if (narg < 1) error->all(FLERR, "bond_coeff: bond_style granbond expects N <bond/nonlinear keywords>");
    int lo, hi;
    utils::bounds(FLERR, arg[0], 1, atom->nbondtypes, lo, hi, error);
    // the core reads the words, and refuses those of bonds a pair style forms
    GbBondParams p;
    const std::string command = std::string("bond_coeff ") + arg[0];
    if (granbond_bond_coeff_read(command.c_str(), arg + 1, static_cast<size_t>(narg - 1), &p) != GB_STATUS_OK)
        error->all(FLERR, coreReason());
    for (int t = lo; t <= hi; t++) {
        granbond_bond_model_free(models_[t]);
        models_[t] = nullptr;
        if (granbond_bond_model_new(&p, &models_[t]) != GB_STATUS_OK)
            error->all(FLERR, "bond_coeff " + std::to_string(t) + ": " + coreReason());
        params_[t] = p;
        setflag[t] = 1;
    }
}

// What a deck must set for the topology and the pair style to work with
// these bonds, as BPM's bond styles ask.
void BondGranbond::checkSettings()
{
    if (!atom->radius_flag || !atom->omega_flag || !atom->torque_flag)
        error->all(FLERR, "bond_style granbond requires an atom style with radius, omega and torque (atom_style "
                          "bpm/sphere, or hybrid sphere bond)");
    if (comm->ghost_velocity == 0)
        error->all(FLERR, "bond_style granbond requires ghost atoms to store velocity (comm_modify vel yes)");
    if (atom->molecular == 2)
        error->all(FLERR, "bond_style granbond cannot be used with atom style template: a bond that breaks must "
                          "leave its atoms' own bond lists");
    if (force->angle || force->dihedral || force->improper)
        error->all(FLERR, "bond_style granbond cannot be used with angles, dihedrals or impropers: a bond that "
                          "breaks would leave them behind");
    const double *lj = force->special_lj, *coul = force->special_coul;
    if (lj[2] != 1.0 || lj[3] != 1.0 || coul[2] != 1.0 || coul[3] != 1.0)
        error->all(FLERR, "bond_style granbond requires 1-3 and 1-4 special weights of 1 (special_bonds lj 0 1 1 "
                          "coul 1 1 1, as BPM): spheres two bonds apart touch as any others do");
    if (lj[1] == 0.0 && coul[1] == 1.0)
        clearsSpecial_ = true;   // BPM's: bonded pairs listed, their contacts off
    else if (lj[1] == 1.0 && coul[1] == 1.0)
        clearsSpecial_ = false;  // the pair style acts under the bonds too
    else
        error->all(FLERR, "bond_style granbond: special_bonds lj " + shortNumber(lj[1]) + " coul " +
                              shortNumber(coul[1]) + " for bonded pairs: use lj 0 coul 1 (special_bonds lj 0 1 1 "
                              "coul 1 1 1, as BPM: bonded pairs stay in the neighbour list without contact, and "
                              "touch once their bond breaks) or lj 1 coul 1 (contacts act under the bonds too); "
                              "with coul 0 a pair whose bond breaks would never touch");
}

void BondGranbond::init_style()
{
    checkSettings();
    bonds_ = bondsFix(lmp, true);
}

// The longest bond now, for LAMMPS's check of the communication cutoff
// (which multiplies this by 1.5).
double BondGranbond::equilibrium_distance(int)
{
    double longest = 0.0;
    double **x = atom->x;
    for (int i = 0; i < atom->nlocal; i++)
        for (int m = 0; m < atom->num_bond[i]; m++) {
            if (atom->bond_type[i][m] <= 0) continue;
            const int j = atom->map(atom->bond_atom[i][m]);
            if (j < 0) continue;
            // the partner's image closest to i, as the bond list takes it
            double xj[3];
            domain->closest_image(x[i], x[j], xj);
            const double d[3] = {x[i][0] - xj[0], x[i][1] - xj[1], x[i][2] - xj[2]};
            longest = std::max(longest, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        }
    double all = 0.0;
    MPI_Allreduce(&longest, &all, 1, MPI_DOUBLE, MPI_MAX, world);
    return all / 1.5;
}

GbAtomArrays BondGranbond::atomArrays() const { return atomArraysOf(atom); }

GbBondStore *BondGranbond::bondStore() const { return bonds_ ? bonds_->store() : nullptr; }

// The type of the topology's entry for the pair: its owner's (which holds
// it under either newton_bond), else its partner's.
size_t BondGranbond::bondKind(int i, int j, size_t) const
{
    const int ends[2][2] = {{i, j}, {j, i}};
    for (const auto &e : ends) {
        if (e[0] >= atom->nlocal) continue;
        for (int m = 0; m < atom->num_bond[e[0]]; m++)
            if (atom->bond_atom[e[0]][m] == atom->tag[e[1]] && atom->bond_type[e[0]][m] > 0)
                return static_cast<size_t>(atom->bond_type[e[0]][m]);
    }
    return 0;
}

void BondGranbond::counts(double *values) const
{
    GbStoreCounts c;
    std::memset(&c, 0, sizeof c);
    if (bonds_) c = bonds_->counts();
    double mine[GRANBOND_COUNTS_ROW_LEN];
    granbond_store_counts_row(&c, mine);
    MPI_Allreduce(mine, values, GRANBOND_COUNTS_ROW_LEN, MPI_DOUBLE, MPI_SUM, world);
}

bool BondGranbond::storeCurrent() const
{
    return passStep_ == update->ntimestep && passAtoms_ == static_cast<bigint>(atom->nlocal) + atom->nghost;
}

void BondGranbond::failBond(int i, int j, const std::string &what)
{
    message_ = "bond_style granbond: " + what + " of atoms " + std::to_string(static_cast<long long>(atom->tag[i])) +
               " and " + std::to_string(static_cast<long long>(atom->tag[j])) + " at step " +
               std::to_string(static_cast<long long>(update->ntimestep)) + ": " + coreReason();
    endRun(lmp, message_);
}

// After a list build: the bonds of the engine's bond list this rank steps,
// each once over all ranks, become the store's. Under newton_bond on a bond
// is listed once, by the atom that holds it, which owns it; under newton_bond
// off both atoms' ranks list it, and the atom with the smaller id owns it.
void BondGranbond::linkTopology()
{
    const int nlocal = atom->nlocal;
    const tagint *tag = atom->tag;
    int **list = neighbor->bondlist;
    std::vector<GbListedBond> listed;
    listed.reserve(static_cast<size_t>(neighbor->nbondlist));
    for (int n = 0; n < neighbor->nbondlist; n++) {
        int i = list[n][0], j = list[n][1];
        const int type = list[n][2];
        if (type <= 0) continue;
        if (!force->newton_bond) {
            if (j < nlocal) {
                if (tag[j] < tag[i]) std::swap(i, j);
            } else if (tag[j] < tag[i]) {
                continue;   // the rank of atom j steps it
            }
        }
        if (type >= static_cast<int>(models_.size()) || !models_[type])
            error->one(FLERR, "bond_style granbond: bond type " + std::to_string(type) + " has no bond_coeff");
        listed.push_back(GbListedBond{i, j, type});
    }
    const GbAtomIds ids = atomIdsOf(atom);
    GbLinkReport report;
    if (granbond_bond_store_link_listed(bonds_->store(), &ids, static_cast<size_t>(nlocal),
                                        atom->nmax > 0 ? atom->x[0] : nullptr, listed.data(), listed.size(),
                                        &report) != GB_STATUS_OK)
        error->one(FLERR, "bond_style granbond: the bonds of the topology: " + coreReason());
    // each atom's bonds to its ghost images, for the per-atom counts
    bonds_->sendView();
    const int64_t mine[4] = {report.owner_gone, report.id_reused, report.no_model, 0};
    const std::string left = ledgerNotice(GRANBOND_NOTICE_TOPOLOGY_LEFT_LAMMPS, mine, update->ntimestep, nullptr, world);
    if (!left.empty() && comm->me == 0) error->warning(FLERR, left);
}

// Steps the bonds of the pass and adds their loads to the atoms: both
// atoms' forces and torques (a ghost's for the engine's reverse
// communication when newton is on for pairs or bonds, else for the fix's),
// the virial of each bond once.
void BondGranbond::stepBonds(bool advance)
{
    const double *const x0 = atom->nmax > 0 ? atom->x[0] : nullptr;
    stepChunks(
        atom, bonds_->store(), models_, force->newton != 0, ghostLoads_,
        bondOutputUsers > 0 && advance ? &outputs_ : nullptr, vflag_global != 0,
        [&](int i, int j, const double *f) {
            const double *xi = x0 + 3 * static_cast<size_t>(i), *xj = x0 + 3 * static_cast<size_t>(j);
            const double d[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
            virial[0] += d[0] * f[0];
            virial[1] += d[1] * f[1];
            virial[2] += d[2] * f[2];
            virial[3] += d[0] * f[1];
            virial[4] += d[0] * f[2];
            virial[5] += d[1] * f[2];
        },
        [&](int i, int j, const std::string &why) {
            if (i >= 0) failBond(i, j, "the bond");
            error->one(FLERR, "bond_style granbond: the bonds: " + why);
        });
}

void BondGranbond::compute(int eflag, int vflag)
{
    ev_init(eflag, vflag);
    if (!bonds_) error->all(FLERR, "bond_style granbond: no run has initialised it");
    const bool advance = !update->setupflag;
    if (update->setupflag || neighbor->ago == 0) linkTopology();
    GbBondStore *store = bonds_->store();
    if (granbond_bond_store_begin_pass(store, update->dt, advance ? 1 : 0, 0) != GB_STATUS_OK)
        error->one(FLERR, "bond_style granbond: " + coreReason());
    ghostLoads_ = force->newton ? nullptr : bonds_->ghostLoads();
    if (bondOutputUsers > 0 && advance) outputs_.clear();
    stepBonds(advance);
    takeBroken(advance);
    if (granbond_bond_store_finish_pass(store) != GB_STATUS_OK)
        error->one(FLERR, "bond_style granbond: " + coreReason());
    if (bondOutputUsers > 0 && advance)
        outputs_.erase(std::remove_if(outputs_.begin(), outputs_.end(),
                                      [](const GbBondOutput &o) { return o.status != GB_BOND_STATUS_INTACT; }),
                       outputs_.end());
    if (!force->newton) bonds_->returnGhostLoads();
    bonds_->sizeExchange();
    if (eflag_global) {
        const GbAtomArrays arrays = atomArraysOf(atom);
        double stored = 0.0;
        if (granbond_bond_store_stored_energy(store, models_.data(), models_.size(), &arrays, &stored) != GB_STATUS_OK)
            error->one(FLERR, "bond_style granbond: the bonds' stored energy: " + coreReason());
        energy += stored;
    }
    passStep_ = update->ntimestep;
    passAtoms_ = static_cast<bigint>(atom->nlocal) + atom->nghost;
}

// The bonds broken in this pass: logged, and gone from the topology of
// every rank.
void BondGranbond::takeBroken(bool advance)
{
    GbBondStore *store = bonds_->store();
    const size_t nb = granbond_bond_store_broken_count(store);
    std::vector<tagint> pairs;
    pairs.reserve(2 * nb);
    for (size_t m = 0; m < nb; m++) {
        GbBrokenBond b;
        if (granbond_bond_store_broken(store, m, &b) != GB_STATUS_OK)
            error->one(FLERR, "bond_style granbond: " + coreReason());
        const int i = b.ends[0], j = b.ends[1];
        pairs.push_back(atom->tag[i]);
        pairs.push_back(atom->tag[j]);
        if (breakLogUsers > 0 && advance) {
            int type = 0;
            for (int q = 0; q < atom->num_bond[i] && type == 0; q++)
                if (atom->bond_atom[i][q] == atom->tag[j]) type = atom->bond_type[i][q];
            for (int q = 0; j < atom->nlocal && q < atom->num_bond[j] && type == 0; q++)
                if (atom->bond_atom[j][q] == atom->tag[i]) type = atom->bond_type[j][q];
            const GbBondModel *model = type > 0 && type < static_cast<int>(models_.size()) ? models_[type] : nullptr;
            BreakEvent e;
            if (!model || makeBreakEvent(model, b.out, atom, i, j, static_cast<double>(update->ntimestep), e) !=
                              GB_STATUS_OK)
                failBond(i, j, "the break log's event");
            breaks_.push_back(e);
        }
    }
    dropBroken(pairs);
}

void BondGranbond::write_restart(FILE *fp)
{
    const int n = atom->nbondtypes;
    for (int t = 1; t <= n; t++) {
        fwrite(&setflag[t], sizeof(int), 1, fp);
        if (setflag[t]) writeBondRows(fp, params_[t], error);
    }
}

void BondGranbond::read_restart(FILE *fp)
{
    allocate();
    const int n = atom->nbondtypes;
    for (int t = 1; t <= n; t++) {
        if (comm->me == 0) utils::sfread(FLERR, &setflag[t], sizeof(int), 1, fp, nullptr, error);
        MPI_Bcast(&setflag[t], 1, MPI_INT, 0, world);
        if (!setflag[t]) continue;
        readBondRows(fp, params_[t], "bond type " + std::to_string(t), comm->me, world, error);
        if (granbond_bond_model_new(&params_[t], &models_[t]) != GB_STATUS_OK)
            error->all(FLERR, "bond_style granbond: the restart file's bond type " + std::to_string(t) + ": " +
                                  coreReason());
    }
}

// A bond's loads depend on its history, which compute bond/local's single
// call cannot name: the deck asks compute granbond/local instead.
double BondGranbond::single(int, double, int, int, double &)
{
    error->all(FLERR, "bond_style granbond: a bond's force and energy depend on its state, which compute bond/local "
                      "cannot ask for; use compute granbond/local (force_x ... and the stored energy) or compute "
                      "bond/local with dist and the atom ids only");
    return 0.0;
}

double BondGranbond::memory_usage()
{
    return Bond::memory_usage() + static_cast<double>(outputs_.capacity() * sizeof(GbBondOutput));
}

}
}
