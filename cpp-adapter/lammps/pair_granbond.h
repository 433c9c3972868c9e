// pair_style granbond: the granbond core's `voigt` contact and
// `bond/nonlinear` bond as one LAMMPS pair style. Translation only: the
// deck's words become rows of the core's parameter tables (pair_coeff.cpp),
// the per-pair state lives in fix neigh/history (as pair granular's), and
// every force comes from the core (pair_granbond.cpp); plugin.cpp registers
// the style.
//
//   pair_style granbond
//   pair_coeff I J voigt <values> [voigt keyword ...] [bond/nonlinear keyword ...]
#ifndef GRANBOND_LAMMPS_PAIR_GRANBOND_H
#define GRANBOND_LAMMPS_PAIR_GRANBOND_H

#include "pair.h"
#include "granbond.h"
#include "bond_index.h"
#include "break_log.h"
#include "run_checks.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class FixNeighHistory;
}

namespace granbond {
class FixGranbondAtoms;
namespace lammps {

class PairGranbond : public LAMMPS_NS::Pair {
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
    // record table says which slots change sign (vectors) and which are
    // copied (scalars such as r0, dmax, dmin, status)
#ifdef GRANBOND_LAMMPS_TRANSFER_HISTORY_IJ
    void transfer_history(double *source, double *target, int i, int j) override;
#else
    void transfer_history(double *source, double *target) override;
#endif
    double memory_usage() override;

    // Everything pair_coeff set for one type pair (plain data: written to
    // restart files as is).
    struct TypePair {
        GbVoigtParams voigt;
        GbBondParams bond;
        int32_t hasBond;
        // the contact's state goes on under an intact bond (pair_coeff
        // ... contact_under_bond yes), or starts afresh when it breaks
        int32_t contactUnderBond;
    };

    // What the per-bond outputs read (bond_watch.cpp): the intact bonds
    // after the latest pass, per type pair, valid while `indexCurrent()`;
    // the layout of their records; the bonds that broke in force passes,
    // kept while `breakLogUsers` is non-zero (fix bond/breaklog).
    const std::vector<BondIndex> &bondIndex() const { return index_; }
    bool indexCurrent() const;
    const GbRecordLayout &recordLayout() const { return layout_; }
    std::vector<BreakEvent> &breakEvents() { return breaks_; }
    int breakLogUsers = 0;

    // The bonds, stepped side by side in their index (bond_index.h), written
    // back to their records in the engine's history pages: before fix
    // neigh/history gathers the records.
    void writeBackBonds();

private:
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
    void checkRenumbering();
    bool countsHere(int i, int j) const;
    void countVanished(long long intact);
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
    void pairKinematics(int i, int j, GbPairKinematics &k) const;
    void indexBonds();
    void sweep(BondIndex &b, size_t first, bool advance, GbSweepTally &tally);
    void logBreaks(const BondIndex &b);
    void contactOf(size_t tp, int i, int j, int *touch, double *history, bool advance, bool touching,
                   const double *del, double rsq);
    void checkIndex();
    void trimToReach();
    std::string checkNear() const;

    std::vector<TypePair> pairs_;
    std::vector<GbVoigtModel *> voigt_;
    std::vector<GbBondModel *> bond_;
    std::vector<char> createsNow_;          // per type pair, this pass (compute)
    std::vector<GbTypeBodies> bodies_;      // per type, over all ranks, at the latest run start
    std::vector<double> transferSign_;      // per history slot: +1 copy, -1 negate
    GbRecordLayout layout_;                 // the core's record: contact, bond, bond loads
    std::vector<BondIndex> index_;          // per type pair: its intact bonds (bond_index.h)
    std::vector<size_t> formed_;            // per type pair: where this pass's new bonds start in index_
    // The pairs of the engine's list the contact loop visits while the list
    // stands (trimToReach): for list position ii, the neighbour slots
    // near_[nearFirst_[ii] .. nearFirst_[ii + 1]).
    std::vector<int> nearFirst_, near_;
    LAMMPS_NS::bigint nearBuilt_ = -1;      // neighbor->ncalls when near_ was built
    // per list position: how many of the atom's visited pairs are not
    // intact bonds (contacts, pairs that may bond, bonds broken since the
    // build); per owned atom: its list position
    std::vector<int> nearLive_;
    std::vector<int> nearAt_;
    bool writtenBack_ = false;              // since the index was built (writeBackBonds)
    bool checkIndex_;                       // GRANBOND_CHECK_INDEX: recount the index after each pass
    int sizeHistory_;
    bool anyBond_;
    LAMMPS_NS::FixNeighHistory *fixHistory_;
    FixGranbondAtoms *atoms_;               // which atoms bonds have seen (bonded runs)
    std::string message_;                   // outlives error->one's use
    LAMMPS_NS::bigint checkedNatoms_;       // atom count of the latest checks
    LAMMPS_NS::bigint firstStep_;           // where the first run started
    TimestepWarning contactWarning_, bondWarning_;
    SaidOnce said_;
    // bonds created and broken on this rank (each pair once), broken by
    // mode (distance, tension, compression, shear), vanished (rank 0), and
    // whether this pass ends with a count of the bonds that vanished
    // (countVanished)
    long long created_, broken_, brokenBy_[4], vanished_;
    bool lossCheck_;
    BondBalance balance_;
    std::vector<BreakEvent> breaks_;
    LAMMPS_NS::bigint passStep_ = -1;       // step and atom count (local + ghost) of the latest pass
    LAMMPS_NS::bigint passAtoms_ = -1;
};

}
}

#endif
