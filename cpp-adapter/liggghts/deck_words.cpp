#include "deck_words.h"
#include "core_bridge.h"
#include "core_message.h"
#include "granbond.h"

#include "fix_property_global.h"
#include "modify.h"

#include <cstring>
#include <string>
#include <vector>

namespace granbond {
namespace liggghts {

namespace {

StyleCreator &engineCreator()
{
    static StyleCreator creator = nullptr;
    return creator;
}

// The spelling of infinity the engine's number reader takes (it refuses
// "inf"; "1e999" passes its character check and reads as infinity).
char kInfinity[] = "1e999";

LAMMPS_NS::Fix *checkedPropertyGlobal(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg)
{
    // the core checks the line of a granbond property (not others)
    std::vector<int32_t> infinite(static_cast<size_t>(narg), 0);
    int32_t ours = 0;
    if (granbond_liggghts_property_line_check(arg, static_cast<size_t>(narg), infinite.data(), &ours) != GB_STATUS_OK)
        endRun(lmp->error, FLERR, coreReason());
    if (ours) {
        for (int k = 0; k < narg; k++)
            if (infinite[k]) arg[k] = kInfinity;
        // a second line for the same property: the engine would refuse it
        // without naming the property, or keep one of the two silently
        const char *style = std::strcmp(arg[4], "scalar") == 0 ? "scalar" : "peratomtypepair";
        for (int i = 0; i < lmp->modify->nfix; i++) {
            LAMMPS_NS::FixPropertyGlobal *f = dynamic_cast<LAMMPS_NS::FixPropertyGlobal *>(lmp->modify->fix[i]);
            if (f && std::strcmp(f->id, arg[0]) != 0 && f->check_fix(arg[3], style, 0, 0, "granbond", false))
                endRun(lmp->error, FLERR, std::string("fix ") + arg[0] + " property/global " + arg[3] + ": " + arg[3] +
                                              " is already defined by fix " + f->id +
                                              "; define each property once (unfix " + f->id + " first to replace it)");
        }
    }
    return engineCreator()(lmp, narg, arg);
}

}

void checkSettingsWords(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int nargs, char **args)
{
    if (granbond_liggghts_settings_check(command.c_str(), args, static_cast<size_t>(nargs)) != GB_STATUS_OK)
        endRun(lmp->error, FLERR, coreReason());
}

void checkPropertyLines(std::map<std::string, StyleCreator> &fixes)
{
    StyleCreator &slot = fixes["property/global"];
    if (slot == &checkedPropertyGlobal || !slot) return;
    engineCreator() = slot;
    slot = &checkedPropertyGlobal;
}

}
}
