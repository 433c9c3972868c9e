// pair_style granbond at a run's start: the atoms and communication it
// needs, the minimizers it can follow, the bond kind of each pair of types,
// the contact history's fix, the reach of the lists and of the ghost atoms,
// and the core's checks of the run (time step, creation rules).
#include "pair_granbond.h"
#include "bond_store_fix.h"
#include "core_message.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

// the neighbour request API of each LAMMPS generation (pair_granbond.cpp)
#ifndef GRANBOND_LAMMPS_ADD_REQUEST
#include "neigh_request.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

void PairGranbond::init_style()
{
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        error->all(FLERR, "pair granbond requires atom_style sphere (radius, rmass, omega, torque)");
    if (comm->ghost_velocity == 0)
        error->all(FLERR, "pair granbond requires ghost atoms to store velocity (comm_modify vel yes)");
    // A line search evaluates trial positions it may reject, and every
    // force pass advances the history of the contacts and bonds, whose
    // forces are not the gradient of an energy. A damped-dynamics
    // minimizer (fire, quickmin) takes every step it evaluates.
    const std::string minStyle = update->minimize_style ? update->minimize_style : "";
    if (update->whichflag == 2 && minStyle != "fire" && minStyle != "fire/old" && minStyle != "quickmin")
        error->all(FLERR, "pair granbond cannot be used with min_style " + minStyle +
                              ": its line search evaluates trial positions it may reject, and every force pass "
                              "advances the history of the contacts and bonds (whose forces are not the gradient "
                              "of an energy); use min_style fire or quickmin, or relax the system with a damped "
                              "run (fix viscous, or the bond model's damping)");
    if (update->whichflag == 2 && comm->me == 0)
        utils::logmesg(lmp, "pair granbond: min_style " + minStyle +
                                " steps the contacts' and bonds' history at every step it takes, as a damped run "
                                "would\n");

    const int n = atom->ntypes;
    anyBond_ = false;
    // the bond kind of each pair of types: the index of its model
    kinds_.assign(static_cast<size_t>(n + 1) * (n + 1), -1);
    for (int i = 1; i <= n; i++)
        for (int j = 1; j <= n; j++) {
            const size_t k = at(std::min(i, j), std::max(i, j));
            if (setflag[std::min(i, j)][std::max(i, j)] && pairs_[k].hasBond) {
                anyBond_ = true;
                kinds_[at(i, j)] = static_cast<int32_t>(k);
            }
        }

    // history: the contact's state, with the core's swap rule of each slot
    // (transfer_history); the bonds live in fix granbond/bonds
    const int size = static_cast<int>(granbond_state_len(GB_STATE_KIND_CONTACT));
    transferSign_.assign(size, 1.0);
    for (int k = 0; k < size; k++) {
        int32_t flips = 0;
        const char *name = nullptr;
        if (granbond_state_slot(GB_STATE_KIND_CONTACT, k, &name, &flips) != GB_STATUS_OK)
            error->all(FLERR, std::string("pair_style granbond: ") + coreReason());
        transferSign_[k] = flips ? -1.0 : 1.0;
    }

#ifdef GRANBOND_LAMMPS_ADD_REQUEST
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
#else
    const int irequest = neighbor->request(this, instance_me);
    neighbor->requests[irequest]->history = 1;
#endif

    if (!fixHistory_) {
        sizeHistory_ = size;
        Fix *made = modify->replace_fix(kFixDummy, std::string(kFix) + " all NEIGH_HISTORY " + std::to_string(size), 0);
        fixHistory_ = static_cast<FixNeighHistory *>(made);
        fixHistory_->pair = this;
    }
    if (modify->find_fix(kFix) < 0) error->all(FLERR, "pair granbond: its fix neigh/history was deleted or replaced");

    // the ghost atoms' reach: the deck's own (comm_modify cutoff), raised
    // by init_one for this init only, so that radii not set yet at an
    // early init leave nothing behind
    if (comm->cutghostuser != ghostReachSet_) deckGhostReach_ = comm->cutghostuser;
    comm->cutghostuser = deckGhostReach_;

    // per-type radii (for the cutoffs) and masses, all ranks, and the
    // spheres fix pour and fix deposit will insert during the run (as pair
    // granular takes them)
    bodies_ = gatherTypeBodies(n, atom->nlocal, atom->type, atom->radius, atom->rmass, world);
    for (int k = 0; k < modify->nfix; k++) {
        const std::string style = modify->fix[k]->style;
        if (style.rfind("pour", 0) != 0 && style.rfind("deposit", 0) != 0) continue;
        for (int t = 1; t <= n; t++) {
            int type = t;
            const double *r = static_cast<const double *>(modify->fix[k]->extract("radius", type));
            if (!r || !(*r > 0.0)) continue;
            bodies_[t].radius_max = std::max(bodies_[t].radius_max, *r);
            bodies_[t].radius_min = std::min(bodies_[t].radius_min, *r);
        }
    }
    // where the first run that steps starts: `run 0`, write_data or any
    // other init before it reaches no creation step
    if (!stepped_) firstStep_ = update->ntimestep;
    // a restart file's bonds come back with their fix; a run without bonds
    // makes none
    if (anyBond_ || modify->find_fix(bondsFixId()) >= 0) bonds_ = bondsFix(lmp);
    // ids changed since the bonds were made (reset_atom_ids, delete_atoms
    // with compress yes) would hand them to other atoms
    if (bonds_ && bondsExist()) {
        long long mine = 0, all = 0;
        for (int i = 0; i < atom->nlocal; i++) {
            const int64_t seen = granbond_bond_store_seen(bonds_->store(), static_cast<size_t>(i));
            if (seen != 0 && seen != static_cast<int64_t>(atom->tag[i])) mine++;
        }
        MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
        if (all > 0) error->all(FLERR, renumberedMessage("pair granbond (bond/nonlinear)", all));
    }
    if (anyBond_ && comm->me == 0 && currentCommand(lmp) == "rerun")
        error->warning(FLERR, "rerun: pair granbond's bonds live in its store (restart files), not in dump files: "
                              "this rerun has the bonds of its own system (" +
                              std::to_string(static_cast<long long>(bonds_ ? granbond_bond_store_len(bonds_->store()) : 0)) +
                              " on rank 0) and forms none, so its forces are those of the contacts and of those bonds");
    if (checkStore_ && anyBond_ && comm->me == 0)
        utils::logmesg(lmp, "pair granbond: recounting the bonds after every pass (GRANBOND_CHECK_STORE)\n");
    // an init outside a run or minimization (reset_atom_ids, write_data)
    // may see atoms before their radii are set: the checks wait for a run
    if (update->whichflag != 0) runChecks(bodies_, true);
}

// The core's checks: the time step against the stiffest contact and bond
// (warned at a run's start, and when the atom count changes if the limit
// moved) and, at a run's start, the bonds' creation rules (each finding
// once).
void PairGranbond::runChecks(const std::vector<GbTypeBodies> &bodies, bool runStart)
{
    checkedNatoms_ = atom->natoms;
    const int n = atom->ntypes;
    GbCheckReport report;
    const char *const contact = "pair granbond (voigt)", *const bond = "pair granbond (bond/nonlinear)";
    const char *const units = update->unit_style;
    if (granbond_voigt_timestep_check(voigt_.data(), n, bodies.data(), update->dt, units, contact, &report) !=
        GB_STATUS_OK)
        error->all(FLERR, std::string(contact) + ": " + coreReason());
    if (contactWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!anyBond_) return;
    if (granbond_bond_timestep_check(bond_.data(), n, bodies.data(), update->dt, 0, units, bond, &report) !=
        GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + coreReason());
    if (bondWarning_.due(report, runStart) && comm->me == 0) error->warning(FLERR, report.message);
    if (!runStart) return;
    if (!lawSaid_ && comm->me == 0) sayLaw();
    lawSaid_ = true;
    if (granbond_bond_creation_check(bond_.data(), n, bodies.data(), firstStep_, bondsExist() ? 1 : 0, 0, 0, units,
                                     bond, &report) != GB_STATUS_OK)
        error->all(FLERR, std::string(bond) + ": " + coreReason());
    for (const std::string &line : said_.fresh(report))
        if (comm->me == 0) error->warning(FLERR, line);
}

// The run's opening lines say which law the bonds follow (the core's
// words), each different line once, until a pair_coeff changes the models:
// LIGGGHTS-INL's decks run with the write-up's law unless they ask for
// INL's code.
void PairGranbond::sayLaw()
{
    std::vector<std::string> said;
    for (const GbBondModel *m : bond_) {
        char line[512];
        if (!m || granbond_bond_law_line(m, 0, line, sizeof line) != GB_STATUS_OK) continue;
        if (std::find(said.begin(), said.end(), std::string(line)) != said.end()) continue;
        said.push_back(line);
        utils::logmesg(lmp, std::string("pair granbond: ") + line + "\n");
    }
}

// The neighbour list reaches as far as two spheres of the types touch, or
// bond at a creation step; the ghost atoms as far as a bond stretches
// before it breaks (the core's reach), so that each bond finds its partner.
double PairGranbond::init_one(int i, int j)
{
    if (!setflag[i][j])
        error->all(FLERR, "pair granbond: no pair_coeff for atom types " + std::to_string(i) + " and " +
                              std::to_string(j));
    double cut = bodies_[i].radius_max + bodies_[j].radius_max;
    const GbBondModel *b = bond_[at(std::min(i, j), std::max(i, j))];
    const double rmin = std::min(bodies_[i].radius_min, bodies_[j].radius_min);
    if (b && std::isfinite(rmin) && rmin > 0.0) {
        const std::string pairCoeff = "pair_coeff " + std::to_string(std::min(i, j)) + " " +
                                      std::to_string(std::max(i, j)) + " bond/nonlinear: ";
        // the core's reach of an intact bond; it refuses a bond no ghost
        // atoms can hold, naming what sets its reach
        double factor = 0.0, creates = 0.0;
        if (granbond_bond_neighbour_reach(b, rmin, std::min(i, j), std::max(i, j), 0, update->unit_style, &factor) !=
                GB_STATUS_OK ||
            granbond_bond_creation_reach(b, update->ntimestep, &creates) != GB_STATUS_OK)
            error->all(FLERR, pairCoeff + coreReason());
        cut = std::max(cut, creates);
        comm->cutghostuser = std::max(comm->cutghostuser, factor * 2.0 * rmin + neighbor->skin);
        ghostReachSet_ = comm->cutghostuser;
    }
    return cut;
}

}
}
