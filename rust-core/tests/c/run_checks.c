/*
 * Run checks: time step and creation rules over the atom types present.
 */

#include "harness.h"

int test_run_checks(void)
{
    GbBondParams p;
    GbVoigtParams vp;
    GbBondModel *bond = NULL;
    GbVoigtModel *voigt = NULL;
    GbCheckReport report;
    GbTypeBodies bodies[3];
    const GbBondModel *bonds[9] = {0};
    const GbVoigtModel *voigts[9] = {0};
    double critical = 0.0, mass = 2500.0 * 4.0 / 3.0 * PI * 1e-9;
    int t;
    granbond_bond_params_default(&p);
    p.k_fn1 = p.ku_fn1 = p.kc_fn1 = 1e9;
    p.k_fn2 = p.ku_fn2 = p.kc_fn2 = 1e9;
    /* regularised: elastic bonds at rest under the plain square root are
       warned at every step (rattle_timestep.rs) */
    p.compression_linear_below = 1e-6;
    p.k_ft = p.k_tn = p.ku_tn = p.k_tt = p.ku_tt = 1e9;
    p.create_distance = 2.2e-3;
    p.max_distance = 2.08e-3;
    p.create_step = 1;
    p.create_always = 1;
    EXPECT_OK(granbond_bond_model_new(&p, &bond), "granbond_bond_model_new");
    granbond_voigt_params_default(&vp);
    vp.k_n = 1e4;
    EXPECT_OK(granbond_voigt_model_new(&vp, &voigt), "granbond_voigt_model_new");
    /* type 1: spheres of 1 mm; type 2: none */
    for (t = 0; t < 3; t++) {
        bodies[t].radius_min = INFINITY;
        bodies[t].radius_max = 0.0;
        bodies[t].mass_min = INFINITY;
    }
    bodies[1].radius_min = bodies[1].radius_max = 1e-3;
    bodies[1].mass_min = mass;
    bonds[1 * 3 + 1] = bond;
    bonds[1 * 3 + 2] = bond;
    voigts[1 * 3 + 1] = voigt;

    EXPECT_OK(granbond_bond_critical_timestep(bond, 1e-3, 1e-3, mass, mass, &critical), "granbond_bond_critical_timestep");
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 1.01 * critical, 0, "si", "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 2 && report.type_a == 1 && report.type_b == 1 && report.critical == critical,
          say("above the critical step: level 2 on types 1 1 (got %d on %d %d)", report.level, report.type_a, report.type_b));
    CHECK(strstr(report.message, "s: time step") == report.message && strstr(report.message, "EXCEEDS"),
          say("the warning names the style and says EXCEEDS: %s", report.message));
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 0.5 * critical, 0, "si", "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 1, "between the recommended and the critical step: level 1");
    EXPECT_OK(granbond_bond_timestep_check(bonds, 2, bodies, 0.1 * critical, 0, "si", "s", &report), "granbond_bond_timestep_check");
    CHECK(report.level == 0 && report.message[0] == 0, "a safe step: level 0, no message");
    EXPECT(granbond_bond_timestep_check(bonds, 2, bodies, NAN, 0, "si", "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_timestep_check, dt = NaN");
    EXPECT(granbond_bond_timestep_check(bonds, -1, bodies, 1e-6, 0, "si", "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_timestep_check, ntypes = -1");
    EXPECT_MESSAGE("ntypes");

    EXPECT_OK(granbond_voigt_critical_timestep(voigt, 1e-3, 1e-3, mass, mass, &critical),
              "granbond_voigt_critical_timestep");
    EXPECT_OK(granbond_voigt_timestep_check(voigts, 2, bodies, 2.0 * critical, "si", "v", &report),
              "granbond_voigt_timestep_check");
    CHECK(report.level == 2 && strstr(report.message, "stiffest contact"), say("voigt: %s", report.message));

    EXPECT_OK(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, 1, "si", "c", &report), "granbond_bond_creation_check");
    CHECK(report.level == 1 && strstr(report.message, "createDistanceBondnonlinear 2.2e-3 m > maxDistanceBondnonlinear"),
          say("createDistance > maxDistance found, LIGGGHTS names: %s", report.message));
    EXPECT_OK(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, 0, "si", "c", &report), "granbond_bond_creation_check");
    CHECK(strstr(report.message, "create_distance 2.2e-3 m > max_distance"), say("LAMMPS names: %s", report.message));
    EXPECT(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, 2, "si", "c", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_creation_check, naming = 2");

    EXPECT(granbond_bond_timestep_check(bonds, 2, bodies, 0.0, 0, "si", "s", &report), GB_STATUS_INVALID_ARGUMENT,
           "granbond_bond_timestep_check, dt = 0");
    EXPECT_MESSAGE("timestep");

    /* the neighbour reach: 1.1 x 2.08e-3 / 2e-3 of distance mode; 25 diameters refused, naming the reach */
    EXPECT_OK(granbond_bond_neighbour_reach(bond, 1e-3, 1, 1, 1, "si", &critical), "granbond_bond_neighbour_reach");
    CHECK(fabs(critical - 1.1 * 2.08e-3 / 2e-3) < 1e-12, say("reach factor %.17g", critical));
    p.max_distance = 0.05;
    p.create_distance = 2.05e-3;
    granbond_bond_model_free(bond);
    bond = NULL;
    EXPECT_OK(granbond_bond_model_new(&p, &bond), "granbond_bond_model_new");
    EXPECT(granbond_bond_neighbour_reach(bond, 1e-3, 1, 1, 1, "si", &critical), GB_STATUS_INVALID_PARAMETER,
           "granbond_bond_neighbour_reach, 27.5 diameters");
    EXPECT_MESSAGE("maxDistanceBondnonlinear");
    EXPECT(granbond_bond_neighbour_reach(bond, 1e-3, 1, 1, 0, "si", &critical), GB_STATUS_INVALID_PARAMETER,
           "granbond_bond_neighbour_reach, 27.5 diameters, LAMMPS names");
    EXPECT_MESSAGE("max_distance");
    /* no compression stiffness while compression is on: refused at the run's start */
    bonds[1 * 3 + 1] = bonds[1 * 3 + 2] = bond;
    p.max_distance = 2.08e-3;
    p.k_fn1 = 0.0;
    granbond_bond_model_free(bond);
    bond = NULL;
    EXPECT_OK(granbond_bond_model_new(&p, &bond), "granbond_bond_model_new, k_fn1 = 0");
    bonds[1 * 3 + 1] = bonds[1 * 3 + 2] = bond;
    EXPECT(granbond_bond_creation_check(bonds, 2, bodies, 0, 0, 0, 1, "si", "c", &report), GB_STATUS_INVALID_PARAMETER,
           "granbond_bond_creation_check, k_fn1 = 0");
    EXPECT_MESSAGE("stiffnessPerUnitAreaK_fn1");
    EXPECT(granbond_bond_neighbour_reach(NULL, 1e-3, 1, 1, 1, "si", &critical), GB_STATUS_NULL_POINTER,
           "granbond_bond_neighbour_reach, model = NULL");

    granbond_bond_model_free(bond);
    granbond_voigt_model_free(voigt);
    return 0;
}
