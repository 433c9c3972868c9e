// pair_style granbond's `pair_style` and `pair_coeff` commands: the words of
// a type pair's models translated to rows of the core's parameter tables,
// and the core's models built from them.
//
//   pair_coeff I J voigt <values> [voigt keyword ...] [bond/nonlinear keyword ...]
//   pair_coeff I J voigt <values> [voigt keyword ...] [bond/linear keyword ...]
//
// `bond/linear` is LIGGGHTS-INL's linear bond: the bond table's row
// `linear` on, the same keywords (the core refuses those of the other law).
// The core reads the words (granbond_pair_coeff_read).
#include "pair_granbond.h"
#include "core_message.h"

#include "atom.h"
#include "error.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace granbond {
namespace lammps {

namespace {

// The model words of pair_coeff.
const char *const kVoigt = "voigt";
const char *const kBond = "bond/nonlinear";
const char *const kLinear = "bond/linear";

}

// pair_style granbond [energy yes|no]: the models are per type pair; the
// one setting is whether the bonds' energy budget is kept (compute pair
// granbond's values 9-11).
void PairGranbond::settings(int narg, char **arg)
{
    const bool energy = narg == 2 && std::strcmp(arg[0], "energy") == 0;
    if (narg != 0 && !energy)
        error->all(FLERR, std::string("pair_style granbond takes only 'energy yes|no' (got '") + arg[0] +
                              "'); the models are set per type pair with pair_coeff");
    if (narg == 0) {
        energyBudget = false;
        return;
    }
    const std::string value = arg[1];
    if (value != "yes" && value != "on" && value != "no" && value != "off")
        error->all(FLERR, "pair_style granbond energy: expected yes or no (or on, off), got '" + value + "'");
    energyBudget = value == "yes" || value == "on";
}

void PairGranbond::coeff(int narg, char **arg)
{
    if (!allocated) allocate();
    if (narg < 3) error->all(FLERR, "pair_coeff: pair_style granbond expects I J voigt ... [bond/nonlinear ...]");
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

    // the core reads the words: the tables' rows and phrases, the bond law's
    // defaults, what the contact does under the bond where the line does not say
    TypePair tp;
    std::memset(&tp, 0, sizeof tp);
    const std::string command = std::string("pair_coeff ") + arg[0] + " " + arg[1];
    if (granbond_pair_coeff_read(command.c_str(), arg + 2, static_cast<size_t>(narg - 2), update->unit_style,
                                 &tp.voigt, &tp.bond, &tp.hasBond) != GB_STATUS_OK)
        error->all(FLERR, coreReason());

    int count = 0;
    for (int ti = ilo; ti <= ihi; ti++)
        for (int tj = jlo; tj <= jhi; tj++) {
            const int i = std::min(ti, tj), j = std::max(ti, tj);
            pairs_[at(i, j)] = tp;
            pairs_[at(j, i)] = tp;
            buildModel(i, j);
            setflag[i][j] = setflag[j][i] = 1;
            count++;
        }
    if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

// Builds the core's models of types (i, j), i <= j, from pairs_ (stored at
// (i, j) only); the core validates, and its message names the parameter,
// its range and the value.
void PairGranbond::buildModel(int i, int j)
{
    const size_t k = at(i, j);
    const TypePair &tp = pairs_[k];
    granbond_voigt_model_free(voigt_[k]);
    granbond_bond_model_free(bond_[k]);
    voigt_[k] = nullptr;
    bond_[k] = nullptr;
    const std::string command = "pair_coeff " + std::to_string(i) + " " + std::to_string(j) + " ";
    if (granbond_voigt_model_new(&tp.voigt, &voigt_[k]) != GB_STATUS_OK)
        error->all(FLERR, command + kVoigt + ": " + coreReason());
    if (tp.hasBond && granbond_bond_model_new(&tp.bond, &bond_[k]) != GB_STATUS_OK)
        error->all(FLERR, command + (tp.bond.linear ? kLinear : kBond) + ": " + coreReason());
    keepsLoads_[k] = bond_[k] && (granbond_bond_keeps_contact_loads(bond_[k]) ||
                                  granbond_bond_keeps_contact_tangential(bond_[k]));
    lawSaid_ = false;
}

}
}
