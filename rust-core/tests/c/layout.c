/*
 * ABI version, the layout check, and the description of the state arrays.
 */

#include "harness.h"

struct layout_item {
    const char *message_names;
    size_t offset;
};

int test_version_and_layout(void)
{
    static const struct layout_item items[] = {
        {"sizeof(GbBondParams)", offsetof(GbLayout, bond_params)},
        {"sizeof(GbVoigtParams)", offsetof(GbLayout, voigt_params)},
        {"sizeof(GbPairKinematics)", offsetof(GbLayout, pair_kinematics)},
        {"sizeof(GbSphereKinematics)", offsetof(GbLayout, sphere_kinematics)},
        {"sizeof(GbBondOutput)", offsetof(GbLayout, bond_output)},
        {"sizeof(GbContactOutput)", offsetof(GbLayout, contact_output)},
        {"sizeof(GbContactFrame)", offsetof(GbLayout, contact_frame)},
        {"sizeof(GbTangentialOutput)", offsetof(GbLayout, tangential_output)},
        {"bond state length", offsetof(GbLayout, bond_state_len)},
        {"wall bond state length", offsetof(GbLayout, wall_bond_state_len)},
        {"contact state length", offsetof(GbLayout, contact_state_len)},
    };
    GbLayout l;
    size_t i;

    CHECK(granbond_abi_version() == GRANBOND_ABI_VERSION,
          say("granbond_abi_version() = %u = GRANBOND_ABI_VERSION", (unsigned)granbond_abi_version()));
    CHECK(GRANBOND_WALL_BOND_STATE_LEN == GRANBOND_BOND_STATE_LEN + 3, "wall bond state = bond state + 3");

    l = caller_layout();
    EXPECT_OK(granbond_check_layout(&l), "granbond_check_layout(layout of this header)");

    for (i = 0; i < sizeof items / sizeof items[0]; i++) {
        l = caller_layout();
        *(size_t *)(void *)((char *)&l + items[i].offset) += 8;
        EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH,
               say("granbond_check_layout with a wrong %s", items[i].message_names));
        EXPECT_MESSAGE(items[i].message_names);
    }
    l = caller_layout();
    l.bond_params = sizeof(GbBondParams) - 8;
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout, GbBondParams too small");
    EXPECT_MESSAGE("GbBondParams");
    l = caller_layout();
    l.abi_version = GRANBOND_ABI_VERSION + 1;
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout with a newer abi_version");
    EXPECT_MESSAGE("abi_version");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after a layout mismatch");
    /* A caller whose GbLayout has another size (older or newer header) is
     * refused from the first two fields, before anything else is read. */
    l = caller_layout();
    l.layout_size = sizeof(GbLayout) - sizeof(size_t);
    EXPECT(granbond_check_layout(&l), GB_STATUS_LAYOUT_MISMATCH, "granbond_check_layout, shorter GbLayout");
    EXPECT_MESSAGE("sizeof(GbLayout)");

    return 0;
}

static int expect_slot(int32_t kind, size_t index, const char *name, int32_t flips)
{
    const char *got = NULL;
    int32_t got_flips = -1;
    EXPECT_OK(granbond_state_slot(kind, index, &got, &got_flips), say("granbond_state_slot(%d, %u)", (int)kind,
                                                                      (unsigned)index));
    CHECK(got != NULL && strcmp(got, name) == 0, say("slot %u of kind %d is \"%s\"", (unsigned)index, (int)kind,
                                                     name));
    CHECK(got_flips == flips, say("slot \"%s\" flips_on_swap = %d", name, (int)flips));
    return 0;
}

int test_state_layout(void)
{
    static const int32_t kinds[4] = {GB_STATE_KIND_BOND, GB_STATE_KIND_WALL_BOND, GB_STATE_KIND_CONTACT,
                                     GB_STATE_KIND_BOND_OUTPUT};
    static const size_t lengths[4] = {GRANBOND_BOND_STATE_LEN, GRANBOND_WALL_BOND_STATE_LEN,
                                      GRANBOND_CONTACT_STATE_LEN, GRANBOND_BOND_OUTPUT_LEN};
    const char *name = NULL;
    int32_t flips = 0;
    int k;

    for (k = 0; k < 4; k++)
        CHECK(granbond_state_len(kinds[k]) == lengths[k],
              say("granbond_state_len(%d) = %u", (int)kinds[k], (unsigned)lengths[k]));
    CHECK(granbond_state_len(4) == 0, "granbond_state_len(4) = 0 (unknown kind)");
    CHECK(granbond_state_len(-1) == 0, "granbond_state_len(-1) = 0 (unknown kind)");

    if (expect_slot(GB_STATE_KIND_BOND, 0, "rest", 0) || expect_slot(GB_STATE_KIND_BOND, 1, "delta_max", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 2, "delta_min", 0) || expect_slot(GB_STATE_KIND_BOND, 3, "shear_force_x", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 11, "bend_angle_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 12, "twist_max", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 13, "twist_min", 0) ||
        expect_slot(GB_STATE_KIND_BOND, 14, "bend_history_x", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 16, "bend_history_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND, 17, "bend_opposite", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 0, "rest", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 18, "partner_x", 0) ||
        expect_slot(GB_STATE_KIND_WALL_BOND, 20, "partner_z", 0) ||
        expect_slot(GB_STATE_KIND_CONTACT, 0, "tangential_spring_x", 1) ||
        expect_slot(GB_STATE_KIND_CONTACT, 5, "rolling_angle_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 0, "bond_force_x", 1) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 2, "bond_force_z", 1) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 3, "bond_torque_1_x", 0) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 5, "bond_torque_1_z", 0) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 6, "bond_torque_2_x", 0) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 8, "bond_torque_2_z", 0) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 9, "bond_side", 1) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 10, "bond_sigma", 0) ||
        expect_slot(GB_STATE_KIND_BOND_OUTPUT, 11, "bond_tau", 0))
        return 1;

    /* Every slot: a non-empty name, unique within its kind. */
    for (k = 0; k < 4; k++) {
        size_t i, j, len = lengths[k];
        int all_named = 1, unique = 1;
        for (i = 0; i < len; i++) {
            const char *a = NULL;
            int32_t fa = -1;
            EXPECT_OK(granbond_state_slot(kinds[k], i, &a, &fa),
                      say("granbond_state_slot(%d, %u)", (int)kinds[k], (unsigned)i));
            if (a == NULL || a[0] == '\0' || (fa != 0 && fa != 1))
                all_named = 0;
            for (j = 0; a != NULL && j < i; j++) {
                const char *b = NULL;
                int32_t fb = 0;
                granbond_state_slot(kinds[k], j, &b, &fb);
                if (b != NULL && strcmp(a, b) == 0)
                    unique = 0;
            }
        }
        CHECK(all_named, say("kind %d: every slot has a name and a 0/1 swap flag", (int)kinds[k]));
        CHECK(unique, say("kind %d: slot names are unique", (int)kinds[k]));
    }
    /* The wall bond state starts with the pair bond state. */
    {
        size_t i;
        int same = 1;
        for (i = 0; i < GRANBOND_BOND_STATE_LEN; i++) {
            const char *a = NULL, *b = NULL;
            int32_t fa = 0, fb = 0;
            granbond_state_slot(GB_STATE_KIND_BOND, i, &a, &fa);
            granbond_state_slot(GB_STATE_KIND_WALL_BOND, i, &b, &fb);
            if (a == NULL || b == NULL || strcmp(a, b) != 0 || fa != fb)
                same = 0;
        }
        CHECK(same, "wall bond slots 0..14 are the bond slots");
    }

    EXPECT(granbond_state_slot(GB_STATE_KIND_BOND, GRANBOND_BOND_STATE_LEN, &name, &flips),
           GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(bond, GRANBOND_BOND_STATE_LEN)");
    EXPECT_MESSAGE("out of range");
    EXPECT(granbond_state_slot(GB_STATE_KIND_WALL_BOND, GRANBOND_WALL_BOND_STATE_LEN, &name, &flips),
           GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(wall bond, GRANBOND_WALL_BOND_STATE_LEN)");
    EXPECT(granbond_state_slot(GB_STATE_KIND_CONTACT, (size_t)-1, &name, &flips), GB_STATUS_INVALID_ARGUMENT,
           "granbond_state_slot(contact, SIZE_MAX)");
    EXPECT(granbond_state_slot(GB_STATE_KIND_BOND_OUTPUT, GRANBOND_BOND_OUTPUT_LEN, &name, &flips),
           GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(bond output, GRANBOND_BOND_OUTPUT_LEN)");
    EXPECT(granbond_state_slot(4, 0, &name, &flips), GB_STATUS_INVALID_ARGUMENT, "granbond_state_slot(kind 4, 0)");
    EXPECT_MESSAGE("unknown state kind");
    EXPECT(granbond_state_slot(-1, 0, &name, &flips), GB_STATUS_INVALID_ARGUMENT,
           "granbond_state_slot(kind -1, 0)");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after an invalid argument");

    return 0;
}
