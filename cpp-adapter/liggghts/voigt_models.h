// `model voigt`, `tangential voigt` and `rolling_friction voigt` as LIGGGHTS
// normal, tangential and rolling models: the template slots the engine's
// GranStyle<> combinations instantiate. Each is VoigtSubModel
// (voigt_contact.h) with its part of the contact; normal models also say
// how the force grows with the overlap.
#ifndef GRANBOND_LIGGGHTS_VOIGT_MODELS_H
#define GRANBOND_LIGGGHTS_VOIGT_MODELS_H

#include "voigt_contact.h"
#include "normal_model_base.h"
#include "tangential_model_base.h"
#include "rolling_model_base.h"
#include "surface_model_default.h"

namespace LIGGGHTS {
namespace ContactModels {

// 6-bit ids of the style hash, one per field; granbond models use ids >= 32.
static const int NORMAL_VOIGT = 40;
static const int TANGENTIAL_VOIGT = 40;
static const int ROLLING_VOIGT = 40;

#define GRANBOND_VOIGT_SLOT(Slot, id, part, extra)                                                             \
    template<>                                                                                                 \
    class Slot<id> : public granbond::liggghts::VoigtSubModel {                                                \
    public:                                                                                                    \
        Slot(LAMMPS *lmp, IContactHistorySetup *hsetup, class ContactModelBase *cmb) :                         \
            VoigtSubModel(lmp, hsetup, cmb, part)                                                              \
        {}                                                                                                     \
        __attribute__((always_inline)) void surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, \
                                                              ForceData &j_forces)                             \
        {                                                                                                      \
            intersect<part>(sidata, i_forces, j_forces);                                                       \
        }                                                                                                      \
        extra                                                                                                  \
    };

GRANBOND_VOIGT_SLOT(NormalModel, NORMAL_VOIGT, GB_CONTACT_PART_NORMAL, double stressStrainExponent() { return 1.0; })
GRANBOND_VOIGT_SLOT(TangentialModel, TANGENTIAL_VOIGT, GB_CONTACT_PART_TANGENTIAL, )
GRANBOND_VOIGT_SLOT(RollingModel, ROLLING_VOIGT, GB_CONTACT_PART_ROLLING, )

#undef GRANBOND_VOIGT_SLOT

// voigt x voigt x (voigt | off), no cohesion, default surface: in a force
// pass the one core call reads the geometry and the engine's velocities
// itself, and nothing else in these combinations reads the relative
// velocities the default surface model derives (vn, wr, vtr, cri, crj), so
// only its overlap is set, by the same expression. Setup and per-contact
// output passes, which tools may inspect, get the full surface model. A
// pair the normal model steps in place (passInPlace) skips the sub-models'
// calls, which would only set their flags and step aside; always inline, as
// the engine's wall loop would otherwise call it rather than inline it.
#define GRANBOND_VOIGT_FUSED_INTERSECT(Rolling, inPlace)                                                       \
    template<>                                                                                                 \
    inline __attribute__((always_inline)) void                                                                 \
    ContactModel<GranStyle<NORMAL_VOIGT, TANGENTIAL_VOIGT, COHESION_OFF, Rolling, SURFACE_DEFAULT> >::            \
        surfacesIntersect(SurfacesIntersectData &sidata, ForceData &i_forces, ForceData &j_forces)            \
    {                                                                                                          \
        if (inPlace && normalModel.passInPlace()) {                                                            \
            sidata.deltan = sidata.radsum - sidata.r;                                                          \
            if (sidata.contact_flags)                                                                          \
                *sidata.contact_flags |= CONTACT_NORMAL_MODEL | CONTACT_TANGENTIAL_MODEL | CONTACT_ROLLING_MODEL; \
            normalModel.stepInPlace(sidata, i_forces, j_forces);                                               \
            return;                                                                                            \
        }                                                                                                      \
        if (sidata.computeflag && sidata.shearupdate)                                                          \
            sidata.deltan = sidata.radsum - sidata.r;                                                          \
        else                                                                                                   \
            surfaceModel.surfacesIntersect(sidata, i_forces, j_forces);                                        \
        normalModel.surfacesIntersect(sidata, i_forces, j_forces);                                             \
        cohesionModel.surfacesIntersect(sidata, i_forces, j_forces);                                           \
        tangentialModel.surfacesIntersect(sidata, i_forces, j_forces);                                         \
        rollingModel.surfacesIntersect(sidata, i_forces, j_forces);                                            \
    }

// only with rolling voigt does the fused state hold the whole contact
GRANBOND_VOIGT_FUSED_INTERSECT(ROLLING_VOIGT, true)
GRANBOND_VOIGT_FUSED_INTERSECT(ROLLING_OFF, false)

#undef GRANBOND_VOIGT_FUSED_INTERSECT

}
}

#endif
