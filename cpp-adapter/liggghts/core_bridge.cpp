#include "core_bridge.h"
#include "core_message.h"
#include "error_line.h"

#include <cstdio>
#include <string>

namespace granbond {
namespace liggghts {

namespace {
std::string &lastMessage()
{
    static std::string message;
    return message;
}
}

LAMMPS_NS::Fix *fixOrNew(LAMMPS_NS::LAMMPS *lmp, const char *id, const char *style)
{
    LAMMPS_NS::Modify *modify = lmp->modify;
    int ifix = modify->find_fix(id);
    if (ifix < 0) {
        char idArg[64], group[] = "all", styleArg[64];
        std::snprintf(idArg, sizeof idArg, "%s", id);
        std::snprintf(styleArg, sizeof styleArg, "%s", style);
        char *args[] = {idArg, group, styleArg};
        modify->add_fix(3, args);
        ifix = modify->find_fix(id);
    }
    return ifix < 0 ? 0 : modify->fix[ifix];
}

void endRun(LAMMPS_NS::Error *error, const char *file, int line, const std::string &message)
{
    lastMessage() = message;
    error->all(file, line, lastMessage().c_str());
}

void endRunOnThisRank(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
    lastMessage() = message;
    flushErrorLine(lmp, message + " (" + file + ":" + std::to_string(line) + ")");
    lmp->error->one(file, line, lastMessage().c_str());
}

void checkCoreLayout(LAMMPS_NS::Error *error)
{
    // Filled in this translation unit by the header, so it records the sizes
    // this adapter was compiled with.
    GbLayout expected = granbond_header_layout();
    if (granbond_check_layout(&expected) != GB_STATUS_OK) {
        endRun(error, FLERR, std::string("granbond: the adapter was built against another granbond.h than "
                                         "the core it links: ") + coreReason());
    }
}

int registerStateSlots(LIGGGHTS::IContactHistorySetup *hsetup, GbStateKind kind, LAMMPS_NS::Error *error)
{
    return registerStateSlots(hsetup, kind, error, 0, granbond_state_len(kind), "");
}

int registerStateSlots(LIGGGHTS::IContactHistorySetup *hsetup, GbStateKind kind, LAMMPS_NS::Error *error,
                       size_t first, size_t count, const char *prefix)
{
    int offset = -1;
    for (size_t k = first; k < first + count; k++) {
        const char *name = 0;
        int32_t flips = 0;
        if (granbond_state_slot(kind, k, &name, &flips) != GB_STATUS_OK) {
            endRun(error, FLERR, std::string("granbond: ") + coreReason());
        }
        // "1": the engine negates the value when the pair is seen from the other atom
        const int at = hsetup->add_history_value(std::string(prefix) + name, flips ? "1" : "0");
        if (k == first) offset = at;
    }
    return offset;
}

size_t slotNamed(GbStateKind kind, const char *name, LAMMPS_NS::Error *error)
{
    const size_t n = granbond_state_len(kind);
    for (size_t k = 0; k < n; k++) {
        const char *slot = 0;
        int32_t flips = 0;
        if (granbond_state_slot(kind, k, &slot, &flips) == GB_STATUS_OK && std::string(slot) == name) return k;
    }
    endRun(error, FLERR, std::string("granbond: the core's state kind ") + std::to_string(static_cast<int>(kind)) +
                             " has no slot " + name);
    return 0;
}

}
}
