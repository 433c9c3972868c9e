#include "bond_nonlinear_parameters.h"
#include "core_message.h"
#include "core_bridge.h"

#include "update.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

namespace {

// The engine's registry takes a plain function per property name, so there
// is one creator per row id of the core's table and model, reading the
// name the model's decks give the row.
const size_t kMaxRows = 64;

GbParameterInfo row(size_t id)
{
    GbParameterInfo info;
    if (granbond_bond_parameter_info(id, &info) != GB_STATUS_OK) std::abort();   // id < count, checked
    return info;
}

// The name decks of the model (`linear`: `cohesion bond`) give row `id`,
// or null when the model does not have the row.
const char *lawName(int linear, size_t id)
{
    const char *name = 0;
    if (granbond_bond_parameter_liggghts_name(linear, id, &name) != GB_STATUS_OK) std::abort();   // id < count
    return name;
}

template<size_t N, int Linear>
MatrixProperty *createPerTypePair(PropertyRegistry &registry, const char *caller, bool)
{
    return MODEL_PARAMS::createPerTypePairProperty(registry, lawName(Linear, N), caller);
}

template<size_t N, int Linear>
ScalarProperty *createScalar(PropertyRegistry &registry, const char *caller, bool)
{
    return MODEL_PARAMS::createScalarProperty(registry, lawName(Linear, N), caller);
}

template<int Linear, size_t... N>
std::array<MatrixPropertyCreator, sizeof...(N)> perTypePairCreators(std::index_sequence<N...>)
{
    return {{&createPerTypePair<N, Linear>...}};
}

template<int Linear, size_t... N>
std::array<ScalarPropertyCreator, sizeof...(N)> scalarCreators(std::index_sequence<N...>)
{
    return {{&createScalar<N, Linear>...}};
}

// [linear][row]
const std::array<MatrixPropertyCreator, kMaxRows> kPerTypePairCreators[2] = {
    perTypePairCreators<0>(std::make_index_sequence<kMaxRows>()),
    perTypePairCreators<1>(std::make_index_sequence<kMaxRows>())};
const std::array<ScalarPropertyCreator, kMaxRows> kScalarCreators[2] = {
    scalarCreators<0>(std::make_index_sequence<kMaxRows>()),
    scalarCreators<1>(std::make_index_sequence<kMaxRows>())};

}

bool BondNonlinearParameters::nextLinear_ = false;

BondNonlinearParameters::BondNonlinearParameters(LAMMPS_NS::LAMMPS *lmp) :
    Pointers(lmp), linear_(nextLinear_), caller_(nextLinear_ ? "cohesion bond" : "cohesion bond/nonlinear"),
    rows_(granbond_bond_parameter_count()), underBondRow_(granbond_bond_parameter_count()), ntypes_(0)
{
    underBondProbe_[0] = false;
    underBondProbe_[1] = true;
    for (size_t k = 0; k < rows_; k++)
        if (granbond_bond_parameter_sets_creation(k) == 2) underBondRow_ = k;
    nextLinear_ = false;
    if (rows_ > kMaxRows)
        error->all(FLERR, (std::string(caller_) + ": the core's parameter table has more rows than this adapter "
                                                  "has property creators (raise kMaxRows)").c_str());
    // the law's defaults (the linear bond's differ), for the switches'
    granbond_bond_params_default_in_units(update->unit_style, linear_, &switches_);
    switchValues_.assign(rows_, false);
    perTypePair_.assign(rows_, static_cast<double **>(0));
    scalars_.assign(rows_, 0.0);
    connectedScalar_.assign(rows_, false);
}

BondNonlinearParameters::~BondNonlinearParameters() { freeModels(); }

void BondNonlinearParameters::freeModels()
{
    for (size_t k = 0; k < models_.size(); k++) granbond_bond_model_free(models_[k]);
    models_.clear();
    ntypes_ = 0;
}

const char *BondNonlinearParameters::name(size_t id) const { return lawName(linear_ ? 1 : 0, id); }

void BondNonlinearParameters::registerSettings(Settings &settings)
{
    for (size_t k = 0; k < rows_; k++) {
        double law = 0.0;
        if (row(k).liggghts_source == GB_LIGGGHTS_SOURCE_SWITCH && name(k) &&
            granbond_bond_params_get(&switches_, k, &law) == GB_STATUS_OK)
            settings.registerOnOff(name(k), switchValues_[k], law != 0.0);
    }
    if (underBondRow_ < rows_ && name(underBondRow_)) {
        settings.registerOnOff(name(underBondRow_), underBondProbe_[0]);
        settings.registerOnOff(name(underBondRow_), underBondProbe_[1]);
        underBondProbe_[0] = false;
        underBondProbe_[1] = true;
    }
}

void BondNonlinearParameters::readSwitches()
{
    granbond_bond_params_default_in_units(update->unit_style, linear_, &switches_);
    for (size_t k = 0; k < rows_; k++) {
        const GbParameterInfo info = row(k);
        if (info.liggghts_source == GB_LIGGGHTS_SOURCE_SWITCH && name(k))
            set(switches_, k, switchValues_[k] ? 1.0 : 0.0, "");
    }
    if (underBondProbe_[0] != underBondProbe_[1]) granbond_bond_params_contact_under_bond_by_law(&switches_);
}

// Stores a deck value in `p`; the core refuses an unknown name or a value
// outside the row's range, naming the parameter.
void BondNonlinearParameters::set(GbBondParams &p, size_t id, double value, const std::string &where)
{
    if (granbond_bond_params_set(&p, row(id).keyword, value) != GB_STATUS_OK)
        endRun(error, FLERR, std::string(caller_) + " " + (name(id) ? name(id) : row(id).keyword) + where + ": " +
                                 coreReason());
}

void BondNonlinearParameters::connectToProperties(PropertyRegistry &registry)
{
    readSwitches();

    // only what the model reads with these switches is asked of the deck;
    // the rest is ignored even when a deck defines it (LIGGGHTS-INL decks do)
    for (size_t k = 0; k < rows_; k++) {
        perTypePair_[k] = 0;
        scalars_[k] = 0.0;
        connectedScalar_[k] = false;
        const GbParameterInfo info = row(k);
        int32_t needed = 0;
        if (granbond_bond_parameter_needed(&switches_, k, &needed) != GB_STATUS_OK)
            endRun(error, FLERR, std::string(caller_) + ": " + coreReason());
        if (!needed) continue;
        // a setting LIGGGHTS-INL does not have: read only where the deck
        // defines it, so INL's decks keep the default and INL's law
        const bool optional = info.liggghts_source == GB_LIGGGHTS_SOURCE_OPTIONAL_PER_TYPE_PAIR;
        if (optional && !modify->find_fix_property(name(k), "property/global", "peratomtypepair", 0, 0,
                                                   caller_, false))
            continue;
        if (info.liggghts_source == GB_LIGGGHTS_SOURCE_PER_TYPE_PAIR || optional) {
            registry.registerProperty(name(k), kPerTypePairCreators[linear_][k]);
            registry.connect(name(k), perTypePair_[k], caller_);
        } else if (info.liggghts_source == GB_LIGGGHTS_SOURCE_SCALAR) {
            registry.registerProperty(name(k), kScalarCreators[linear_][k]);
            registry.connect(name(k), scalars_[k], caller_);
            connectedScalar_[k] = true;
        }
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
            const std::string where = " (atom types " + std::to_string(a) + " and " + std::to_string(b) + ")";
            GbBondParams p = switches_;
            for (size_t k = 0; k < rows_; k++) {
                if (perTypePair_[k]) set(p, k, perTypePair_[k][a][b], where);
                // a step number passes as given: the core refuses a
                // fractional one (INL truncated it, so 0.999 meant step 0)
                if (connectedScalar_[k]) set(p, k, scalars_[k], where);
            }
            GbBondModel *m = 0;
            if (granbond_bond_model_new(&p, &m) != GB_STATUS_OK)
                endRun(error, FLERR, std::string(caller_) + where + ": " + coreReason());
            models_[a * (ntypes + 1) + b] = m;
        }
}

// A bond stays intact up to a centre distance the neighbour lists must keep;
// the engine takes it as a multiple of the contact distance.
void BondNonlinearParameters::registerContactDistanceFactor(PropertyRegistry &registry)
{
    const double minRadius = registry.min_radius();
    if (!(minRadius > 0.0))
        error->all(FLERR, (std::string(caller_) + ": the smallest particle radius is not known or not positive; "
                                                  "define the particles (or their templates) before the first run")
                              .c_str());
    // the core refuses a reach the lists cannot hold, naming what sets it
    double factor = 1.0;
    for (int a = 1; a <= ntypes_; a++)
        for (int b = 1; b <= ntypes_; b++) {
            double f = 0.0;
            if (granbond_bond_neighbour_reach(model(a, b), minRadius, a, b, 1, update->unit_style, &f) != GB_STATUS_OK)
                endRun(error, FLERR, std::string(caller_) + ": " + coreReason());
            if (f > factor) factor = f;
        }
    neighbor->register_contact_dist_factor(factor);
}

}
}
