/*
 * What engines keep and log of a bond: its output packed into history
 * slots (GB_STATE_KIND_BOND_OUTPUT), and the bond centre.
 */

#include "harness.h"

/* An output with loads that are not exact in binary. */
static GbBondOutput some_output(void)
{
    GbBondOutput o;
    memset(&o, 0, sizeof o);
    o.force_i[0] = 1.1e-3;
    o.force_i[1] = -2.3;
    o.force_i[2] = 0.7;
    o.torque_i[0] = 3.3e-7;
    o.torque_i[1] = -1.7e-6;
    o.torque_i[2] = 2.9e-9;
    o.torque_j[0] = -4.1e-7;
    o.torque_j[1] = -0.3e-6;
    o.torque_j[2] = 7.7e-8;
    o.normal_force = 0.9;
    o.sigma = 1.3e6;
    o.tau = 4.7e5;
    o.delta = -1.0e-6;
    o.status = GB_BOND_STATUS_INTACT;
    o.break_mode = GB_BREAK_MODE_NONE;
    return o;
}

/* The slots, looked up by name. */
struct output_slots {
    int force, t1, t2, side, sigma, tau;
};

static int find_output_slots(struct output_slots *s)
{
    s->force = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_force_x");
    s->t1 = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_torque_1_x");
    s->t2 = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_torque_2_x");
    s->side = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_side");
    s->sigma = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_sigma");
    s->tau = slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_tau");
    CHECK(s->force >= 0 && s->t1 >= 0 && s->t2 >= 0 && s->side >= 0 && s->sigma >= 0 && s->tau >= 0,
          "bond output slots force, torques 1 and 2, side, sigma, tau found");
    CHECK(slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_force_z") == s->force + 2 &&
              slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_torque_1_z") == s->t1 + 2 &&
              slot_index(GB_STATE_KIND_BOND_OUTPUT, "bond_torque_2_z") == s->t2 + 2,
          "vector slots x, y, z in a row");
    return 0;
}

/* store then load: the slots are force_i, T_i, T_j, side +1, sigma, tau;
 * loaded, every load comes back bit for bit. */
static int check_round_trip(const GbBondOutput *o, const struct output_slots *s, const char *what)
{
    double slots[GRANBOND_BOND_OUTPUT_LEN];
    GbBondOutput back;
    int c, stored = 1, loaded = 1;

    EXPECT_OK(granbond_bond_output_store(o, slots), say("granbond_bond_output_store(%s)", what));
    for (c = 0; c < 3; c++)
        stored = stored && slots[s->force + c] == o->force_i[c] && slots[s->t1 + c] == o->torque_i[c] &&
                 slots[s->t2 + c] == o->torque_j[c];
    CHECK(stored && slots[s->side] == 1.0 && slots[s->sigma] == o->sigma && slots[s->tau] == o->tau,
          say("%s: slots force_i, T_i, T_j, side +1, sigma, tau", what));
    memset(&back, 0xff, sizeof back);
    EXPECT_OK(granbond_bond_output_load(slots, &back), say("granbond_bond_output_load(%s)", what));
    for (c = 0; c < 3; c++)
        loaded = loaded && back.force_i[c] == o->force_i[c] && back.torque_i[c] == o->torque_i[c] &&
                 back.torque_j[c] == o->torque_j[c];
    CHECK(loaded, say("%s: loaded force_i, T_i, T_j, bit for bit", what));
    CHECK(back.sigma == o->sigma && back.tau == o->tau && back.status == GB_BOND_STATUS_INTACT &&
              back.break_mode == GB_BREAK_MODE_NONE && back.normal_force == 0.0 && back.delta == 0.0,
          say("%s: sigma, tau; intact, no break; normal force and delta 0", what));
    return 0;
}

int test_bond_output_slots(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k;
    GbBondOutput o = some_output(), other, back, step;
    struct output_slots s;
    double state[GRANBOND_BOND_STATE_LEN], slots[GRANBOND_BOND_OUTPUT_LEN], swapped[GRANBOND_BOND_OUTPUT_LEN];
    double copy[GRANBOND_BOND_OUTPUT_LEN];
    size_t i;
    int c;

    CHECK(granbond_state_len(GB_STATE_KIND_BOND_OUTPUT) == GRANBOND_BOND_OUTPUT_LEN,
          "granbond_state_len(GB_STATE_KIND_BOND_OUTPUT) = GRANBOND_BOND_OUTPUT_LEN");
    if (find_output_slots(&s) || check_round_trip(&o, &s, "an output"))
        return 1;

    /* The output of a bond step: stretched and twisted. */
    if (new_bond_model(&p, &m))
        return 1;
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    memset(state, 0, sizeof state);
    if (create_bond(m, state))
        return 1;
    pair_at(&k, R0_NOMINAL + 1.0e-6, R_I, R_J);
    for (c = 0; c < 3; c++) {
        k.w_i[c] = 50.0 * AXIS[c] + (c == 0 ? 30.0 : 0.0);
        k.v_i[c] = (c == 1 ? 0.02 : 0.0);
    }
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &step), "granbond_bond_compute, stretched and turning");
    CHECK(!vec_zero(step.torque_i) && !vec_zero(step.torque_j), "the step has torques on both spheres");
    if (check_round_trip(&step, &s, "a bond step"))
        return 1;
    granbond_bond_model_free(m);

    /* The swap rule: the slots with flips_on_swap negated load as the
     * output seen from sphere j (force -force_i, torques traded). */
    EXPECT_OK(granbond_bond_output_store(&o, slots), "granbond_bond_output_store");
    for (i = 0; i < GRANBOND_BOND_OUTPUT_LEN; i++) {
        const char *name = NULL;
        int32_t flips = -1;
        EXPECT_OK(granbond_state_slot(GB_STATE_KIND_BOND_OUTPUT, i, &name, &flips), "granbond_state_slot");
        swapped[i] = flips ? -slots[i] : slots[i];
    }
    /* swapped back, the slots are those stored */
    for (i = 0; i < GRANBOND_BOND_OUTPUT_LEN; i++) {
        const char *name = NULL;
        int32_t flips = -1;
        EXPECT_OK(granbond_state_slot(GB_STATE_KIND_BOND_OUTPUT, i, &name, &flips), "granbond_state_slot");
        copy[i] = flips ? -swapped[i] : swapped[i];
    }
    CHECK(memcmp(copy, slots, sizeof copy) == 0, "flagged slots negated twice = the slots stored, bit for bit");
    EXPECT_OK(granbond_bond_output_load(swapped, &back), "granbond_bond_output_load(swapped slots)");
    EXPECT_OK(granbond_bond_output_load(slots, &step), "granbond_bond_output_load");
    for (c = 0; c < 3; c++)
        CHECK(back.force_i[c] == -step.force_i[c] && back.torque_i[c] == step.torque_j[c] &&
                  back.torque_j[c] == step.torque_i[c],
              say("swapped slots load as the output seen from j (component %d)", c));

    /* Non-finite loads are refused, the destination left alone. */
    memcpy(copy, slots, sizeof copy);
    other = o;
    other.sigma = NAN;
    EXPECT(granbond_bond_output_store(&other, slots), GB_STATUS_NON_FINITE_INPUT,
           "granbond_bond_output_store(sigma NaN)");
    EXPECT_MESSAGE("`out`");
    other = o;
    other.torque_j[2] = INFINITY;
    EXPECT(granbond_bond_output_store(&other, slots), GB_STATUS_NON_FINITE_INPUT,
           "granbond_bond_output_store(torque_j infinite)");
    CHECK(memcmp(copy, slots, sizeof copy) == 0, "refused stores leave the slots alone");
    slots[s.t2 + 1] = NAN;
    back = o;
    EXPECT(granbond_bond_output_load(slots, &back), GB_STATUS_NON_FINITE_INPUT,
           "granbond_bond_output_load(a NaN slot)");
    EXPECT_MESSAGE("`slots`");
    CHECK(memcmp(&back, &o, sizeof back) == 0, "a refused load leaves the output alone");
    return 0;
}

int test_bond_centre(void)
{
    const double x_i[3] = {1.0e-3, 2.5e-3, -0.7e-3}, wall[3] = {0.3e-3, -1.1e-3, 0.0};
    const double huge[3] = {1.0e308, 0.0, 0.0}, minus_huge[3] = {-1.0e308, 0.0, 0.0};
    double centre[3], want[3], bad[3], before[3], d, w;
    int c;

    /* Pairs: x_j + R_j / (R_i + R_j) (x_i - x_j), bit for bit. */
    EXPECT_OK(granbond_bond_centre(x_i, X_J, R_I, R_J, centre), "granbond_bond_centre(pair)");
    w = R_J / (R_I + R_J);
    for (c = 0; c < 3; c++)
        want[c] = X_J[c] + w * (x_i[c] - X_J[c]);
    CHECK(vec_equal(centre, want), "centre = x_j + R_j / (R_i + R_j) (x_i - x_j), bit for bit");
    d = distance3(x_i, X_J);
    CHECK(close_to(distance3(centre, x_i), R_I / (R_I + R_J) * d, 1e-12) &&
              close_to(distance3(centre, X_J), R_J / (R_I + R_J) * d, 1e-12),
          "|c - x_i| = R_i / (R_i + R_j) d, |c - x_j| = R_j / (R_i + R_j) d");
    EXPECT_OK(granbond_bond_centre(X_J, x_i, R_J, R_I, want), "granbond_bond_centre(the pair swapped)");
    CHECK(vec_close(want, centre, 1e-15), "the same centre seen from j");

    /* Walls: the wall point, radius 0. */
    EXPECT_OK(granbond_bond_centre(x_i, wall, R_I, 0.0, centre), "granbond_bond_centre(wall)");
    CHECK(vec_equal(centre, wall), "a wall bond's centre is the wall point");

    /* Refused, naming the argument; the centre left alone. */
    memcpy(before, centre, sizeof before);
    EXPECT(granbond_bond_centre(x_i, wall, 0.0, R_J, centre), GB_STATUS_INVALID_ARGUMENT, "radius_i = 0");
    EXPECT_MESSAGE("radius_i");
    EXPECT(granbond_bond_centre(x_i, wall, -R_I, R_J, centre), GB_STATUS_INVALID_ARGUMENT, "radius_i < 0");
    EXPECT(granbond_bond_centre(x_i, wall, NAN, R_J, centre), GB_STATUS_INVALID_ARGUMENT, "radius_i NaN");
    EXPECT(granbond_bond_centre(x_i, wall, R_I, -R_J, centre), GB_STATUS_INVALID_ARGUMENT, "radius_j < 0");
    EXPECT_MESSAGE("radius_j");
    EXPECT(granbond_bond_centre(x_i, wall, R_I, INFINITY, centre), GB_STATUS_INVALID_ARGUMENT,
           "radius_j infinite");
    EXPECT_MESSAGE("radius_j");
    memcpy(bad, x_i, sizeof bad);
    bad[1] = NAN;
    EXPECT(granbond_bond_centre(bad, wall, R_I, R_J, centre), GB_STATUS_NON_FINITE_INPUT, "x_i NaN");
    EXPECT_MESSAGE("x_i");
    bad[1] = -INFINITY;
    EXPECT(granbond_bond_centre(x_i, bad, R_I, R_J, centre), GB_STATUS_NON_FINITE_INPUT, "x_j infinite");
    EXPECT_MESSAGE("x_j");
    EXPECT(granbond_bond_centre(huge, minus_huge, R_I, R_J, centre), GB_STATUS_NON_FINITE_RESULT,
           "positions whose difference overflows");
    EXPECT(granbond_bond_centre(x_i, wall, 1.0e308, 1.0e308, centre), GB_STATUS_INVALID_ARGUMENT,
           "radii whose sum overflows");
    CHECK(vec_equal(centre, before), "refused calls leave the centre alone");
    return 0;
}
