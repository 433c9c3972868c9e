// pair_style granbond: the granbond core's `voigt` contact and
// `bond/nonlinear` bond as one LAMMPS pair style. Translation only: the
// deck's words become rows of the core's parameter tables (pair_coeff.cpp),
// a contact's state lives in fix neigh/history (as pair granular's), a
// bond's in the core's bond store behind fix granbond/bonds
// (bond_store_fix.h), and every force comes from the core
// (pair_granbond.cpp); plugin.cpp registers the style.
//
//   pair_style granbond
//   pair_coeff I J voigt <values> [voigt keyword ...] [bond/nonlinear keyword ...]
#ifndef GRANBOND_LAMMPS_PAIR_GRANBOND_H
#define GRANBOND_LAMMPS_PAIR_GRANBOND_H

#include "pair.h"
#include "granbond.h"
#include "bond_source.h"
#include "break_log.h"
#include "run_checks.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class FixNeighHistory;
}

namespace granbond {
namespace lammps {
class FixGranbondBonds;

class PairGranbond : public LAMMPS_NS::Pair, public BondSource {
public:
    explicit PairGranbond(LAMMPS_NS::LAMMPS *lmp);
    ~PairGranbond() override;

    void compute(int eflag, int vflag) override;
    void settings(int narg, char **arg) override;
    void coeff(int narg, char **arg) override;
    void init_style() override;
    double init_one(int i, int j) override;
    void write_restart(FILE *fp) override;
    void read_restart(FILE *fp) override;
    void reset_dt() override {}
    // fix neigh/history: the pair seen from the other atom; the core's
    // contact table says which slots change sign (vectors)
#ifdef GRANBOND_LAMMPS_TRANSFER_HISTORY_IJ
    void transfer_history(double *source, double *target, int i, int j) override;
#else
    void transfer_history(double *source, double *target) override;
#endif
    double memory_usage() override;

    // Everything pair_coeff set for one type pair (written to restart files
    // as rows of the core's tables, pair_restart.cpp).
    struct TypePair {
        GbVoigtParams voigt;
        GbBondParams bond;
        int32_t hasBond;
    };

    // What the per-bond outputs read (bond_watch.cpp): the store and its
    // bonds' models by kind (the type pair), valid while `storeCurrent()`;
    // each bond's output of the latest force pass, in store order, kept
    // while `bondOutputUsers` is non-zero (compute granbond/local); the
    // bonds that broke in force passes, kept while `breakLogUsers` is
    // non-zero (fix bond/breaklog).
    GbBondStore *bondStore() const override;
    const GbBondModel *bondModel(size_t kind) const override { return kind < bond_.size() ? bond_[kind] : nullptr; }
    size_t bondKind(int i, int j, size_t k) const override;
    bool storeCurrent() const override;
    const std::vector<GbBondOutput> &bondOutputs() const override { return outputs_; }
    std::vector<BreakEvent> &breakEvents() override { return breaks_; }
    const GbBondModel *const *bondModels() const override { return bond_.data(); }
    size_t bondKinds() const override { return bond_.size(); }
    GbAtomArrays atomArrays() const override;
    // pair_style granbond energy yes: the store keeps the bonds' energy
    // budget; energyOutputUsers (compute granbond/local asking for a bond's
    // dissipated energy) keeps each bond's share too.
    bool energyBudget = false;
    // The contact history's flag of a pair: 0 apart (its history all
    // zero), 1 touching, kBondedMark bonded. The last is a cache of the
    // bond store, marked again from it after every list build and wherever
    // a bond breaks or forms (fix neigh/history keeps only whether a flag
    // is set).
    static const int kBondedMark = 2;
    GbAtomIds atomIds() const;

private:
    // the contact history's fix, and the placeholder that keeps its place
    // in the fix list until init_style makes it
    static constexpr const char *kFixDummy = "NEIGH_HISTORY_GRANBOND_DUMMY";
    static constexpr const char *kFix = "NEIGH_HISTORY_GRANBOND";
    void allocate();
    void freeModels();
    void buildModel(int i, int j);
    // Ends the run on this rank: `what` of atoms i and j failed, with the
    // core's reason.
    [[noreturn]] void failPair(int i, int j, const char *what);
    // Adds a pair's loads to atoms i and j as LAMMPS's pair styles do;
    // `del` (x_i - x_j) is read only when the virial is tallied (evflag).
    void apply(double *f, double *torque, int i, int j, const double *fi, const double *ti, const double *tj,
               const double *del, int nlocal, int newton_pair);
    size_t at(int i, int j) const;
    void runChecks(const std::vector<GbTypeBodies> &bodies, bool runStart);
    void sayLaw();
    bool bondsExist() const;

    // What the Voigt steps of a pass read, fetched once per pass: with a
    // core call between two steps, the compiler would fetch each of them
    // again through the objects for every contact.
    struct ContactReads {
        const GbVoigtModel *const *voigt;   // per type pair
        const double *radius, *v, *omega;    // atom->radius, v[0], omega[0]
        double dt;
    };
    ContactReads contactReads() const;
    void voigtStep(const ContactReads &r, size_t tp, int i, int j, const double *del, double rsq, double *state,
                   GbContactOutput &cout);
    void voigtEvaluate(size_t tp, int i, int j, const double *del, double rsq, const double *state,
                       GbContactOutput &cout);
    void contactOf(size_t tp, int i, int j, int *touch, double *history, bool advance, bool touching,
                   const double *del, double rsq);
    // A touching bonded pair whose bond's law keeps some of the contact's
    // loads (keepsLoads_): the contact stepped (its state held at zero
    // unless contact_under_bond), and the loads the core says act under
    // the bond applied.
    void stepContactOfBond(size_t tp, int i, int j, double *history, bool advance, const double *del, double rsq);

    // The bond pass (pair_bonds.cpp): the store linked after a
    // list build, the contact history's flags marked from it, its chunks
    // stepped and their loads added to the atoms, the bonds that broke
    // taken out of the contact loop, the view sent again where bonds broke
    // or formed on any rank, the counts.
    void linkBonds();
    void markBonded();
    void stepBonds(bool advance);
    void takeBroken(bool advance);
    bool tryBond(size_t tp, int i, int j, int *touch, double *history);
    void countBonds();
    void checkStore();

    std::vector<TypePair> pairs_;
    std::vector<GbVoigtModel *> voigt_;
    std::vector<GbBondModel *> bond_;
    std::vector<int32_t> kinds_;            // per type pair: its bond kind (its index), -1 without a bond
    std::vector<char> keepsLoads_;          // per type pair: its bond's law keeps some of the contact's loads
    std::vector<char> createsNow_;          // per type pair, this pass (compute)
    std::vector<GbTypeBodies> bodies_;      // per type, over all ranks, at the latest run start
    std::vector<double> transferSign_;      // per history slot: +1 copy, -1 negate
    std::vector<GbBondOutput> outputs_;     // per bond, the latest force pass (bondOutputUsers)
    // per position of the list: its pairs that are not bonds (the contact
    // loop passes over an atom without any); per local atom: its position
    std::vector<int> livePairs_, listPosition_;
    double *ghostLoads_ = nullptr;          // this pass's loads on ghost atoms (newton off)
    bool checkStore_;                       // GRANBOND_CHECK_STORE: recount the bonds after each pass
    int sizeHistory_;
    bool anyBond_;
    LAMMPS_NS::FixNeighHistory *fixHistory_;
    FixGranbondBonds *bonds_;               // the bonds' home (bonded runs)
    std::string message_;                   // outlives error->one's use
    LAMMPS_NS::bigint checkedNatoms_;       // atom count of the latest checks
    LAMMPS_NS::bigint firstStep_;           // where the first run that steps started
    bool stepped_;                          // a force pass has stepped the system
    TimestepWarning contactWarning_, bondWarning_;
    SaidOnce said_;
    bool lawSaid_ = false;                  // the bonds' law told since the latest pair_coeff
    bool formedThisPass_ = false;          // bonds formed here in this pass
    double deckGhostReach_ = 0.0;           // comm_modify cutoff as the deck set it
    double ghostReachSet_ = -1.0;           // the ghost reach init_one set last
    std::vector<BreakEvent> breaks_;
    LAMMPS_NS::bigint passStep_ = -1;       // step and atom count (local + ghost) of the latest pass
    LAMMPS_NS::bigint passAtoms_ = -1;
};

}
}

#endif
