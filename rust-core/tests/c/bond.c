/*
 * Bonds between two spheres: creation, loads, errors, the batch and
 * indexed calls, breakage, neighbour range and time step.
 */

#include "harness.h"

int test_bond_create_and_force(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN], copy[GRANBOND_BOND_STATE_LEN];
    double n[3], expected[3], r, r0, delta, rb, area, fn;
    int32_t created = -1;
    int c, i_r0, i_dmin, i_dmax;
    const double stretch = 1.0e-5, squeeze = 1.0e-5;

    if (new_bond_model(&p, &m))
        return 1;
    i_r0 = slot_index(GB_STATE_KIND_BOND, "rest");
    i_dmin = slot_index(GB_STATE_KIND_BOND, "delta_min");
    i_dmax = slot_index(GB_STATE_KIND_BOND, "delta_max");
    CHECK(i_r0 >= 0 && i_dmin >= 0 && i_dmax >= 0, "slots rest, delta_min, delta_max found");

    /* Creation rules. What granbond_bond_may_create says of a state and a
     * step: unbonded, only at create_step (create_always is off); intact
     * never; broken only with create_always; 0 for bad pointers. */
    memset(state, 0, sizeof state);
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 1, "may_create: unbonded, at create_step");
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP - 1) == 0 &&
              granbond_bond_may_create(m, state, CREATE_STEP + 1) == 0,
          "may_create: unbonded, not at create_step");
    /* the rest length's sign is the status: positive intact, negative broken */
    state[i_r0] = R0_NOMINAL;
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 0, "may_create: intact");
    state[i_r0] = -R0_NOMINAL;
    CHECK(granbond_bond_may_create(m, state, CREATE_STEP) == 0, "may_create: broken, create_always off");
    {
        GbBondParams always = p;
        GbBondModel *ma = NULL;
        always.create_always = 1;
        if (new_bond_model(&always, &ma))
            return 1;
        CHECK(granbond_bond_may_create(ma, state, CREATE_STEP + 7) == 1, "may_create: broken, create_always on");
        granbond_bond_model_free(ma);
    }
    /* granbond_bond_keeps_contact_tangential and granbond_bond_law_line:
     * which law a model steps (inl_compatible), in each engine's words; a
     * bad naming or buffer is refused. */
    {
        GbBondParams inl = p;
        GbBondModel *mi = NULL;
        char line[512];
        inl.inl_compatible = 1;
        if (new_bond_model(&inl, &mi))
            return 1;
        CHECK(granbond_bond_keeps_contact_tangential(m) == 0 && granbond_bond_keeps_contact_tangential(mi) == 1 &&
                  granbond_bond_keeps_contact_tangential(NULL) == 0,
              "keeps_contact_tangential: only under inl_compatible");
        CHECK(granbond_bond_keeps_contact_loads(m) == 0 && granbond_bond_keeps_contact_loads(mi) == 0 &&
                  granbond_bond_keeps_contact_loads(NULL) == 0,
              "keeps_contact_loads: not under bond/nonlinear");
        /* granbond_bond_contact_loads_under_bond: the default law leaves
         * none of a touching contact's loads, INL's code its tangential and
         * rolling ones (the normal force along del taken out) */
        {
            const double del[3] = {3.0e-3, 0.0, 4.0e-3};
            GbContactOutput c, under;
            memset(&c, 0, sizeof c);
            c.force_i[0] = 0.6 * 2.0 + 1.0;   /* normal 2 N along del/5e-3, tangential (1, 0.25, -0.75) */
            c.force_i[1] = 0.25;
            c.force_i[2] = 0.8 * 2.0 - 0.75;
            c.torque_i[1] = 1.0e-3;
            c.torque_j[1] = 2.0e-3;
            c.normal_force = 2.0;
            c.touching = 1;
            under = c;
            EXPECT_OK(granbond_bond_contact_loads_under_bond(mi, del, 25.0e-6, &under), "contact_loads_under_bond, INL");
            CHECK(fabs(under.force_i[0] - 1.0) < 1e-12 && fabs(under.force_i[1] - 0.25) < 1e-12 &&
                      fabs(under.force_i[2] + 0.75) < 1e-12 && under.torque_i[1] == 1.0e-3 &&
                      under.torque_j[1] == 2.0e-3,
                  "contact_loads_under_bond: INL's code keeps the tangential force and the torques");
            under = c;
            EXPECT_OK(granbond_bond_contact_loads_under_bond(m, del, 25.0e-6, &under), "contact_loads_under_bond");
            CHECK(under.force_i[0] == 0.0 && under.force_i[2] == 0.0 && under.torque_i[1] == 0.0 &&
                      under.torque_j[1] == 0.0,
                  "contact_loads_under_bond: the default law keeps none");
            CHECK(granbond_bond_contact_loads_under_bond(mi, del, 0.0, &under) != GB_STATUS_OK,
                  "contact_loads_under_bond: coincident centres refused");
        }
        {
            const char *name = NULL;
            CHECK(granbond_bond_parameter_liggghts_name(1, 0, &name) == GB_STATUS_OK && name &&
                      strcmp(name, "radiusMultiplierBond") == 0,
                  "parameter_liggghts_name: lambda of the linear bond");
            CHECK(granbond_bond_parameter_liggghts_name(2, 0, &name) == GB_STATUS_INVALID_ARGUMENT,
                  "parameter_liggghts_name: law 2 refused");
        }
        CHECK(granbond_bond_law_line(m, 1, line, sizeof line) == GB_STATUS_OK && strstr(line, "inlCompatible on"),
              "law_line: the default law names the LIGGGHTS switch");
        CHECK(granbond_bond_law_line(mi, 0, line, sizeof line) == GB_STATUS_OK && strstr(line, "inl_compatible on") &&
                  strstr(line, "without the section A"),
              "law_line: INL's code in LAMMPS words");
        CHECK(granbond_bond_law_line(mi, 2, line, sizeof line) == GB_STATUS_INVALID_ARGUMENT,
              "law_line: naming 2 refused");
        CHECK(granbond_bond_law_line(mi, 1, line, 0) == GB_STATUS_INVALID_ARGUMENT, "law_line: no room refused");
        CHECK(granbond_bond_law_line(mi, 1, line, 8) == GB_STATUS_OK && strlen(line) == 7, "law_line: cut to fit");
        /* granbond_bond_setup_compute and granbond_wall_bond_setup_compute:
         * the default law keeps its latest loads (nothing computed); INL's
         * code computes a trial step that leaves the angles and the shear
         * force where they were. */
        {
            GbPairKinematics kp;
            GbSphereKinematics sp;
            double st[GRANBOND_BOND_STATE_LEN], before[GRANBOND_BOND_STATE_LEN];
            double wst[GRANBOND_WALL_BOND_STATE_LEN], zero[3] = {0.0, 0.0, 0.0};
            int32_t rec = -1;
            memset(st, 0, sizeof st);
            memset(&out, 0, sizeof out);
            pair_at(&kp, R0_NOMINAL, R_I, R_J);
            kp.v_i[1] = 1e-3;
            st[i_r0] = R0_NOMINAL * (1.0 + 1e-6);
            EXPECT_OK(granbond_bond_setup_compute(m, &kp, 1e-8, st, &rec, &out), "setup_compute, default law");
            CHECK(rec == 0 && out.force_i[0] == 0.0, "setup_compute: the default law computes nothing");
            memcpy(before, st, sizeof st);
            EXPECT_OK(granbond_bond_setup_compute(mi, &kp, 1e-8, st, &rec, &out), "setup_compute, INL's code");
            CHECK(rec == 1 && out.force_i[0] > 0.0 && out.status == GB_BOND_STATUS_INTACT,
                  "setup_compute: INL's code pushes the compressed pair apart");
            CHECK(memcmp(st + 4, before + 4, 3 * sizeof(double)) == 0, "setup_compute: the shear force is not stored");
            CHECK(granbond_bond_setup_compute(mi, &kp, 1e-8, st, NULL, &out) == GB_STATUS_NULL_POINTER,
                  "setup_compute: a null recomputed is an error");
            memset(wst, 0, sizeof wst);
            memset(&sp, 0, sizeof sp);
            sp.x[2] = 0.999 * R_I;
            sp.radius = R_I;
            EXPECT_OK(granbond_wall_bond_try_create(mi, &sp, zero, CREATE_STEP, wst, &created), "INL wall bond");
            sp.x[2] = 0.999 * R_I * (1.0 - 1e-6);
            EXPECT_OK(granbond_wall_bond_setup_compute(mi, &sp, zero, 1e-8, wst, &rec, &out),
                      "wall_bond_setup_compute, INL's code");
            CHECK(created == 1 && rec == 1 && out.force_i[2] > 0.0, "wall setup: INL's code pushes off the wall");
            CHECK(wst[GRANBOND_BOND_STATE_LEN + 2] == 0.0, "wall setup: the contact point stays");
        }
        granbond_bond_model_free(mi);
    }
    /* granbond_bond_creates_at: at create_step only (create_always off),
     * every step with create_always; 0 for a bad model. */
    CHECK(granbond_bond_creates_at(m, CREATE_STEP) == 1, "creates_at: at create_step");
    CHECK(granbond_bond_creates_at(m, CREATE_STEP - 1) == 0 && granbond_bond_creates_at(m, CREATE_STEP + 1) == 0,
          "creates_at: not at another step");
    {
        GbBondParams always = p;
        GbBondModel *ma = NULL;
        always.create_always = 1;
        if (new_bond_model(&always, &ma))
            return 1;
        CHECK(granbond_bond_creates_at(ma, CREATE_STEP + 7) == 1, "creates_at: any step with create_always");
        granbond_bond_model_free(ma);
    }
    CHECK(granbond_bond_creates_at(NULL, CREATE_STEP) == 0 &&
              granbond_bond_creates_at((const GbBondModel *)((const char *)m + 1), CREATE_STEP) == 0,
          "creates_at: 0 for a null or misaligned model");
    /* granbond_bond_creation_reach: create_distance up to create_step, 0
     * after it; with create_always, create_distance at every step */
    {
        double reach = -1.0;
        GbBondParams always = p;
        GbBondModel *ma = NULL;
        EXPECT_OK(granbond_bond_creation_reach(m, CREATE_STEP, &reach), "creation_reach at create_step");
        CHECK(reach == CREATE_DISTANCE, "creation_reach: create_distance up to create_step");
        EXPECT_OK(granbond_bond_creation_reach(m, CREATE_STEP + 1, &reach), "creation_reach after create_step");
        CHECK(reach == 0.0, "creation_reach: 0 after create_step");
        always.create_always = 1;
        if (new_bond_model(&always, &ma))
            return 1;
        EXPECT_OK(granbond_bond_creation_reach(ma, CREATE_STEP + 7, &reach), "creation_reach, create_always");
        CHECK(reach == CREATE_DISTANCE, "creation_reach: create_distance at any step with create_always");
        granbond_bond_model_free(ma);
        CHECK(granbond_bond_creation_reach(NULL, CREATE_STEP, &reach) == GB_STATUS_NULL_POINTER &&
                  granbond_bond_creation_reach(m, CREATE_STEP, NULL) == GB_STATUS_NULL_POINTER,
              "creation_reach: a null model or reach is an error");
    }
    CHECK(granbond_bond_may_create(NULL, state, CREATE_STEP) == 0 && granbond_bond_may_create(m, NULL, CREATE_STEP) == 0 &&
              granbond_bond_may_create(m, (const double *)((const char *)state + 1), CREATE_STEP) == 0,
          "may_create: 0 for a null model, a null or misaligned state");
    memset(state, 0, sizeof state);
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP - 1, state, &created),
              "try_create within create_distance, not at create_step");
    CHECK(created == 0, "not created before create_step");
    CHECK(state[i_r0] == 0.0 && !signbit(state[i_r0]), "state still unbonded");
    pair_at(&k, CREATE_DISTANCE * 1.05, R_I, R_J);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created),
              "try_create at create_step, outside create_distance");
    CHECK(created == 0, "not created beyond create_distance");
    CHECK(state[i_r0] == 0.0 && !signbit(state[i_r0]), "state still unbonded");
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created),
              "try_create at create_step, within create_distance");
    CHECK(created == 1, "created");
    CHECK(state[i_r0] > 0.0, "rest slot positive: intact");
    r = distance3(k.x_i, k.x_j);
    CHECK(close_to(state[i_r0], r, 1e-15), say("r0 slot = centre distance %.17g", r));
    memcpy(copy, state, sizeof state);
    created = -1;
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "try_create on an intact bond");
    CHECK(created == 0 && memcmp(copy, state, sizeof state) == 0, "an intact bond is kept as it is");

    /* Stretch: virgin tension Fn = k_fn2 A delta (delta < 0), force on i = Fn n. */
    r0 = state[i_r0];
    pair_at(&k, r0 + stretch, R_I, R_J);
    memset(&out, 0xAB, sizeof out);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute, stretched bond");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    delta = r0 - r;
    rb = LAMBDA * (R_I < R_J ? R_I : R_J);
    area = PI * rb * rb;
    fn = p.k_fn2 * area * delta;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(delta < 0.0 && close_to(delta, -stretch, 1e-9), say("stretched: delta = r0 - r = %.6g", delta));
    CHECK(close_to(out.delta, delta, 1e-12), say("out.delta = %.17g", delta));
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_fn2 A delta = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12),
          say("force on i = Fn n = (%.12g, %.12g, %.12g) to 1e-12", expected[0], expected[1], expected[2]));
    CHECK(dot3(out.force_i, n) < 0.0, "tension pulls i towards j");
    CHECK(close_to(out.sigma, fabs(fn) / area, 1e-12), "out.sigma = |Fn| / A");
    CHECK(fabs(out.tau) < 1e-30, "out.tau = 0 (no shear, no twist)");
    CHECK(norm3(out.torque_i) < 1e-30 && norm3(out.torque_j) < 1e-30, "no torques at rest");
    CHECK(out.status == GB_BOND_STATUS_INTACT && out.break_mode == GB_BREAK_MODE_NONE, "intact, no break");
    CHECK(close_to(state[i_dmin], delta, 1e-12), "delta_min slot = delta");

    /* Squeeze a fresh bond: virgin compression Fn = k_fn1 A sqrt(delta). */
    if (create_bond(m, state))
        return 1;
    r0 = state[i_r0];
    pair_at(&k, r0 - squeeze, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute, compressed bond");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    delta = r0 - r;
    fn = p.k_fn1 * area * sqrt(delta);
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_fn1 A sqrt(delta) = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12), "force on i = Fn n to 1e-12");
    CHECK(dot3(out.force_i, n) > 0.0, "compression pushes i away from j");
    CHECK(close_to(state[i_dmax], delta, 1e-12), "delta_max slot = delta");

    /* dt = 0 is a valid step. */
    EXPECT_OK(granbond_bond_compute(m, &k, 0.0, state, &out), "granbond_bond_compute with dt = 0");

    /* A pair that was never bonded exerts nothing. */
    memset(state, 0, sizeof state);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute on an unbonded pair");
    CHECK(out.status == GB_BOND_STATUS_UNBONDED && vec_zero(out.force_i) && vec_zero(out.torque_i) &&
              vec_zero(out.torque_j),
          "unbonded: status UNBONDED, no force, no torque");

    granbond_bond_model_free(m);
    return 0;
}

int test_bond_errors(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics good, k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN], copy[GRANBOND_BOND_STATE_LEN];
    union {
        double d[GRANBOND_BOND_STATE_LEN + 1];
        unsigned char bytes[(GRANBOND_BOND_STATE_LEN + 1) * sizeof(double)];
    } misaligned;
    int32_t created = 0;

    if (new_bond_model(&p, &m) || create_bond(m, state))
        return 1;
    memcpy(copy, state, sizeof state);
    pair_at(&good, R0_NOMINAL + 1.0e-6, R_I, R_J);

    /* Bad kinematics on an intact bond: the error, and the state untouched. */
    k = good;
    memcpy(k.x_i, k.x_j, sizeof k.x_i);
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_COINCIDENT_CENTRES, "coincident centres");
    EXPECT_MESSAGE("coincident");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    k = good;
    k.v_i[1] = NAN;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "NaN in v_i");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    k = good;
    k.x_j[2] = INFINITY;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "inf in x_j");
    k = good;
    k.w_j[0] = -INFINITY;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "-inf in w_j");
    k = good;
    k.radius_i = NAN;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_FINITE_INPUT, "NaN radius_i");
    k = good;
    k.radius_j = 0.0;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS, "radius_j = 0");
    EXPECT_MESSAGE("radius");
    k = good;
    k.radius_i = -1.0e-3;
    EXPECT(granbond_bond_compute(m, &k, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS, "radius_i < 0");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");
    CHECK(granbond_last_error_parameter() == -1, "no parameter id after an input error");

    /* Bad time steps. */
    EXPECT(granbond_bond_compute(m, &good, -1.0e-9, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt < 0");
    EXPECT_MESSAGE("dt");
    EXPECT(granbond_bond_compute(m, &good, NAN, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt = NaN");
    EXPECT(granbond_bond_compute(m, &good, INFINITY, state, &out), GB_STATUS_INVALID_ARGUMENT, "dt = inf");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    /* Creation from bad kinematics. */
    memset(state, 0, sizeof state);
    k = good;
    memcpy(k.x_j, k.x_i, sizeof k.x_j);
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_COINCIDENT_CENTRES,
           "try_create, coincident centres");
    k = good;
    k.x_i[0] = NAN;
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_NON_FINITE_INPUT,
           "try_create, NaN position");
    k = good;
    k.radius_i = 0.0;
    EXPECT(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), GB_STATUS_NON_POSITIVE_RADIUS,
           "try_create, radius 0");

    /* A misaligned state pointer is refused, not dereferenced. */
    EXPECT(granbond_bond_compute(m, &good, DT, (double *)(void *)(misaligned.bytes + 4), &out),
           GB_STATUS_MISALIGNED, "granbond_bond_compute with a misaligned state");
    EXPECT_MESSAGE("misaligned");

    granbond_bond_model_free(m);
    return 0;
}

#define N_SCATTERED 11

/* States apart in memory, in an order unrelated to their addresses, as in an
 * engine's contact history; among them a broken bond and one that breaks in
 * this step. */
static int scattered_fixture(GbBondModel *m, GbPairKinematics *k, double *memory, double **states)
{
    int b;
    for (b = 0; b < N_SCATTERED; b++) {
        states[b] = memory + 2 * (N_SCATTERED - 1 - b) * GRANBOND_BOND_STATE_LEN;
        if (create_bond(m, states[b]))
            return 1;
        pair_at(&k[b], R0_NOMINAL + (b - 5.0) * 1.0e-6, R_I, R_J);
        k[b].v_i[1] = 2.0e-3 * b;
        k[b].w_i[0] = 0.3 * b;
        k[b].w_j[2] = -0.5 * b;
    }
    states[5][0] = -states[5][0]; /* the rest length negative: broken */
    pair_at(&k[7], 1.01 * MAX_DISTANCE, R_I, R_J);
    return 0;
}

/* The scattered bonds with their spheres in per-atom arrays, as an engine
 * keeps them: bond b joins atoms 2N-1-b (i) and b (j). */
static void indexed_fixture(const GbPairKinematics *k, double *x, double *v, double *w, double *radius,
                            int32_t *pairs, GbAtomArrays *atoms)
{
    int b, c;
    for (b = 0; b < N_SCATTERED; b++) {
        const int i = 2 * N_SCATTERED - 1 - b, j = b;
        pairs[2 * b] = i;
        pairs[2 * b + 1] = j;
        for (c = 0; c < 3; c++) {
            x[3 * i + c] = k[b].x_i[c];
            v[3 * i + c] = k[b].v_i[c];
            w[3 * i + c] = k[b].w_i[c];
            x[3 * j + c] = k[b].x_j[c];
            v[3 * j + c] = k[b].v_j[c];
            w[3 * j + c] = k[b].w_j[c];
        }
        radius[i] = k[b].radius_i;
        radius[j] = k[b].radius_j;
    }
    atoms->x = x;
    atoms->v = v;
    atoms->omega = w;
    atoms->radius = radius;
    atoms->count = 2 * N_SCATTERED;
}

/* Each bond as one granbond_bond_compute would give it, bit for bit; a bad
 * state pointer or bond is reported with its index. */
int test_bond_indexed_results(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k[N_SCATTERED];
    GbBondOutput out[N_SCATTERED], single;
    double memory[2 * N_SCATTERED * GRANBOND_BOND_STATE_LEN], before[sizeof memory / sizeof(double)];
    double x[6 * N_SCATTERED], v[6 * N_SCATTERED], w[6 * N_SCATTERED], radius[2 * N_SCATTERED];
    double *states[N_SCATTERED], one[GRANBOND_BOND_STATE_LEN], *saved;
    int32_t pairs[2 * N_SCATTERED];
    GbAtomArrays atoms;
    size_t failed = 999;
    int b;

    if (new_bond_model(&p, &m) || scattered_fixture(m, k, memory, states))
        return 1;
    indexed_fixture(k, x, v, w, radius, pairs, &atoms);
    memcpy(before, memory, sizeof memory);

    EXPECT_OK(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
              "granbond_bond_compute_indexed");
    CHECK(failed == 999, "failed_index left alone on success");
    CHECK(out[5].status == GB_BOND_STATUS_BROKEN && out[7].status == GB_BOND_STATUS_BROKEN &&
              out[7].break_mode == GB_BREAK_MODE_DISTANCE && out[3].status == GB_BOND_STATUS_INTACT,
          "indexed: broken, breaking and intact bonds");
    for (b = 0; b < N_SCATTERED; b++) {
        memcpy(one, before + (states[b] - memory), sizeof one);
        EXPECT_OK(granbond_bond_compute(m, &k[b], DT, one, &single), say("granbond_bond_compute, bond %d", b));
        CHECK(memcmp(&out[b], &single, sizeof single) == 0 && memcmp(one, states[b], sizeof one) == 0,
              say("indexed bond %d = single call, bit for bit", b));
    }

    /* A null state pointer: reported with its index before any bond moves. */
    memcpy(memory, before, sizeof memory);
    saved = states[4];
    states[4] = NULL;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_NULL_POINTER, "granbond_bond_compute_indexed with states[4] = NULL");
    CHECK(failed == 4, say("failed_index = 4 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("bond 4");
    CHECK(memcmp(memory, before, sizeof memory) == 0, "no state advanced when a state pointer is null");
    states[4] = saved;

    /* A bad bond stops there, as in the batch call: v_j of bond 6 is atom 6's. */
    v[3 * 6 + 2] = INFINITY;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_NON_FINITE_INPUT, "granbond_bond_compute_indexed with inf in bond 6");
    CHECK(failed == 6, say("failed_index = 6 (got %u)", (unsigned)failed));
    v[3 * 6 + 2] = 0.0;

    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, NAN, states, out, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with dt = NaN");

    granbond_bond_model_free(m);
    return 0;
}

/* An index outside the arrays is refused before any bond moves. */
int test_bond_indexed(void)
{
    const GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k[N_SCATTERED];
    GbBondOutput out[N_SCATTERED], want[N_SCATTERED];
    double memory[2 * N_SCATTERED * GRANBOND_BOND_STATE_LEN], before[sizeof memory / sizeof(double)],
        after[sizeof memory / sizeof(double)];
    double x[6 * N_SCATTERED], v[6 * N_SCATTERED], w[6 * N_SCATTERED], radius[2 * N_SCATTERED];
    double *states[N_SCATTERED];
    int32_t pairs[2 * N_SCATTERED];
    GbAtomArrays atoms, bad;
    size_t failed = 999;
    int b;

    if (new_bond_model(&p, &m) || scattered_fixture(m, k, memory, states))
        return 1;
    indexed_fixture(k, x, v, w, radius, pairs, &atoms);
    memcpy(before, memory, sizeof memory);

    for (b = 0; b < N_SCATTERED; b++)
        EXPECT_OK(granbond_bond_compute(m, &k[b], DT, states[b], &want[b]),
                  say("granbond_bond_compute, bond %d (reference for the indexed call)", b));
    memcpy(after, memory, sizeof memory);
    memcpy(memory, before, sizeof memory);
    EXPECT_OK(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
              "granbond_bond_compute_indexed");
    CHECK(failed == 999, "failed_index left alone on success");
    CHECK(memcmp(out, want, sizeof out) == 0 && memcmp(memory, after, sizeof memory) == 0,
          "indexed = single calls, outputs and states bit for bit");

    /* An atom index past the arrays, or negative: its bond, nothing moved. */
    memcpy(memory, before, sizeof memory);
    pairs[2 * 3 + 1] = 2 * N_SCATTERED;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with an index = count");
    CHECK(failed == 3, say("failed_index = 3 (got %u)", (unsigned)failed));
    EXPECT_MESSAGE("bond 3");
    EXPECT_MESSAGE("atom index 22");
    CHECK(memcmp(memory, before, sizeof memory) == 0, "no state advanced for a bad index");
    pairs[2 * 3 + 1] = 3;
    pairs[2 * 8] = -1;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with a negative index");
    CHECK(failed == 8, say("failed_index = 8 (got %u)", (unsigned)failed));
    pairs[2 * 8] = 2 * N_SCATTERED - 1 - 8;

    /* count too large for the arrays' sizes to be computed */
    bad = atoms;
    bad.count = (size_t)-1;
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &bad, pairs, DT, states, out, &failed),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with atoms->count = SIZE_MAX");
    EXPECT_MESSAGE("atoms->count");

    EXPECT_OK(granbond_bond_compute_indexed(m, 0, &atoms, NULL, DT, NULL, NULL, NULL),
              "granbond_bond_compute_indexed, count = 0 and NULL arrays");
    EXPECT(granbond_bond_compute_indexed(m, N_SCATTERED, &atoms, pairs, -DT, states, out, NULL),
           GB_STATUS_INVALID_ARGUMENT, "granbond_bond_compute_indexed with dt < 0");
    bad = atoms;
    bad.x = NULL;
    bad = atoms;
    bad.omega = NULL;
    bad = atoms;
    bad.radius = NULL;

    granbond_bond_model_free(m);
    return 0;
}

int test_bond_break(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL, *always = NULL, *stress = NULL;
    GbPairKinematics k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN];
    static const double distances[6] = {1.85e-3, 1.95e-3, 1.85e-3, 1.95e-3, 1.8e-3, 2.5e-3};
    int s, breaks = 0, i_rest;
    int32_t created = -1;

    if (new_bond_model(&p, &m) || create_bond(m, state))
        return 1;
    i_rest = slot_index(GB_STATE_KIND_BOND, "rest");

    /* Distance mode: breaks in the first step with r > max_distance, once. */
    for (s = 0; s < 6; s++) {
        pair_at(&k, distances[s], R_I, R_J);
        memset(&out, 0xAB, sizeof out);
        EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), say("step %d at r = %g", s, distances[s]));
        if (out.break_mode == GB_BREAK_MODE_DISTANCE)
            breaks++;
        if (s == 0)
            CHECK(out.status == GB_BOND_STATUS_INTACT && out.break_mode == GB_BREAK_MODE_NONE &&
                      !vec_zero(out.force_i),
                  "r < max_distance: intact, loaded");
        if (s == 1) {
            CHECK(out.break_mode == GB_BREAK_MODE_DISTANCE, "r > max_distance: break_mode = GB_BREAK_MODE_DISTANCE");
            CHECK(out.status == GB_BOND_STATUS_BROKEN, "status = GB_BOND_STATUS_BROKEN");
            CHECK(state[i_rest] < 0.0, "rest slot negative: broken");
        }
        if (s >= 1)
            CHECK(out.status == GB_BOND_STATUS_BROKEN && vec_zero(out.force_i) && vec_zero(out.torque_i) &&
                      vec_zero(out.torque_j),
                  say("step %d: broken, no force, no torque", s));
        if (s >= 2)
            CHECK(out.break_mode == GB_BREAK_MODE_NONE, say("step %d: break_mode = NONE after the break", s));
    }
    CHECK(breaks == 1, "the bond broke exactly once");

    /* A broken bond is re-created only under create_always. */
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "try_create on a broken bond");
    CHECK(created == 0 && state[i_rest] < 0.0, "broken bond stays broken");
    p.create_always = 1;
    if (new_bond_model(&p, &always))
        return 1;
    created = -1;
    EXPECT_OK(granbond_bond_try_create(always, &k, 12345, state, &created),
              "try_create on a broken bond, create_always on");
    CHECK(created == 1 && state[i_rest] > 0.0, "re-created under create_always");

    /* Stress mode: tension breaks at sigma = k_fn2 |delta| >= max_sigma. */
    p = bond_fixture();
    p.stress_break = 1;
    p.max_sigma = 1.0e5; /* Pa: k_fn2 * 1e-5 m */
    if (new_bond_model(&p, &stress) || create_bond(stress, state))
        return 1;
    pair_at(&k, state[slot_index(GB_STATE_KIND_BOND, "rest")] + 0.5e-5, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(stress, &k, DT, state, &out), "stress mode, sigma below max_sigma");
    CHECK(out.status == GB_BOND_STATUS_INTACT && out.sigma < p.max_sigma, "intact below the limit");
    pair_at(&k, state[slot_index(GB_STATE_KIND_BOND, "rest")] + 2.0e-5, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(stress, &k, DT, state, &out), "stress mode, sigma above max_sigma");
    CHECK(out.status == GB_BOND_STATUS_BROKEN && out.break_mode == GB_BREAK_MODE_TENSION && vec_zero(out.force_i),
          "breaks in tension: break_mode = GB_BREAK_MODE_TENSION, no force");

    granbond_bond_model_free(stress);
    granbond_bond_model_free(always);
    granbond_bond_model_free(m);
    return 0;
}

int test_bond_limits(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL, *stress = NULL, *unbreakable = NULL;
    const double mass_i = 1.0e-5, mass_j = 0.6e-5;
    double d = -1.0, dt = -1.0, m_eff, rb, area, bound;

    if (new_bond_model(&p, &m))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(m, R0_NOMINAL, &d), "granbond_bond_max_distance, distance mode");
    EXPECT(granbond_bond_max_distance(m, NAN, &d), GB_STATUS_INVALID_ARGUMENT, "granbond_bond_max_distance, NaN r0");
    EXPECT(granbond_bond_max_distance(m, -1.0, &d), GB_STATUS_INVALID_ARGUMENT, "granbond_bond_max_distance, r0 < 0");
    CHECK(d == MAX_DISTANCE, "distance mode: max bond distance = max_distance");

    p.stress_break = 1;
    p.max_sigma = 1.0e7;
    p.use_ratio = 1;
    p.tension_compression_ratio = 0.5;
    if (new_bond_model(&p, &stress))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(stress, R0_NOMINAL, &d), "granbond_bond_max_distance, stress mode");
    CHECK(close_to(d, R0_NOMINAL + 0.5 * 1.0e7 / p.k_fn2, 1e-14),
          say("stress mode: r0 + gamma max_sigma / k_fn2 = %.17g", R0_NOMINAL + 0.5 * 1.0e7 / p.k_fn2));
    p.max_sigma = INFINITY;
    if (new_bond_model(&p, &unbreakable))
        return 1;
    EXPECT_OK(granbond_bond_max_distance(unbreakable, R0_NOMINAL, &d),
              "granbond_bond_max_distance, stress mode without limit");
    CHECK(isinf(d) && d > 0.0, "never breaks: +inf");

    /* Neighbour-list factor: 1.1 x the largest bonded distance / (2 min R), at least 1. */
    EXPECT_OK(granbond_bond_contact_distance_factor(m, R_J, &d),
              "granbond_bond_contact_distance_factor, distance mode");
    CHECK(close_to(d, 1.1 * MAX_DISTANCE / (2.0 * R_J), 1e-14),
          say("distance mode: 1.1 max_distance / (2 R_min) = %.17g", 1.1 * MAX_DISTANCE / (2.0 * R_J)));
    EXPECT_OK(granbond_bond_contact_distance_factor(stress, R_J, &d),
              "granbond_bond_contact_distance_factor, stress mode");
    CHECK(close_to(d, 1.1 * (CREATE_DISTANCE + 0.5 * 1.0e7 / p.k_fn2) / (2.0 * R_J), 1e-14),
          "stress mode: 1.1 (create_distance + gamma max_sigma / k_fn2) / (2 R_min)");
    EXPECT_OK(granbond_bond_contact_distance_factor(unbreakable, R_J, &d),
              "granbond_bond_contact_distance_factor, stress mode without limit");
    CHECK(isinf(d) && d > 0.0, "unlimited stretch: +inf");
    EXPECT_OK(granbond_bond_contact_distance_factor(m, 1.0, &d),
              "granbond_bond_contact_distance_factor, huge spheres");
    CHECK(d == 1.0, "never below 1");
    EXPECT(granbond_bond_contact_distance_factor(m, 0.0, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = 0");
    EXPECT_MESSAGE("min_radius");
    EXPECT(granbond_bond_contact_distance_factor(m, NAN, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = NaN");
    EXPECT(granbond_bond_contact_distance_factor(m, INFINITY, &d), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_contact_distance_factor, min_radius = inf");

    EXPECT_OK(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, mass_j, &dt), "granbond_bond_critical_timestep");
    m_eff = mass_i * mass_j / (mass_i + mass_j);
    rb = LAMBDA * R_J;
    area = PI * rb * rb;
    bound = 2.0 * sqrt(m_eff / (p.k_fn2 * area));
    CHECK(isfinite(dt) && dt > 0.0, say("critical time step %.6g s is positive and finite", dt));
    CHECK(dt <= bound * (1.0 + 1e-12), say("critical time step <= 2 sqrt(m_eff / (k_fn2 A)) = %.6g s", bound));
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, 0.0, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_i = 0");
    EXPECT_MESSAGE("mass_i");
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, -1.0, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_j < 0");
    EXPECT_MESSAGE("mass_j");
    EXPECT(granbond_bond_critical_timestep(m, R_I, R_J, NAN, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, mass_i = NaN");
    EXPECT(granbond_bond_critical_timestep(m, 0.0, R_J, mass_i, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, radius_i = 0");
    EXPECT_MESSAGE("radius_i");
    EXPECT(granbond_bond_critical_timestep(m, R_I, INFINITY, mass_i, mass_j, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_critical_timestep, radius_j = inf");

    {
        double recommended = 0.0;
        EXPECT_OK(granbond_bond_critical_timestep(m, R_I, R_J, mass_i, mass_j, &dt),
                  "granbond_bond_critical_timestep");
        EXPECT_OK(granbond_bond_recommended_timestep(m, R_I, R_J, mass_i, mass_j, &recommended),
                  "granbond_bond_recommended_timestep");
        CHECK(recommended > 0.0 && recommended < dt,
              say("recommended step %.6g s is below the critical step %.6g s", recommended, dt));
        EXPECT(granbond_bond_recommended_timestep(m, R_I, R_J, 0.0, mass_j, &recommended),
               GB_STATUS_INVALID_ARGUMENT, "granbond_bond_recommended_timestep, mass_i = 0");
        EXPECT_MESSAGE("mass_i");
    }

    granbond_bond_model_free(unbreakable);
    granbond_bond_model_free(stress);
    granbond_bond_model_free(m);
    return 0;
}
