// The one place where granbond models enter LIGGGHTS. A global constructor
// runs when this library is loaded (linked into liggghts-granbond, or
// LD_PRELOADed into the stock liggghts) and fills the engine's factories:
// model names -> ids, then every combination listed in models.txt (the
// generated granbond_register_*() functions, one per translation unit).
#include "liggghts_engine.h"
#include "granbond_models.h"          // generated: our model headers
#include "granbond_combinations.h"    // generated: per-TU registration functions
#include <cstdio>
#include <cstdlib>

namespace {

int g_registered = 0;

struct Registrar {
    Registrar()
    {
        using namespace LIGGGHTS::ContactModels;
        Factory &models = Factory::instance();
#define GRANBOND_MODEL(kind, name, constant) models.add##kind##Model(name, constant);
        GRANBOND_MODEL_LIST
#undef GRANBOND_MODEL
        GRANBOND_REGISTER_ALL_COMBINATIONS
        g_registered = GRANBOND_COMBINATION_COUNT;
        if (std::getenv("GRANBOND_DEBUG"))
            std::fprintf(stderr, "granbond: registered %d pair+wall model combinations\n", g_registered);
    }
};

Registrar g_registrar;

}

// Exported (adapter.map): the launcher calls it so the linker keeps this library.
extern "C" __attribute__((visibility("default"))) int granbond_liggghts_registered(void) { return g_registered; }

// Exported: the ABI version of the core linked into this library, for
// `liggghts-granbond --version`.
extern "C" __attribute__((visibility("default"))) unsigned granbond_liggghts_core_abi_version(void)
{
    return granbond_abi_version();
}
