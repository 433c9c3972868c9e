/*
 * A bond's named output fields (granbond_bond_field_*, granbond_bond_fields)
 * and the stress limits of a break (granbond_bond_stress_limits), on a bond
 * stretched along the virgin tension line.
 */

#include "harness.h"

/* The position of field `name` in the library's table, or -1. */
static int field_index(const char *name)
{
    size_t n = granbond_bond_field_count(), f;
    for (f = 0; f < n; f++) {
        const char *fname = NULL, *unit = NULL, *description = NULL;
        if (granbond_bond_field_info(f, &fname, &unit, &description) == GB_STATUS_OK && strcmp(fname, name) == 0)
            return (int)f;
    }
    return -1;
}

int test_bond_fields(void)
{
    const double stretch = 2.0e-7, sigma_max = 5.0e7, tau_max = 4.0e7, gamma = 0.5;
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbPairKinematics k;
    GbBondOutput out;
    double state[GRANBOND_BOND_STATE_LEN], record[64], values[64], limit_sigma = -1.0, limit_tau = -1.0;
    const char *name = NULL, *unit = NULL, *description = NULL;
    size_t n = granbond_bond_field_count(), f;
    double area, force;
    int c;

    CHECK(n > 10 && n <= 64, "granbond_bond_field_count: a table of fields");
    for (f = 0; f < n; f++) {
        EXPECT_OK(granbond_bond_field_info(f, &name, &unit, &description), "granbond_bond_field_info");
        CHECK(name && unit && description && name[0] && unit[0] && description[0],
              "every field has a name, a unit and a description");
    }
    EXPECT(granbond_bond_field_info(n, &name, &unit, &description), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_field_info past the table");
    EXPECT_NULL_ARG(granbond_bond_field_info(0, NULL, &unit, &description), "granbond_bond_field_info", "name");
    CHECK(field_index("status") == 0 && field_index("normal_force") > 0 && field_index("sigma_ratio") > 0,
          "status, normal_force and sigma_ratio are fields");

    p.stress_break = 1;
    p.max_sigma = sigma_max;
    p.max_tau = tau_max;
    p.use_ratio = 1;
    p.tension_compression_ratio = gamma;
    if (new_bond_model(&p, &m)) return 1;
    if (create_bond(m, state)) return 1;
    pair_at(&k, R0_NOMINAL + stretch, R_I, R_J);
    EXPECT_OK(granbond_bond_compute(m, &k, DT, state, &out), "granbond_bond_compute(stretched)");
    CHECK(GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN <= 64, "the record fits the test's buffer");
    memset(record, 0, sizeof record);
    for (c = 0; c < GRANBOND_BOND_STATE_LEN; c++)
        record[c] = state[c];
    EXPECT_OK(granbond_bond_output_store(&out, record + GRANBOND_BOND_STATE_LEN), "granbond_bond_output_store");
    {
        const char *name = NULL, *unit = NULL, *description = NULL;
        EXPECT_OK(granbond_bond_energy_field_info(0, &name, &unit, &description), "granbond_bond_energy_field_info");
        CHECK(strcmp(name, "energy_stored") == 0 && strcmp(unit, "J") == 0, "the first energy field");
        EXPECT(granbond_bond_energy_field_info(granbond_bond_energy_field_count(), &name, &unit, &description),
               GB_STATUS_INVALID_ARGUMENT, "granbond_bond_energy_field_info, beyond the table");
    }
    EXPECT_OK(granbond_bond_fields(m, record, k.x_i, k.x_j, values), "granbond_bond_fields");

    /* eq. 5, virgin tension: k_fn2 |delta| on A = pi (lambda min R)^2 */
    area = PI * (LAMBDA * R_J) * (LAMBDA * R_J);
    force = p.k_fn2 * area * stretch;
    CHECK(values[field_index("status")] == 1.0, "status 1 (intact)");
    CHECK(close_to(values[field_index("stretch")], stretch, 1e-6), "stretch = r - r0");
    CHECK(close_to(values[field_index("normal_force")], -force, 1e-6), "normal_force = -k_fn2 A |delta|");
    CHECK(close_to(values[field_index("sigma")], p.k_fn2 * stretch, 1e-6), "sigma = k_fn2 |delta|");
    CHECK(values[field_index("sigma_max")] == gamma * sigma_max, "sigma_max: the tensile limit gamma sigma_max");
    CHECK(close_to(values[field_index("sigma_ratio")], p.k_fn2 * stretch / (gamma * sigma_max), 1e-6),
          "sigma_ratio = sigma / (gamma sigma_max)");

    EXPECT_OK(granbond_bond_stress_limits(m, -stretch, &limit_sigma, &limit_tau), "granbond_bond_stress_limits");
    CHECK(limit_sigma == gamma * sigma_max && limit_tau == tau_max, "stretched: gamma sigma_max and tau_max");
    EXPECT_OK(granbond_bond_stress_limits(m, stretch, &limit_sigma, &limit_tau), "granbond_bond_stress_limits");
    CHECK(limit_sigma == sigma_max && limit_tau == tau_max, "compressed: sigma_max and tau_max");
    EXPECT(granbond_bond_stress_limits(m, NAN, &limit_sigma, &limit_tau), GB_STATUS_NON_FINITE_INPUT, "delta NaN");
    EXPECT_MESSAGE("delta");
    EXPECT_NULL_ARG(granbond_bond_stress_limits(NULL, 0.0, &limit_sigma, &limit_tau), "granbond_bond_stress_limits",
                    "model");

    EXPECT(granbond_bond_fields(m, record, k.x_i, k.x_i, values), GB_STATUS_INVALID_ARGUMENT,
           "coincident centres");
    EXPECT_MESSAGE("coincide");
    EXPECT_NULL_ARG(granbond_bond_fields(m, NULL, k.x_i, k.x_j, values), "granbond_bond_fields", "record");
    EXPECT_NULL_ARG(granbond_bond_fields(m, record, k.x_i, k.x_j, NULL), "granbond_bond_fields", "values");
    granbond_bond_model_free(m);
    return 0;
}
