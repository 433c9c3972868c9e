#include "voigt_deck.h"

#include "force.h"
#include "core_bridge.h"
#include "core_message.h"

#include <array>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

using namespace LIGGGHTS::ContactModels;

namespace granbond {
namespace liggghts {

// ------------------------------------------------------------ model table

void VoigtModelTable::build(LAMMPS_NS::Error *error, const char *who, int ntypes,
                            const std::vector<GbVoigtParams> &params)
{
    checkCoreLayout(error);
    clear();
    stride_ = ntypes + 1;
    models_.assign(stride_ * stride_, static_cast<GbVoigtModel *>(0));
    for (int a = 1; a <= ntypes; a++)
        for (int b = 1; b <= ntypes; b++) {
            GbVoigtModel *model = 0;
            if (granbond_voigt_model_new(&params[a * stride_ + b], &model) != GB_STATUS_OK) {
                const std::string msg = std::string(who) + " (atom types " + std::to_string(a) + " and " +
                                        std::to_string(b) + "): " + coreReason();
                clear();
                endRun(error, FLERR, msg);
            }
            models_[a * stride_ + b] = model;
        }
}

void VoigtModelTable::clear()
{
    for (size_t k = 0; k < models_.size(); k++)
        granbond_voigt_model_free(models_[k]);
    models_.clear();
}

namespace {

// The core's Voigt table, row by row, with the part of the contact each
// row belongs to.
struct VoigtRow {
    GbParameterInfo info;
    GbContactPart part;
};

const std::vector<VoigtRow> &voigtRows()
{
    static const std::vector<VoigtRow> rows = [] {
        std::vector<VoigtRow> r;
        VoigtRow row;
        for (size_t id = 0; granbond_voigt_parameter_info(id, &row.info) == GB_STATUS_OK; id++) {
            if (granbond_voigt_parameter_part(id, &row.part) != GB_STATUS_OK) std::abort();   // id < rows, read
            r.push_back(row);
        }
        return r;
    }();
    return rows;
}

// The engine's registry takes a plain function per property, so there is
// one creator per row id of the core's table, reading the row's name.
const size_t kMaxRows = 32;

template<size_t N>
MatrixProperty *createRow(PropertyRegistry &registry, const char *caller, bool)
{
    return MODEL_PARAMS::createPerTypePairProperty(registry, voigtRows()[N].info.liggghts_name, caller);
}

template<size_t... N>
std::array<MatrixPropertyCreator, sizeof...(N)> rowCreators(std::index_sequence<N...>)
{
    return {{&createRow<N>...}};
}

const std::array<MatrixPropertyCreator, kMaxRows> kRowCreators = rowCreators(std::make_index_sequence<kMaxRows>());

bool in(unsigned parts, GbContactPart part) { return (parts & partBit(part)) != 0; }

void set(LAMMPS_NS::Error *error, const std::string &caller, GbVoigtParams &p, const GbParameterInfo &info,
         double value)
{
    if (granbond_voigt_params_set(&p, info.keyword, value) != GB_STATUS_OK)
        endRun(error, FLERR, caller + ": " + coreReason());
}

// Writes the switches that say a part is present into `p`.
void setPresentParts(LAMMPS_NS::Error *error, const char *caller, GbVoigtParams &p, unsigned present)
{
    for (const VoigtRow &r : voigtRows())
        if (r.info.kind == GB_PARAMETER_KIND_SWITCH && r.info.liggghts_source == GB_LIGGGHTS_SOURCE_FIXED)
            set(error, caller, p, r.info, in(present, r.part) ? 1.0 : 0.0);
}

std::map<const void *, VoigtContactShare *> &shares()
{
    static std::map<const void *, VoigtContactShare *> all;
    return all;
}

}

// ------------------------------------------------------------ deck

VoigtContactShare::VoigtContactShare() :
    frame(),
    normal(false),
    tangential_offset(-1),
    rolling_offset(-1),
    users_(0),
    stride_(0),
    settingRegistered_(false),
    goesOnUnderBond_(false),
    bondStatus_(-1),
    bondedFlag_(-1),
    values_(voigtRows().size(), static_cast<double **>(0))
{
    // a switch no sub-model registers keeps the core's default
    for (const VoigtRow &r : voigtRows()) switches_.push_back(r.info.default_value != 0.0);
}

void VoigtContactShare::registerSettings(::Settings &settings, unsigned owns)
{
    const std::vector<VoigtRow> &rows = voigtRows();
    for (size_t k = 0; k < rows.size(); k++)
        if (in(owns, rows[k].part) && rows[k].info.liggghts_source == GB_LIGGGHTS_SOURCE_SWITCH)
            settings.registerOnOff(rows[k].info.liggghts_name, switches_[k], rows[k].info.default_value != 0.0);
    if (settingRegistered_) return;
    settingRegistered_ = true;
    GbParameterInfo info;
    for (size_t k = 0; granbond_bond_parameter_info(k, &info) == GB_STATUS_OK; k++)
        if (granbond_bond_parameter_sets_creation(k) == 2)
            settings.registerOnOff(info.liggghts_name, goesOnUnderBond_, info.default_value != 0.0);
}

void VoigtContactShare::connect(::PropertyRegistry &registry, const char *caller, unsigned reads)
{
    // LIGGGHTS's own creators scale the stiffness and damping of a
    // coarse-grained deck; the core's table takes the values as written,
    // so such a deck would silently run other physics
    if (registry.getLAMMPS()->force->cg_active())
        endRun(registry.getLAMMPS()->error, FLERR,
               std::string(caller) + ": coarse-graining (the coarsegraining command) is not supported by the voigt "
                                     "sub-models");
    const std::vector<VoigtRow> &rows = voigtRows();
    if (rows.size() > kMaxRows)
        endRun(registry.getLAMMPS()->error, FLERR,
               std::string(caller) + ": the core's Voigt table has more rows than this adapter has property "
                                     "creators (raise kMaxRows)");
    for (size_t k = 0; k < rows.size(); k++) {
        if (!in(reads, rows[k].part) || rows[k].info.liggghts_source != GB_LIGGGHTS_SOURCE_PER_TYPE_PAIR) continue;
        // registry keys of our own, so they cannot meet a stock model's
        // key of the same property with another creator
        const std::string key = std::string("voigt_") + rows[k].info.liggghts_name;
        registry.registerProperty(key, kRowCreators[k]);
        registry.connect(key, values_[k], caller);
    }
}

void VoigtContactShare::fill(LAMMPS_NS::Error *error, const char *caller, GbVoigtParams &p, int a, int b,
                             unsigned parts) const
{
    const std::vector<VoigtRow> &rows = voigtRows();
    const std::string where = std::string(caller) + " (fix property/global, atom types " + std::to_string(a) +
                              " and " + std::to_string(b) + ")";
    for (size_t k = 0; k < rows.size(); k++) {
        if (!in(parts, rows[k].part)) continue;
        if (values_[k]) set(error, where, p, rows[k].info, values_[k][a][b]);
        if (rows[k].info.liggghts_source == GB_LIGGGHTS_SOURCE_SWITCH)
            set(error, caller, p, rows[k].info, switches_[k] ? 1.0 : 0.0);
    }
}

std::vector<GbVoigtParams> VoigtContactShare::params(LAMMPS_NS::Error *error, const char *caller, int ntypes,
                                                     unsigned parts, unsigned present) const
{
    const int stride = ntypes + 1;
    GbVoigtParams defaults;
    granbond_voigt_params_default(&defaults);
    std::vector<GbVoigtParams> all(stride * stride, defaults);
    for (int a = 1; a <= ntypes; a++)
        for (int b = 1; b <= ntypes; b++) {
            fill(error, caller, all[a * stride + b], a, b, parts);
            setPresentParts(error, caller, all[a * stride + b], present);
        }
    return all;
}

void VoigtContactShare::contribute(LAMMPS_NS::Error *error, const char *caller, int ntypes, unsigned parts)
{
    if (ntypes + 1 != stride_) {
        stride_ = ntypes + 1;
        GbVoigtParams defaults;
        granbond_voigt_params_default(&defaults);
        params_.assign(stride_ * stride_, defaults);
    }
    for (int a = 1; a <= ntypes; a++)
        for (int b = 1; b <= ntypes; b++) fill(error, caller, params_[a * stride_ + b], a, b, parts);
    if (!fused()) return;
    const unsigned present = partBit(GB_CONTACT_PART_NORMAL) | partBit(GB_CONTACT_PART_TANGENTIAL) |
                             (fusedRolling() ? partBit(GB_CONTACT_PART_ROLLING) : 0u);
    for (size_t k = 0; k < params_.size(); k++) setPresentParts(error, "voigt contact", params_[k], present);
    table_.build(error, "voigt contact", stride_ - 1, params_);
}

// ------------------------------------------------------------ shared state

void VoigtContactShare::findBond(LIGGGHTS::ContactModels::ContactModelBase *cmb)
{
    bondStatus_ = cmb->get_history_offset("bondnonlinear_status");
    bondedFlag_ = cmb->get_history_offset("bondnonlinear_bonded_flag");
}

void VoigtContactShare::bondSays(const void *owner, bool goesOnUnderBond)
{
    std::map<const void *, VoigtContactShare *>::iterator it = shares().find(owner);
    if (it != shares().end()) it->second->goesOnUnderBond_ = goesOnUnderBond;
}

VoigtContactShare *VoigtContactShare::attach(const void *owner, bool *first)
{
    VoigtContactShare *&share = shares()[owner];
    *first = !share;
    if (!share) share = new VoigtContactShare();
    share->users_++;
    return share;
}

void VoigtContactShare::detach(const void *owner)
{
    std::map<const void *, VoigtContactShare *>::iterator it = shares().find(owner);
    if (it != shares().end() && --it->second->users_ == 0) {
        delete it->second;
        shares().erase(it);
    }
}

}
}
