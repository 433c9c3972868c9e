// Instantiates one GranStyle<normal, tangential, cohesion, rolling, surface>
// for pairs and walls and adds it to the engine's factories under the style
// hash the engine computes from `pair_style gran` / `fix wall/gran` words.
#ifndef GRANBOND_LIGGGHTS_REGISTER_COMBINATION_H
#define GRANBOND_LIGGGHTS_REGISTER_COMBINATION_H

#include "liggghts_engine.h"
#include "pair_gran_base.h"
#include "fix_wall_gran_base.h"
#include "combination_check.h"

namespace granbond {
namespace liggghts {

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
    PairStyles::Factory::instance().addStyle("gran", Style::HASHCODE, &makePair<PairStyles::Granular<Model> >);
    Walls::Factory::instance().addStyle("gran", Style::HASHCODE, &makeWall<Walls::Granular<Model> >);
    noteRegisteredCombination(Style::HASHCODE);
}

}
}

#endif
