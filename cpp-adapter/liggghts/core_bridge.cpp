#include "core_bridge.h"

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

void endRun(LAMMPS_NS::Error *error, const char *file, int line, const std::string &message)
{
    lastMessage() = message;
    error->all(file, line, lastMessage().c_str());
}

void endRunOnThisRank(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
    lastMessage() = message;
    // error->one aborts MPI without flushing, so a redirected screen or log
    // would lose the message: write and flush it first
    FILE *streams[2] = {lmp->screen, lmp->logfile};
    for (FILE *s : streams)
        if (s) {
            fprintf(s, "ERROR on proc %d: %s (%s:%d)\n", lmp->comm->me, message.c_str(), file, line);
            fflush(s);
        }
    lmp->error->one(file, line, lastMessage().c_str());
}

// A field added to GbLayout must be filled below.
static_assert(sizeof(GbLayout) == 14 * sizeof(size_t), "GbLayout changed: update checkCoreLayout");

void checkCoreLayout(LAMMPS_NS::Error *error)
{
    GbLayout expected = GbLayout();
    expected.abi_version = GRANBOND_ABI_VERSION;
    expected.layout_size = sizeof(GbLayout);
    expected.bond_params = sizeof(GbBondParams);
    expected.voigt_params = sizeof(GbVoigtParams);
    expected.pair_kinematics = sizeof(GbPairKinematics);
    expected.sphere_kinematics = sizeof(GbSphereKinematics);
    expected.plane = sizeof(GbPlane);
    expected.bond_output = sizeof(GbBondOutput);
    expected.contact_output = sizeof(GbContactOutput);
    expected.contact_frame = sizeof(GbContactFrame);
    expected.tangential_output = sizeof(GbTangentialOutput);
    expected.bond_state_len = GRANBOND_BOND_STATE_LEN;
    expected.wall_bond_state_len = GRANBOND_WALL_BOND_STATE_LEN;
    expected.contact_state_len = GRANBOND_CONTACT_STATE_LEN;
    if (granbond_check_layout(&expected) != GB_STATUS_OK) {
        endRun(error, FLERR, std::string("granbond: the adapter was built against another granbond.h than "
                                         "the core it links: ") + granbond_last_error_message());
    }
}

int registerStateSlots(LIGGGHTS::IContactHistorySetup *hsetup, GbStateKind kind, LAMMPS_NS::Error *error)
{
    const size_t n = granbond_state_len(kind);
    int first = -1;
    for (size_t k = 0; k < n; k++) {
        const char *name = 0;
        int32_t flips = 0;
        if (granbond_state_slot(kind, k, &name, &flips) != GB_STATUS_OK) {
            endRun(error, FLERR, std::string("granbond: ") + granbond_last_error_message());
        }
        // "1": the engine negates the value when the pair is seen from the other atom
        const int offset = hsetup->add_history_value(name, flips ? "1" : "0");
        if (k == 0) first = offset;
    }
    return first;
}

}
}
