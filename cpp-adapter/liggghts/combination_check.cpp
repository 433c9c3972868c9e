// An unregistered combination that names a granbond model ends with an error
// listing the combinations that exist, instead of the engine's generic
// fallback failing with `Unknown cohesion model`.
//
// How (no LIGGGHTS rebuild): `pair_style gran` and `fix wall/gran` turn the
// model words into a style hash through the variant selector registered for
// "gran". We replace that selector with one that calls the engine's own
// (ContactModels::Factory::select) and, if the hash holds one of our model ids
// but was not registered, returns a sentinel hash whose creator ends the run
// with the list. Combinations of stock models only are left to the engine.
//
// The engine (re-)registers its selector in every LAMMPS constructor
// (RegisterGranularStyles), after our global constructor has run, so the
// replacement has to happen later: the launcher does it right after
// constructing LAMMPS; with LD_PRELOAD the first bond model constructed does
// it, which covers every later pair_style / fix wall/gran but not the first.
#include "combination_check.h"
#include "core_bridge.h"
#include "granbond_models.h"   // generated: GRANBOND_MODEL_LIST

#include <iostream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace granbond {
namespace liggghts {

namespace {

using namespace LIGGGHTS;
using namespace LIGGGHTS::ContactModels;

enum Axis { NORMAL, TANGENTIAL, COHESION, ROLLING, SURFACE, AXES };
const char *const kAxisWord[AXES] = {"model", "tangential", "cohesion", "rolling_friction", "surface"};

// every combination hash this library registered
std::set<int64_t> &registered()
{
    static std::set<int64_t> s;
    return s;
}

int64_t &requested()
{
    static int64_t h = 0;
    return h;
}

// All bits set in every field: no model uses id 63.
const int64_t kSentinel = (int64_t(63)) | (int64_t(63) << 6) | (int64_t(63) << 12) | (int64_t(63) << 18) |
                          (int64_t(63) << 24);

int field(int64_t hash, int axis) { return static_cast<int>((hash >> (6 * axis)) & 63); }

// id -> deck name, per axis: the stock models (from the installed headers,
// as the engine's own tables) and ours
struct Names {
    std::map<int, std::string> byId[AXES];
    std::set<int> ours[AXES];
    Names()
    {
        byId[NORMAL][NORMAL_OFF] = "off";
        byId[TANGENTIAL][TANGENTIAL_OFF] = "off";
        byId[COHESION][COHESION_OFF] = "off";
        byId[ROLLING][ROLLING_OFF] = "off";
#define SURFACE_MODEL(identifier, str, constant) byId[SURFACE][constant] = #str;
#include "style_surface_model.h"
#undef SURFACE_MODEL
#define NORMAL_MODEL(identifier, str, constant) byId[NORMAL][constant] = #str;
#include "style_normal_model.h"
#undef NORMAL_MODEL
#define TANGENTIAL_MODEL(identifier, str, constant) byId[TANGENTIAL][constant] = #str;
#include "style_tangential_model.h"
#undef TANGENTIAL_MODEL
#define COHESION_MODEL(identifier, str, constant) byId[COHESION][constant] = #str;
#include "style_cohesion_model.h"
#undef COHESION_MODEL
#define ROLLING_MODEL(identifier, str, constant) byId[ROLLING][constant] = #str;
#include "style_rolling_model.h"
#undef ROLLING_MODEL
#define GRANBOND_MODEL(kind, name, constant) add(#kind, name, constant);
        GRANBOND_MODEL_LIST
#undef GRANBOND_MODEL
    }
    void add(const std::string &kind, const char *name, int id)
    {
        const int axis = kind == "Normal" ? NORMAL
                       : kind == "Tangential" ? TANGENTIAL
                       : kind == "Cohesion" ? COHESION
                       : kind == "Rolling" ? ROLLING
                                           : SURFACE;
        byId[axis][id] = name;
        ours[axis].insert(id);
    }
    std::string name(int axis, int id) const
    {
        std::map<int, std::string>::const_iterator it = byId[axis].find(id);
        return it != byId[axis].end() ? it->second : "#" + std::to_string(id);
    }
};

const Names &names()
{
    static const Names n;
    return n;
}

bool namesOurModel(int64_t hash)
{
    for (int a = 0; a < AXES; a++)
        if (names().ours[a].count(field(hash, a))) return true;
    return false;
}

std::string describe(const std::vector<std::set<int> > &c)
{
    std::string s;
    for (int a = 0; a < AXES; a++) {
        s += std::string(a ? " " : "") + kAxisWord[a] + " ";
        bool first = true;
        for (int id : c[a]) {
            s += (first ? "" : "|") + names().name(a, id);
            first = false;
        }
    }
    return s;
}

// The registered hashes as few Cartesian products as a greedy merge finds.
std::vector<std::vector<std::set<int> > > compactList()
{
    typedef std::vector<std::set<int> > Product;
    std::vector<Product> list;
    for (int64_t h : registered()) {
        Product p(AXES);
        for (int a = 0; a < AXES; a++) p[a].insert(field(h, a));
        list.push_back(p);
    }
    const int order[AXES] = {ROLLING, NORMAL, TANGENTIAL, COHESION, SURFACE};
    for (int round = 0; round < 2; round++)
        for (int axis : order) {
            std::map<std::vector<std::set<int> >, std::set<int> > merged;
            for (const Product &p : list) {
                Product key = p;
                key[axis].clear();
                merged[key].insert(p[axis].begin(), p[axis].end());
            }
            list.clear();
            for (auto &kv : merged) {
                Product p = kv.first;
                p[axis] = kv.second;
                list.push_back(p);
            }
        }
    return list;
}

std::string unsupportedMessage()
{
    const int64_t h = requested();
    std::vector<std::set<int> > asked(AXES);
    for (int a = 0; a < AXES; a++) asked[a].insert(field(h, a));
    std::string msg = "granbond: the model combination '" + describe(asked) +
                      "' is not registered (cpp-adapter/liggghts/models.txt). Registered for pair_style gran "
                      "and fix wall/gran:";
    for (const std::vector<std::set<int> > &p : compactList()) msg += "\n  " + describe(p);
    return msg;
}

PairStyles::IGranularPairStyle *unsupportedPair(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::PairGran *, int64_t)
{
    endRun(lmp->error, FLERR, unsupportedMessage());
    return 0;
}

Walls::IGranularWall *unsupportedWall(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixWallGran *, int64_t)
{
    endRun(lmp->error, FLERR, unsupportedMessage());
    return 0;
}

int64_t selectChecked(int &argc, char **&argv, LAMMPS_NS::Custom_contact_models ccm)
{
    const int64_t hash = ContactModels::Factory::select(argc, argv, ccm);
    if (namesOurModel(hash) && !registered().count(hash)) {
        requested() = hash;
        return kSentinel;
    }
    return hash;
}

}

void noteRegisteredCombination(int64_t hash) { registered().insert(hash); }

void installCombinationCheck()
{
    // Replacing the engine's selector (and our own entries, on a second
    // call) prints collision notices on stderr, which are expected here.
    std::streambuf *err = std::cerr.rdbuf(0);
    PairStyles::Factory::instance().addStyle("gran", static_cast<int>(kSentinel), &unsupportedPair);
    Walls::Factory::instance().addStyle("gran", static_cast<int>(kSentinel), &unsupportedWall);
    PairStyles::Factory::instance().addVariantSelector("gran", &selectChecked);
    Walls::Factory::instance().addVariantSelector("gran", &selectChecked);
    std::cerr.rdbuf(err);
}

}
}
