/*
 * The Voigt contact: pairs, walls, time step, contact frames (from the
 * engine's geometry and the radii) and the parts an engine assembles a
 * contact from.
 */

#include "harness.h"

int test_voigt_contact(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k, bad;
    GbContactOutput out;
    double state[GRANBOND_CONTACT_STATE_LEN], copy[GRANBOND_CONTACT_STATE_LEN];
    double n[3], expected[3], v_rel[3], r, overlap, v_n, fn;
    int c;

    if (new_voigt_model(&p, &m))
        return 1;
    memset(state, 0, sizeof state);

    /* Overlap, approaching: Fn = k_n overlap - gamma_n v_n along n. */
    contact_at(&k, 1.0e-5, 0.01);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, overlapping");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++) {
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
        v_rel[c] = k.v_i[c] - k.v_j[c];
    }
    overlap = k.radius_i + k.radius_j - r;
    v_n = dot3(v_rel, n);
    fn = p.k_n * overlap - p.gamma_n * v_n;
    for (c = 0; c < 3; c++)
        expected[c] = fn * n[c];
    CHECK(v_n < 0.0, "approaching: v_n < 0");
    CHECK(close_to(out.overlap, overlap, 1e-12), say("out.overlap = %.17g", overlap));
    CHECK(close_to(out.normal_force, fn, 1e-12), say("out.normal_force = k_n overlap - gamma_n v_n = %.17g N", fn));
    CHECK(vec_close(out.force_i, expected, 1e-12), "force on i = Fn n to 1e-12");
    CHECK(dot3(out.force_i, n) > 0.0, "repulsive");
    CHECK(out.touching == 1 && out.sliding == 0 && out.rolling_slip == 0, "touching, not sliding");

    /* Separating fast: no attraction clamps Fn at 0. */
    contact_at(&k, 1.0e-6, -100.0);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, separating fast");
    CHECK(out.normal_force == 0.0 && out.touching == 1, "no attraction: Fn = 0");

    /* Apart: nothing, and the history is forgotten. */
    for (c = 0; c < GRANBOND_CONTACT_STATE_LEN; c++)
        state[c] = 1.0e-9 * (c + 1);
    contact_at(&k, -1.0e-5, 0.0);
    EXPECT_OK(granbond_voigt_compute(m, &k, DT, state, &out), "granbond_voigt_compute, apart");
    CHECK(out.touching == 0 && vec_zero(out.force_i) && vec_zero(out.torque_i) && vec_zero(out.torque_j) &&
              out.normal_force == 0.0,
          "apart: not touching, no force, no torque");
    CHECK(close_to(out.overlap, -1.0e-5, 1e-9), "apart: overlap < 0 reported");
    for (c = 0; c < GRANBOND_CONTACT_STATE_LEN; c++)
        CHECK(state[c] == 0.0, say("apart: state slot %d zeroed", c));

    /* Errors. */
    contact_at(&k, 1.0e-5, 0.01);
    memcpy(copy, state, sizeof state);
    bad = k;
    memcpy(bad.x_i, bad.x_j, sizeof bad.x_i);
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_COINCIDENT_CENTRES,
           "granbond_voigt_compute, coincident centres");
    bad = k;
    bad.w_i[2] = NAN;
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_compute, NaN w_i");
    bad = k;
    bad.radius_j = 0.0;
    EXPECT(granbond_voigt_compute(m, &bad, DT, state, &out), GB_STATUS_NON_POSITIVE_RADIUS,
           "granbond_voigt_compute, radius_j = 0");
    EXPECT(granbond_voigt_compute(m, &k, -DT, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute, dt < 0");
    EXPECT(granbond_voigt_compute(m, &k, NAN, state, &out), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_compute, dt = NaN");
    CHECK(memcmp(copy, state, sizeof state) == 0, "state untouched");

    granbond_voigt_model_free(m);
    return 0;
}

/* The frame of a pair as the LAMMPS adapter builds it: from the separation. */
static GbStatus pair_frame(const GbPairKinematics *k, GbContactFrame *f)
{
    double del[3];
    int c;
    for (c = 0; c < 3; c++)
        del[c] = k->x_i[c] - k->x_j[c];
    return granbond_contact_frame_separation(del, del[0] * del[0] + del[1] * del[1] + del[2] * del[2], k->radius_i,
                                             k->radius_j, k->v_i, k->v_j, k->w_i, k->w_j, f);
}

/* A sphere pressed into a wall, handed over as the LIGGGHTS adapter does:
 * the wall's normal, the centre's distance from it, and radius 0. */
int test_voigt_wall(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbContactOutput out;
    double state[GRANBOND_CONTACT_STATE_LEN];
    const double overlap = 2.0e-5, speed = 0.02, normal[3] = {0.0, 0.0, 1.0}, gap = R_C - overlap;
    const double v_i[3] = {0.0, 0.0, -speed}, zero[3] = {0.0, 0.0, 0.0};
    double fn;

    if (new_voigt_model(&p, &m))
        return 1;
    memset(state, 0, sizeof state);
    EXPECT_OK(granbond_voigt_compute_normal_unchecked(m, normal, gap, R_C, 0.0, v_i, zero, zero, zero, DT, state, &out),
              "granbond_voigt_compute_normal_unchecked, sphere pressed into a wall");
    fn = p.k_n * (R_C - gap) + p.gamma_n * speed;
    CHECK(close_to(out.overlap, R_C - gap, 1e-12), "wall overlap = R - gap");
    CHECK(close_to(out.normal_force, fn, 1e-12), say("wall Fn = k_n overlap - gamma_n v_n = %.17g N", fn));
    CHECK(close_to(out.force_i[2], fn, 1e-12) && out.force_i[0] == 0.0 && out.force_i[1] == 0.0,
          "force along the wall normal, repulsive");
    CHECK(out.touching == 1, "touching");

    granbond_voigt_model_free(m);
    return 0;
}

int test_voigt_timestep(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    const double mass = 2500.0 * 4.0 / 3.0 * PI * R_C * R_C * R_C;
    double dt = -1.0, bound;

    if (new_voigt_model(&p, &m))
        return 1;
    EXPECT_OK(granbond_voigt_critical_timestep(m, R_C, R_C, mass, mass, &dt), "granbond_voigt_critical_timestep");
    bound = 2.0 * sqrt(0.5 * mass / p.k_n);
    CHECK(isfinite(dt) && dt > 0.0, say("critical time step %.6g s is positive and finite", dt));
    CHECK(dt <= bound * (1.0 + 1e-12), say("critical time step <= 2 sqrt(m_eff / k_n) = %.6g s", bound));
    EXPECT(granbond_voigt_critical_timestep(m, R_C, R_C, 0.0, mass, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, mass_i = 0");
    EXPECT_MESSAGE("mass_i");
    EXPECT(granbond_voigt_critical_timestep(m, R_C, R_C, mass, NAN, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, mass_j = NaN");
    EXPECT(granbond_voigt_critical_timestep(m, R_C, -R_C, mass, mass, &dt), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_critical_timestep, radius_j < 0");
    EXPECT_MESSAGE("radius_j");
    granbond_voigt_model_free(m);
    return 0;
}

int test_contact_frames(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k;
    GbContactFrame frame, tilted;
    double n[3], r, del[3], fn = 0.0;
    const double wall_normal[3] = {0.0, 0.0, 1.0}, wall_velocity[3] = {0.01, 0.0, 0.0}, zero[3] = {0.0, 0.0, 0.0};
    const double sphere_v[3] = {0.0, 0.0, -0.02}, sphere_w[3] = {0.0, 1.5, 0.0};
    int c;

    /* Sphere pair, from its separation. */
    contact_at(&k, 1.0e-5, 0.01);
    k.radius_j = 0.7e-3;
    k.w_i[0] = 0.2;
    k.w_j[1] = -0.3;
    k.v_j[2] = 0.004;
    memset(&frame, 0xAB, sizeof frame);
    EXPECT_OK(pair_frame(&k, &frame), "granbond_contact_frame_separation");
    r = distance3(k.x_i, k.x_j);
    for (c = 0; c < 3; c++)
        n[c] = (k.x_i[c] - k.x_j[c]) / r;
    CHECK(vec_close(frame.n, n, 1e-15), "frame.n = (x_i - x_j) / |x_i - x_j|");
    CHECK(close_to(frame.overlap, k.radius_i + k.radius_j - r, 1e-12), "frame.overlap = R_i + R_j - r");
    CHECK(frame.lever_i == k.radius_i && frame.lever_j == k.radius_j, "frame levers = radii");
    CHECK(close_to(frame.r_eff, k.radius_i * k.radius_j / (k.radius_i + k.radius_j), 1e-15),
          "frame.r_eff = R_i R_j / (R_i + R_j)");
    CHECK(vec_equal(frame.v_i, k.v_i) && vec_equal(frame.v_j, k.v_j) && vec_equal(frame.w_i, k.w_i) &&
              vec_equal(frame.w_j, k.w_j),
          "frame velocities = kinematics");
    memset(del, 0, sizeof del);
    EXPECT(granbond_contact_frame_separation(del, 0.0, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j, &frame),
           GB_STATUS_COINCIDENT_CENTRES, "granbond_contact_frame_separation, coincident centres");

    /* Sphere on a wall: the wall is the j side, radius 0, with no lever. */
    memset(&frame, 0xAB, sizeof frame);
    EXPECT_OK(granbond_contact_frame_normal(wall_normal, R_C - 3.0e-5, R_C, 0.0, sphere_v, wall_velocity, sphere_w,
                                            zero, &frame),
              "granbond_contact_frame_normal, a wall");
    CHECK(vec_equal(frame.n, wall_normal), "frame.n = wall normal");
    CHECK(close_to(frame.overlap, 3.0e-5, 1e-9), "frame.overlap = R - gap");
    CHECK(frame.lever_i == R_C && frame.lever_j == 0.0 && frame.r_eff == R_C, "levers R and 0, r_eff = R");
    CHECK(vec_equal(frame.v_i, sphere_v) && vec_equal(frame.v_j, wall_velocity) && vec_equal(frame.w_i, sphere_w) &&
              vec_zero(frame.w_j),
          "frame velocities: sphere, wall, no wall spin");

    /* A frame handed back to the parts must have a unit normal. */
    if (new_voigt_model(&p, &m))
        return 1;
    tilted = frame;
    tilted.n[2] = 0.5;
    EXPECT(granbond_voigt_normal_force(m, &tilted, &fn), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_normal_force, |n| = 0.5");
    EXPECT_MESSAGE("unit");
    granbond_voigt_model_free(m);
    return 0;
}

/* normal + tangential + rolling over a frame, assembled as an engine would. */
static int voigt_by_parts(const GbVoigtModel *m, const GbContactFrame *f, int rolling, double dt, double *state,
                          GbContactOutput *out)
{
    GbTangentialOutput t;
    double fn = -1.0, t_r[3] = {0.0, 0.0, 0.0};
    int32_t slip = 0;
    int c;
    EXPECT_OK(granbond_voigt_normal_force(m, f, &fn), "granbond_voigt_normal_force");
    EXPECT_OK(granbond_voigt_tangential(m, f, fn, dt, state, &t), "granbond_voigt_tangential");
    if (rolling)
        EXPECT_OK(granbond_voigt_rolling(m, f, fn, dt, state + 3, t_r, &slip), "granbond_voigt_rolling");
    memset(out, 0, sizeof *out);
    for (c = 0; c < 3; c++) {
        out->force_i[c] = f->n[c] * fn + t.force_i[c];
        out->torque_i[c] = t.torque_i[c] + t_r[c];
        out->torque_j[c] = t.torque_j[c] - t_r[c];
    }
    out->normal_force = fn;
    out->overlap = f->overlap;
    out->touching = 1;
    out->sliding = t.sliding;
    out->rolling_slip = slip;
    return 0;
}

static int same_contact_output(const GbContactOutput *a, const GbContactOutput *b)
{
    return vec_close(a->force_i, b->force_i, 1e-15) && vec_close(a->torque_i, b->torque_i, 1e-15) &&
           vec_close(a->torque_j, b->torque_j, 1e-15) && close_to(a->normal_force, b->normal_force, 1e-15) &&
           a->touching == b->touching && a->sliding == b->sliding && a->rolling_slip == b->rolling_slip;
}

static int identical_contact_output(const GbContactOutput *a, const GbContactOutput *b)
{
    return memcmp(a->force_i, b->force_i, sizeof a->force_i) == 0 &&
           memcmp(a->torque_i, b->torque_i, sizeof a->torque_i) == 0 &&
           memcmp(a->torque_j, b->torque_j, sizeof a->torque_j) == 0 &&
           memcmp(&a->normal_force, &b->normal_force, sizeof a->normal_force) == 0 &&
           memcmp(&a->overlap, &b->overlap, sizeof a->overlap) == 0 && a->touching == b->touching &&
           a->sliding == b->sliding && a->rolling_slip == b->rolling_slip;
}

int test_voigt_parts(void)
{
    const GbVoigtParams p = voigt_fixture();
    GbVoigtModel *m = NULL;
    GbPairKinematics k;
    GbContactFrame frame, bad;
    GbContactOutput whole, parts;
    GbTangentialOutput t;
    double state_whole[GRANBOND_CONTACT_STATE_LEN], state_parts[GRANBOND_CONTACT_STATE_LEN];
    double state_sep[GRANBOND_CONTACT_STATE_LEN], state_normal[GRANBOND_CONTACT_STATE_LEN];
    GbContactOutput sep, normal;
    GbContactFrame built;
    double del[3], rsq, distance;
    double fn = 0.0, v_rel[3], torque[3], spring[3] = {0.0, 0.0, 0.0}, angle[3] = {0.0, 0.0, 0.0};
    int32_t slip = 0;
    int step, c;

    if (new_voigt_model(&p, &m))
        return 1;

    /* The parts, and the unchecked whole step on the engine's geometry,
     * reproduce granbond_voigt_compute, step after step. */
    memset(state_whole, 0, sizeof state_whole);
    memset(state_parts, 0, sizeof state_parts);
    memset(state_sep, 0, sizeof state_sep);
    memset(state_normal, 0, sizeof state_normal);
    for (step = 0; step < 4; step++) {
        contact_at(&k, 1.0e-5 + 1.0e-6 * step, 0.01);
        k.v_i[0] += 2.0e-3;
        k.w_i[1] = 0.4;
        k.w_j[0] = -0.1 * step;
        EXPECT_OK(granbond_voigt_compute(m, &k, DT, state_whole, &whole), say("granbond_voigt_compute, step %d", step));
        EXPECT_OK(pair_frame(&k, &frame), say("granbond_contact_frame_separation, step %d", step));
        if (voigt_by_parts(m, &frame, p.rolling, DT, state_parts, &parts))
            return 1;
        CHECK(same_contact_output(&whole, &parts), say("step %d: normal + tangential + rolling = whole step", step));
        CHECK(vec_close(state_whole, state_parts, 1e-15) && vec_close(state_whole + 3, state_parts + 3, 1e-15),
              say("step %d: same spring and rolling angle", step));
        /* From the engine's geometry and the radii: the same frame, the same bits. */
        for (c = 0; c < 3; c++)
            del[c] = k.x_i[c] - k.x_j[c];
        rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        distance = sqrt(rsq);
        EXPECT_OK(granbond_contact_frame_normal(frame.n, distance, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i, k.w_j,
                                                &built),
                  say("granbond_contact_frame_normal, step %d", step));
        CHECK(memcmp(&built, &frame, sizeof built) == 0,
              say("step %d: the frame from the normal and distance = the frame from the separation", step));
        EXPECT_OK(granbond_voigt_compute_separation_unchecked(m, del, rsq, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i,
                                                              k.w_j, DT, state_sep, &sep),
                  say("granbond_voigt_compute_separation_unchecked, step %d", step));
        CHECK(same_contact_output(&sep, &whole) && memcmp(state_sep, state_whole, sizeof state_sep) == 0,
              say("step %d: unchecked step on the separation = granbond_voigt_compute", step));
        EXPECT_OK(granbond_voigt_compute_normal_unchecked(m, frame.n, distance, k.radius_i, k.radius_j, k.v_i, k.v_j,
                                                          k.w_i, k.w_j, DT, state_normal, &normal),
                  say("granbond_voigt_compute_normal_unchecked, step %d", step));
        CHECK(identical_contact_output(&normal, &sep) && memcmp(state_normal, state_sep, sizeof state_sep) == 0,
              say("step %d: unchecked step on the normal and distance = on the separation, bit for bit", step));
    }
    bad = frame;
    bad.w_j[2] = NAN;
    EXPECT(granbond_voigt_compute_normal_unchecked(m, bad.n, distance, k.radius_i, k.radius_j, bad.v_i, bad.v_j, bad.w_i,
                                                   bad.w_j, DT, state_normal, &normal),
           GB_STATUS_NON_FINITE_RESULT, "granbond_voigt_compute_normal_unchecked, NaN w_j: a non-finite torque is reported");
    EXPECT_MESSAGE("granbond_voigt_compute_normal_unchecked");

    /* The normal part alone: k_n overlap - gamma_n v_n. */
    contact_at(&k, 1.0e-5, 0.01);
    EXPECT_OK(pair_frame(&k, &frame), "granbond_contact_frame_separation");
    EXPECT_OK(granbond_voigt_normal_force(m, &frame, &fn), "granbond_voigt_normal_force");
    for (c = 0; c < 3; c++)
        v_rel[c] = frame.v_i[c] - frame.v_j[c];
    CHECK(close_to(fn, p.k_n * frame.overlap - p.gamma_n * dot3(v_rel, frame.n), 1e-12),
          "granbond_voigt_normal_force = k_n overlap - gamma_n v_n");

    /* Sliding: the tangential force sits on the Coulomb cap mu |Fn|. */
    k.v_i[0] += 10.0;
    EXPECT_OK(pair_frame(&k, &frame), "granbond_contact_frame_separation, fast slip");
    EXPECT_OK(granbond_voigt_tangential(m, &frame, fn, 1.0e-3, spring, &t), "granbond_voigt_tangential, fast slip");
    CHECK(t.sliding == 1 && close_to(norm3(t.force_i), p.mu * fabs(fn), 1e-12), "sliding: |Ft| = mu |Fn|");
    CHECK(fabs(dot3(t.force_i, frame.n)) <= 1e-12 * norm3(t.force_i), "Ft is tangential");

    /* A model without rolling resistance gives no rolling torque and
     * forgets the rolling angle. */
    {
        GbVoigtParams q = p;
        GbVoigtModel *off = NULL;
        double a[3] = {1.0e-3, 2.0e-3, 0.0}, tq[3] = {1.0, 1.0, 1.0};
        int32_t sl = 7;
        q.rolling = 0;
        if (new_voigt_model(&q, &off))
            return 1;
        EXPECT_OK(granbond_voigt_rolling(off, &frame, fn, DT, a, tq, &sl), "granbond_voigt_rolling, rolling off");
        CHECK(norm3(tq) == 0.0 && norm3(a) == 0.0 && sl == 0, "rolling off: no torque, angle zeroed");
        granbond_voigt_model_free(off);
    }

    /* Evaluating without advancing: the stored state is read, not written,
     * and a step of the same frame with dt = 0 gives the same loads. */
    {
        double held[GRANBOND_CONTACT_STATE_LEN] = {1.0e-7, -2.0e-7, 0.0, 3.0e-4, 1.0e-4, 0.0};
        double copy[GRANBOND_CONTACT_STATE_LEN], tq[3], tq0[3];
        GbContactOutput ev, st;
        GbTangentialOutput te, t0;
        int32_t sl = 0, sl0 = 0;
        memcpy(copy, held, sizeof held);
        EXPECT_OK(granbond_voigt_evaluate_frame(m, &frame, held, &ev), "granbond_voigt_evaluate_frame");
        CHECK(memcmp(copy, held, sizeof held) == 0, "granbond_voigt_evaluate_frame leaves the state alone");
        for (c = 0; c < 3; c++)
            del[c] = k.x_i[c] - k.x_j[c];
        rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        EXPECT_OK(granbond_voigt_compute_separation_unchecked(m, del, rsq, k.radius_i, k.radius_j, k.v_i, k.v_j, k.w_i,
                                                              k.w_j, 0.0, copy, &st),
                  "granbond_voigt_compute_separation_unchecked, dt = 0");
        CHECK(close_to(ev.force_i[0], st.force_i[0], 1e-15) && close_to(ev.force_i[1], st.force_i[1], 1e-15) &&
                  close_to(ev.torque_i[2], st.torque_i[2], 1e-15),
              "evaluation = a step of zero length");
        memcpy(copy, held, sizeof held);
        EXPECT_OK(granbond_voigt_tangential_evaluate(m, &frame, fn, held, &te), "granbond_voigt_tangential_evaluate");
        EXPECT_OK(granbond_voigt_tangential(m, &frame, fn, 0.0, copy, &t0), "granbond_voigt_tangential, dt = 0");
        CHECK(close_to(te.force_i[1], t0.force_i[1], 1e-15), "tangential evaluation = a step of zero length");
        EXPECT_OK(granbond_voigt_rolling_evaluate(m, &frame, fn, held + 3, tq, &sl), "granbond_voigt_rolling_evaluate");
        EXPECT_OK(granbond_voigt_rolling(m, &frame, fn, 0.0, copy + 3, tq0, &sl0), "granbond_voigt_rolling, dt = 0");
        CHECK(close_to(tq[0], tq0[0], 1e-15) && sl == sl0, "rolling evaluation = a step of zero length");
        bad = frame;
        bad.v_i[0] = NAN;
        EXPECT(granbond_voigt_evaluate_frame(m, &bad, held, &ev), GB_STATUS_NON_FINITE_INPUT,
               "granbond_voigt_evaluate_frame, NaN v_i");
    }

    /* Errors. */
    bad = frame;
    bad.overlap = NAN;
    EXPECT(granbond_voigt_normal_force(m, &bad, &fn), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_normal_force, NaN overlap");
    bad = frame;
    bad.n[0] *= 2.0;
    EXPECT(granbond_voigt_normal_force(m, &bad, &fn), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_normal_force, non-unit normal");
    EXPECT_MESSAGE("unit");
    bad = frame;
    bad.w_j[1] = -INFINITY;
    EXPECT(granbond_voigt_tangential(m, &bad, fn, DT, spring, &t), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_tangential, -inf w_j");
    EXPECT(granbond_voigt_tangential(m, &frame, fn, -DT, spring, &t), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_tangential, dt < 0");
    EXPECT(granbond_voigt_tangential(m, &frame, NAN, DT, spring, &t), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_tangential, NaN normal force");
    EXPECT(granbond_voigt_rolling(m, &frame, INFINITY, DT, angle, torque, &slip), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_rolling, infinite normal force");
    EXPECT(granbond_voigt_rolling(m, &bad, fn, DT, angle, torque, &slip), GB_STATUS_NON_FINITE_INPUT,
           "granbond_voigt_rolling, -inf w_j");
    EXPECT(granbond_voigt_rolling(m, &frame, fn, NAN, angle, torque, &slip), GB_STATUS_INVALID_ARGUMENT,
           "granbond_voigt_rolling, dt = NaN");

    granbond_voigt_model_free(m);
    return 0;
}
