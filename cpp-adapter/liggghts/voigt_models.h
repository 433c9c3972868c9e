// `model voigt`, `tangential voigt` and `rolling_friction voigt` as LIGGGHTS
// normal, tangential and rolling models: the template slots the engine's
// GranStyle<> combinations instantiate. All behaviour lives in VoigtNormal,
// VoigtTangential and VoigtRolling (voigt_contact.cpp, compiled once); this
// only gives them ids.
#ifndef GRANBOND_LIGGGHTS_VOIGT_MODELS_H
#define GRANBOND_LIGGGHTS_VOIGT_MODELS_H

#include "voigt_contact.h"

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit ids of the style hash, one per field; granbond models use ids >= 32.
static const int NORMAL_VOIGT = 40;
static const int TANGENTIAL_VOIGT = 40;
static const int ROLLING_VOIGT = 40;

#define GRANBOND_VOIGT_SLOT(Slot, id, Impl)                                                                    \
    template<>                                                                                             \
    class Slot<id> : public granbond::liggghts::Impl {                                                     \
    public:                                                                                                \
        Slot(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb) : Impl(lmp, hsetup, cmb) \
        {}                                                                                                 \
    };

GRANBOND_VOIGT_SLOT(NormalModel, NORMAL_VOIGT, VoigtNormal)
GRANBOND_VOIGT_SLOT(TangentialModel, TANGENTIAL_VOIGT, VoigtTangential)
GRANBOND_VOIGT_SLOT(RollingModel, ROLLING_VOIGT, VoigtRolling)

#undef GRANBOND_VOIGT_SLOT

}
}

#endif
