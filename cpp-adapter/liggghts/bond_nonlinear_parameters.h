// Deck -> core translation for `cohesion bond/nonlinear`: the on/off switches
// of `pair_style gran ... cohesion bond/nonlinear`, the `fix property/global`
// values of docs/reference/cohesion_bond_nonlinear.md, and one
// validated GbBondModel per atom-type pair built from them. The same for
// LIGGGHTS-INL's linear bond, `cohesion bond`, under its names (the core's
// granbond_bond_parameter_liggghts_name).
#ifndef GRANBOND_LIGGGHTS_BOND_NONLINEAR_PARAMETERS_H
#define GRANBOND_LIGGGHTS_BOND_NONLINEAR_PARAMETERS_H

#include "liggghts_engine.h"
#include "granbond.h"

#include <deque>
#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

class BondNonlinearParameters : protected LAMMPS_NS::Pointers {
public:
    explicit BondNonlinearParameters(LAMMPS_NS::LAMMPS *lmp);
    ~BondNonlinearParameters();

    // The next parameters built serve `cohesion bond` (the linear bond):
    // its model class shares the cohesion class that builds them, which
    // does not otherwise tell them the model (cohesion_model_bond_linear.h).
    static void nextServeLinearBond() { nextLinear_ = true; }

    void registerSettings(::Settings &settings);
    // The deck's switches over the law's defaults, once the engine has read
    // them, and what the contact does under the bond: as the deck says, or
    // where it does not, as the law says (the core's rule).
    void readSwitches();
    bool contactGoesOnUnderBond() const { return switches_.contact_under_bond != 0; }

    // Connects the properties the switches ask for, builds the models (any
    // core validation error ends the run naming the property) and registers
    // the neighbour-list reach that keeps stretched bonds in the lists.
    void connectToProperties(::PropertyRegistry &registry);

    // Model of the type pair, or null if none was built (not yet connected).
    const GbBondModel *model(int itype, int jtype) const
    {
        if (itype < 1 || jtype < 1 || itype > ntypes_ || jtype > ntypes_) return 0;
        return models_[itype * (ntypes_ + 1) + jtype];
    }

    // The model as its decks name it: `cohesion bond/nonlinear`, or
    // `cohesion bond` for the linear bond (for the run's messages).
    const char *caller() const { return caller_; }

    // The models as the core's checks take them: entry a * (ntypes() + 1) + b.
    const GbBondModel *const *table() const { return models_.data(); }
    int ntypes() const { return ntypes_; }

private:
    BondNonlinearParameters(const BondNonlinearParameters &);
    BondNonlinearParameters &operator=(const BondNonlinearParameters &);

    void freeModels();
    void connectPerTypePair(::PropertyRegistry &registry, size_t index);
    void buildModels(::PropertyRegistry &registry);
    void registerContactDistanceFactor(::PropertyRegistry &registry);

    void set(GbBondParams &p, size_t id, double value, const std::string &where);
    // The name this model's decks give row `id`, or null if it has none.
    const char *name(size_t id) const;

    static bool nextLinear_;
    const bool linear_;          // `cohesion bond` rather than `cohesion bond/nonlinear`
    const char *const caller_;   // the model, as the deck names it

    // indexed by row of the core's parameter table
    size_t rows_;
    std::deque<bool> switchValues_;        // the engine's Settings take a bool&
    std::vector<double **> perTypePair_;   // connected per-type-pair properties
    std::vector<double> scalars_;          // connected scalar properties
    std::vector<bool> connectedScalar_;
    GbBondParams switches_;                // the defaults with the deck's switches
    // The engine's Settings write a switch's value into every variable
    // registered under its name only when the deck gives the switch, so two
    // such variables left unequal after registering stay unequal unless the
    // deck gives contactUnderBond.
    size_t underBondRow_;
    bool underBondProbe_[2];

    int ntypes_;
    std::vector<GbBondModel *> models_;
};

}
}

#endif
