// Instantiates one GranStyle<normal, tangential, cohesion, rolling, surface>
// for pairs and walls and adds it to the engine's factories under the style
// hash the engine computes from `pair_style gran` / `fix wall/gran` words.
#ifndef GRANBOND_LIGGGHTS_REGISTER_COMBINATION_H
#define GRANBOND_LIGGGHTS_REGISTER_COMBINATION_H

#include "liggghts_engine.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"
#include "combination_check.h"
#include "deck_words.h"

#include <string>

namespace granbond {
namespace liggghts {

// The engine's pair and wall styles of a combination, whose settings words
// are checked before the engine's parser reads them (deck_words.h).
template<class Model>
class CheckedPair : public LIGGGHTS::PairStyles::Granular<Model> {
public:
    CheckedPair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash) :
        LIGGGHTS::PairStyles::Granular<Model>(lmp, parent, hash), lmp_(lmp)
    {}
    void settings(int nargs, char **args, LIGGGHTS::IContactHistorySetup *hsetup)
    {
        checkSettingsWords(lmp_, "pair_style gran", nargs, args);
        LIGGGHTS::PairStyles::Granular<Model>::settings(nargs, args, hsetup);
    }

private:
    LAMMPS_NS::LAMMPS *lmp_;
};

template<class Model>
class CheckedWall : public LIGGGHTS::Walls::Granular<Model> {
public:
    CheckedWall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash) :
        LIGGGHTS::Walls::Granular<Model>(lmp, parent, hash), lmp_(lmp), command_(std::string("fix ") + parent->id + " wall/gran")
    {}
    void settings(int nargs, char **args, LIGGGHTS::IContactHistorySetup *hsetup)
    {
        checkSettingsWords(lmp_, command_, nargs, args);
        LIGGGHTS::Walls::Granular<Model>::settings(nargs, args, hsetup);
    }

private:
    LAMMPS_NS::LAMMPS *lmp_;
    std::string command_;
};

template<class T>
LIGGGHTS::PairStyles::IGranularPairStyle *makePair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *parent, int64_t hash)
{ return new T(lmp, parent, hash); }

template<class T>
LIGGGHTS::Walls::IGranularWall *makeWall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *parent, int64_t hash)
{ return new T(lmp, parent, hash); }

template<int N, int T, int C, int R, int S>
void registerCombination()
{
    using namespace LIGGGHTS;
    typedef ContactModels::GranStyle<N, T, C, R, S> Style;
    typedef ContactModels::ContactModel<Style> Model;
    PairStyles::Factory::instance().addStyle("gran", Style::HASHCODE, &makePair<CheckedPair<Model> >);
    Walls::Factory::instance().addStyle("gran", Style::HASHCODE, &makeWall<CheckedWall<Model> >);
    noteRegisteredCombination(Style::HASHCODE);
}

}
}

#endif
