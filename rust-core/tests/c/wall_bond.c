/*
 * Bonds between a sphere and a wall.
 */

#include "harness.h"

#define R_W 0.9e-3

int test_wall_bond(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbSphereKinematics sphere, bad;
    GbBondOutput out;
    double state[GRANBOND_WALL_BOND_STATE_LEN], copy[GRANBOND_WALL_BOND_STATE_LEN];
    double contact[3] = {0.2e-3, -0.1e-3, 0.0};
    double wall_velocity[3] = {0.0, 0.0, 0.0};
    double partner[3], n[3], expected[3], r0, r, delta, area, fn;
    const double stretch = 1.0e-5, dt = 1.0e-6;
    int32_t created = -1;
    int c, i_partner, i_r0;

    if (new_bond_model(&p, &m))
        return 1;
    i_partner = slot_index(GB_STATE_KIND_WALL_BOND, "partner_x");
    i_r0 = slot_index(GB_STATE_KIND_WALL_BOND, "rest");
    CHECK(i_partner == GRANBOND_BOND_STATE_LEN && i_r0 >= 0, "wall bond slots partner_x, rest found");
    memset(state, 0, sizeof state);
    memset(&sphere, 0, sizeof sphere);

    /* Too far from the contact point: no bond. */
    sphere.x[0] = contact[0];
    sphere.x[1] = contact[1];
    sphere.x[2] = 2.0 * R_W;
    sphere.radius = R_W;
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, state, &created),
              "granbond_wall_bond_try_create, sphere off the wall");
    CHECK(created == 0, "not created outside create_distance");

    /* Touching the wall at the contact point: bonded to a mirror sphere. */
    sphere.x[2] = R_W;
    created = -1;
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP - 1, state, &created),
              "granbond_wall_bond_try_create, before create_step");
    CHECK(created == 0, "not created before create_step");
    EXPECT_OK(granbond_wall_bond_try_create(m, &sphere, contact, CREATE_STEP, state, &created),
              "granbond_wall_bond_try_create, touching, at create_step");
    CHECK(created == 1, "wall bond created");
    CHECK(state[0] > 0.0, "rest slot positive: intact");
    for (c = 0; c < 3; c++)
        partner[c] = state[i_partner + c];
    CHECK(fabs(partner[0] - contact[0]) < 1e-18 && fabs(partner[1] - contact[1]) < 1e-18 &&
              close_to(partner[2], -R_W, 1e-15),
          "partner centre = contact point - R n (the sphere's mirror image)");
    CHECK(close_to(state[i_r0], 2.0 * R_W, 1e-15), "r0 = 2 R");

    /* Pull the sphere off the wall: tension along the wall normal. */
    r0 = state[i_r0];
    sphere.x[2] = R_W + stretch;
    EXPECT_OK(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out),
              "granbond_wall_bond_compute, sphere pulled off the wall");
    r = distance3(sphere.x, partner);
    for (c = 0; c < 3; c++)
        n[c] = (sphere.x[c] - partner[c]) / r;
    delta = r0 - r;
    area = PI * (LAMBDA * R_W) * (LAMBDA * R_W);
    fn = p.k_fn2 * area * delta;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(close_to(out.normal_force, fn, 1e-12), say("wall bond Fn = k_fn2 A delta = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12) && out.force_i[2] < 0.0,
          "force on the sphere = Fn n, towards the wall");
    CHECK(out.status == GB_BOND_STATUS_INTACT, "intact");

    /* A moving wall carries the partner centre with it. */
    wall_velocity[0] = 1.0e-3;
    EXPECT_OK(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out),
              "granbond_wall_bond_compute, wall moving along x");
    CHECK(fabs(state[i_partner] - (partner[0] + wall_velocity[0] * dt)) < 1e-18 &&
              state[i_partner + 1] == partner[1] && state[i_partner + 2] == partner[2],
          "partner centre moved by wall_velocity dt");
    CHECK(out.status == GB_BOND_STATUS_INTACT && isfinite(out.force_i[0]), "intact, finite force");

    /* Errors. */
    memcpy(copy, state, sizeof state);
    wall_velocity[1] = NAN;
    EXPECT(granbond_wall_bond_compute(m, &sphere, wall_velocity, dt, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_wall_bond_compute, NaN wall velocity");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    wall_velocity[1] = 0.0;
    bad = sphere;
    bad.radius = 0.0;
    EXPECT(granbond_wall_bond_compute(m, &bad, wall_velocity, dt, state, &out), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_wall_bond_compute, radius 0");
    EXPECT(granbond_wall_bond_compute(m, &sphere, wall_velocity, -dt, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_wall_bond_compute, dt < 0");
    bad = sphere;
    bad.x[0] = INFINITY;
    {
        /* Kinematics are checked when creation is possible (an intact bond
         * returns at once: its compute call checks them). */
        double fresh[GRANBOND_WALL_BOND_STATE_LEN] = {0};
        EXPECT(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, fresh, &created),
               GB_STATUS_NON_FINITE_INPUT, "granbond_wall_bond_try_create, inf position");
        EXPECT_OK(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, state, &created),
                  "granbond_wall_bond_try_create on an intact bond returns before the kinematics");
        CHECK(created == 0, "an intact wall bond is kept");
    }
    bad = sphere;
    bad.radius = -R_W;
    {
        double fresh[GRANBOND_WALL_BOND_STATE_LEN] = {0};
        EXPECT(granbond_wall_bond_try_create(m, &bad, contact, CREATE_STEP, fresh, &created),
               GB_STATUS_NON_POSITIVE_RADIUS, "granbond_wall_bond_try_create, negative radius");
    }
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    granbond_bond_model_free(m);
    return 0;
}
