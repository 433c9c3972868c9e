#include "bond_nonlinear_parameters.h"
#include "core_bridge.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

namespace {

const char *const kCaller = "cohesion bond/nonlinear";

// Which switch setting makes a property required; the others are ignored
// even when a deck defines them (decks written for LIGGGHTS-INL do).
enum Need { ALWAYS, DAMPING, DISTANCE_MODE, STRESS_MODE, STRESS_RATIO };

struct PerTypePairProperty {
    const char *name;               // fix property/global name, as in LIGGGHTS-INL
    double GbBondParams::*field;
    Need need;
};

const PerTypePairProperty kProperties[] = {
    {"radiusMultiplierBondnonlinear", &GbBondParams::lambda, ALWAYS},
    {"stiffnessPerUnitAreaK_fn1", &GbBondParams::k_fn1, ALWAYS},
    {"stiffnessPerUnitAreaKu_fn1", &GbBondParams::ku_fn1, ALWAYS},
    {"stiffnessPerUnitAreaKc_fn1", &GbBondParams::kc_fn1, ALWAYS},
    {"stiffnessPerUnitAreaK_fn2", &GbBondParams::k_fn2, ALWAYS},
    {"stiffnessPerUnitAreaKu_fn2", &GbBondParams::ku_fn2, ALWAYS},
    {"stiffnessPerUnitAreaKc_fn2", &GbBondParams::kc_fn2, ALWAYS},
    {"stiffnessPerUnitAreaK_ft", &GbBondParams::k_ft, ALWAYS},
    {"stiffnessPerUnitAreaK_tn", &GbBondParams::k_tn, ALWAYS},
    {"stiffnessPerUnitAreaKu_tn", &GbBondParams::ku_tn, ALWAYS},
    {"stiffnessPerUnitAreaKc_tn", &GbBondParams::kc_tn, ALWAYS},
    {"stiffnessPerUnitAreaK_tt", &GbBondParams::k_tt, ALWAYS},
    {"stiffnessPerUnitAreaKu_tt", &GbBondParams::ku_tt, ALWAYS},
    {"stiffnessPerUnitAreaKc_tt", &GbBondParams::kc_tt, ALWAYS},
    {"createDistanceBondnonlinear", &GbBondParams::create_distance, ALWAYS},
    {"dampingNormalForceBondnonlinear", &GbBondParams::eta_fn, DAMPING},
    {"dampingTangentialForceBondnonlinear", &GbBondParams::eta_ft, DAMPING},
    {"dampingNormalTorqueBondnonlinear", &GbBondParams::eta_tn, DAMPING},
    {"dampingTangentialTorqueBondnonlinear", &GbBondParams::eta_tt, DAMPING},
    {"maxDistanceBondnonlinear", &GbBondParams::max_distance, DISTANCE_MODE},
    {"maxSigmaBondnonlinear", &GbBondParams::max_sigma, STRESS_MODE},
    {"maxTauBondnonlinear", &GbBondParams::max_tau, STRESS_MODE},
    {"ratioTensionCompressionBondnonlinear", &GbBondParams::tension_compression_ratio, STRESS_RATIO},
};
const size_t kPropertyCount = sizeof(kProperties) / sizeof(kProperties[0]);

const char *const kCreateStep = "tsCreateBondnonlinear";   // scalar

// The engine's registry takes a plain function per property name.
template<size_t N>
MatrixProperty *createPerTypePair(PropertyRegistry &registry, const char *caller, bool)
{
    return MODEL_PARAMS::createPerTypePairProperty(registry, kProperties[N].name, caller);
}

template<size_t... N>
std::array<MatrixPropertyCreator, sizeof...(N)> perTypePairCreators(std::index_sequence<N...>)
{
    return {{&createPerTypePair<N>...}};
}

const std::array<MatrixPropertyCreator, kPropertyCount> kCreators =
    perTypePairCreators(std::make_index_sequence<kPropertyCount>());

ScalarProperty *createCreateStep(PropertyRegistry &registry, const char *caller, bool)
{
    return MODEL_PARAMS::createScalarProperty(registry, kCreateStep, caller);
}

int32_t onOff(bool b) { return b ? 1 : 0; }

}

BondNonlinearParameters::BondNonlinearParameters(LAMMPS_NS::LAMMPS *lmp) :
    Pointers(lmp),
    stressBreak_(false), tension_(true), compression_(true), shear_(true), twist_(true), bend_(true),
    createAlways_(false), damping_(true), dampingSmooth_(false), useRatio_(false), historyReset_(false),
    perTypePair_(kPropertyCount, static_cast<double **>(0)), createStep_(0.0), ntypes_(0)
{
}

BondNonlinearParameters::~BondNonlinearParameters() { freeModels(); }

void BondNonlinearParameters::freeModels()
{
    for (size_t k = 0; k < models_.size(); k++) granbond_bond_model_free(models_[k]);
    models_.clear();
    ntypes_ = 0;
}

void BondNonlinearParameters::registerSettings(Settings &settings)
{
    settings.registerOnOff("stressBreak", stressBreak_, false);
    settings.registerOnOff("tensionStress", tension_, true);
    settings.registerOnOff("compressionStress", compression_, true);
    settings.registerOnOff("shearStress", shear_, true);
    settings.registerOnOff("normalTorqueStress", twist_, true);
    settings.registerOnOff("shearTorqueStress", bend_, true);
    settings.registerOnOff("createBondAlways", createAlways_, false);
    settings.registerOnOff("dampingBond", damping_, true);
    settings.registerOnOff("dampingBondSmooth", dampingSmooth_, false);
    settings.registerOnOff("ratioTensionCompressionBond", useRatio_, false);
    settings.registerOnOff("historyReset", historyReset_, false);
}

void BondNonlinearParameters::connectPerTypePair(PropertyRegistry &registry, size_t index)
{
    registry.registerProperty(kProperties[index].name, kCreators[index]);
    registry.connect(kProperties[index].name, perTypePair_[index], kCaller);
}

void BondNonlinearParameters::connectToProperties(PropertyRegistry &registry)
{
    // smoothing is a kind of damping (as in the reference)
    if (dampingSmooth_) damping_ = true;

    for (size_t k = 0; k < kPropertyCount; k++) {
        perTypePair_[k] = 0;
        bool wanted = false;
        switch (kProperties[k].need) {
        case ALWAYS: wanted = true; break;
        case DAMPING: wanted = damping_; break;
        case DISTANCE_MODE: wanted = !stressBreak_; break;
        case STRESS_MODE: wanted = stressBreak_; break;
        case STRESS_RATIO: wanted = stressBreak_ && useRatio_; break;
        }
        if (wanted) connectPerTypePair(registry, k);
    }
    createStep_ = 0.0;
    if (!createAlways_) {
        registry.registerProperty(kCreateStep, &createCreateStep);
        registry.connect(kCreateStep, createStep_, kCaller);
    }

    buildModels(registry);
    registerContactDistanceFactor(registry);
}

void BondNonlinearParameters::buildModels(PropertyRegistry &registry)
{
    freeModels();
    const int ntypes = registry.max_type();
    models_.assign((ntypes + 1) * (ntypes + 1), static_cast<GbBondModel *>(0));
    ntypes_ = ntypes;

    for (int a = 1; a <= ntypes; a++)
        for (int b = 1; b <= ntypes; b++) {
            GbBondParams p;
            granbond_bond_params_default(&p);
            for (size_t k = 0; k < kPropertyCount; k++)
                if (perTypePair_[k]) p.*(kProperties[k].field) = perTypePair_[k][a][b];
            // the reference truncates the step number to an int
            p.create_step = static_cast<int64_t>(createStep_);
            p.stress_break = onOff(stressBreak_);
            p.use_ratio = onOff(useRatio_);
            p.create_always = onOff(createAlways_);
            p.history_reset = onOff(historyReset_);
            p.damping = onOff(damping_);
            p.damping_smooth = onOff(dampingSmooth_);
            p.tension = onOff(tension_);
            p.compression = onOff(compression_);
            p.shear = onOff(shear_);
            p.twist = onOff(twist_);
            p.bend = onOff(bend_);

            GbBondModel *m = 0;
            if (granbond_bond_model_new(&p, &m) != GB_STATUS_OK) {
                endRun(error, FLERR, std::string(kCaller) + " (atom types " + std::to_string(a) + " and " +
                                         std::to_string(b) + "): " + granbond_last_error_message());
            }
            models_[a * (ntypes + 1) + b] = m;
        }
}

// A bond stays intact up to a centre distance the neighbour lists must keep;
// the engine takes it as a multiple of the contact distance.
void BondNonlinearParameters::registerContactDistanceFactor(PropertyRegistry &registry)
{
    const double minRadius = registry.min_radius();
    if (!(minRadius > 0.0))
        error->all(FLERR, "cohesion bond/nonlinear: the smallest particle radius is not known or not positive; "
                          "define the particles (or their templates) before the first run");
    const char *limit = stressBreak_ ? "maxSigmaBondnonlinear (or raise stiffnessPerUnitAreaK_fn2)"
                                     : "maxDistanceBondnonlinear";
    double factor = 1.0;
    for (int a = 1; a <= ntypes_; a++)
        for (int b = 1; b <= ntypes_; b++) {
            double f = 0.0;
            if (granbond_bond_contact_distance_factor(model(a, b), minRadius, &f) != GB_STATUS_OK) {
                endRun(error, FLERR, std::string(kCaller) + ": " + granbond_last_error_message());
            }
            char msg[640];
            if (!std::isfinite(f)) {
                snprintf(msg, sizeof msg,
                         "%s: bonds of atom types %d and %d never break by stretching, so no neighbour list "
                         "can keep them; set a finite %s%s", kCaller, a, b, limit,
                         stressBreak_ ? " and keep tensionStress on" : "");
                endRun(error, FLERR, msg);
            }
            if (f > 10.0) {
                snprintf(msg, sizeof msg,
                         "%s: bonds of atom types %d and %d stretch up to %g x particle diameter (neighbour "
                         "reach, +10%%), exceeding 10 x particle diameter; please reduce %s", kCaller, a, b, f,
                         limit);
                endRun(error, FLERR, msg);
            }
            if (f > factor) factor = f;
        }
    neighbor->register_contact_dist_factor(factor);
}

}
}
