/*
 * The granbond C test bed: proves the C ABI from C.
 *
 * Calls every function declared in granbond.h, prints one line per check
 * ("ok   ..." or "FAIL ...") and returns non-zero at the first failure.
 * Built and run by rust-core/tests/c_abi.rs (`cargo test --test c_abi`),
 * which compiles every .c file of this directory as C99 with -Wall -Wextra
 * -Werror and links them against libgranbond.a. They are also compiled
 * (syntax only) as C++11, to prove the header is C++-compatible, so they
 * keep to the common subset of C99 and C++11: no designated initialisers,
 * no compound literals, explicit casts.
 *
 * Expected values come from the models (docs/models/bond-nonlinear.md,
 * docs/models/voigt.md), evaluated here in C from the same inputs.
 *
 * This header: the checks every file reports through, number helpers,
 * fixtures, and the topics' test functions (main.c runs them in order).
 */
#ifndef GRANBOND_TEST_HARNESS_H
#define GRANBOND_TEST_HARNESS_H

#include "granbond.h"

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* M_PI is POSIX, not C99. */
#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* Reporting                                                                 */
/* ------------------------------------------------------------------------ */

extern int n_checks;

const char *status_name(GbStatus s);
/* printf into a static buffer: a check description, used at once. */
const char *say(const char *format, ...);
const char *last_message(void);
int check_(int ok, const char *what, const char *condition, const char *file, int line);
/* A call's status; on success the thread's error must be cleared, on
 * failure there must be a message. */
int expect_(GbStatus got, GbStatus want, const char *what, const char *file, int line);
/* The last error message contains `needle`. */
int message_has_(const char *needle, const char *file, int line);
/* A NULL pointer argument: NULL_POINTER, a message naming the function and
 * the argument, no parameter id. */
int null_arg_(GbStatus got, const char *function, const char *argument, const char *file, int line);

#define CHECK(cond, what)                                                                                    \
    do {                                                                                                     \
        if (!check_((cond) ? 1 : 0, (what), #cond, __FILE__, __LINE__))                                      \
            return 1;                                                                                        \
    } while (0)

#define EXPECT(call, want, what)                                                                             \
    do {                                                                                                     \
        if (!expect_((call), (want), (what), __FILE__, __LINE__))                                            \
            return 1;                                                                                        \
    } while (0)

#define EXPECT_OK(call, what) EXPECT(call, GB_STATUS_OK, what)

#define EXPECT_MESSAGE(needle)                                                                               \
    do {                                                                                                     \
        if (!message_has_((needle), __FILE__, __LINE__))                                                     \
            return 1;                                                                                        \
    } while (0)

#define EXPECT_NULL_ARG(call, function, argument)                                                            \
    do {                                                                                                     \
        if (!null_arg_((call), (function), (argument), __FILE__, __LINE__))                                  \
            return 1;                                                                                        \
    } while (0)

/* ------------------------------------------------------------------------ */
/* Numbers and vectors                                                       */
/* ------------------------------------------------------------------------ */

int close_to(double got, double want, double rel);
double dot3(const double a[3], const double b[3]);
double norm3(const double a[3]);
double distance3(const double a[3], const double b[3]);
/* |got - want| <= rel |want| */
int vec_close(const double got[3], const double want[3], double rel);
int vec_zero(const double v[3]);
int vec_equal(const double a[3], const double b[3]);

/* ------------------------------------------------------------------------ */
/* Fixtures                                                                  */
/* ------------------------------------------------------------------------ */

/* Bond fixture: spheres of radii R_I > R_J, touching at creation. */
#define R_I 1.0e-3
#define R_J 0.8e-3
#define R0_NOMINAL (R_I + R_J)
#define LAMBDA 0.5
#define CREATE_DISTANCE 2.0e-3
#define MAX_DISTANCE 1.9e-3
#define CREATE_STEP 7
#define DT 1.0e-7
/* Voigt fixture: spheres of radius R_C. */
#define R_C 1.0e-3

/* Direction of the centre line (not along an axis): (2, 3, 6) / 7. */
extern const double AXIS[3];
extern const double X_J[3];
/* Something non-NULL to preset output pointers with. */
extern unsigned char sentinel_object[16];

/* Sphere j at X_J, sphere i at distance r along AXIS; at rest. */
void pair_at(GbPairKinematics *k, double r, double radius_i, double radius_j);
/* Two spheres of radius R_C overlapping by `overlap`, i approaching j at
 * `speed` along the centre line. */
void contact_at(GbPairKinematics *k, double overlap, double speed);
GbBondParams bond_fixture(void);
GbVoigtParams voigt_fixture(void);
GbLayout caller_layout(void);
/* Index of the slot called `name` in a state of `kind`, or -1. */
int slot_index(int32_t kind, const char *name);
int new_bond_model(const GbBondParams *p, GbBondModel **m);
/* A bond created at the fixture's rest length in `state`. */
int create_bond(const GbBondModel *m, double *state);
int new_voigt_model(const GbVoigtParams *p, GbVoigtModel **m);

/* The bond parameter table as test_parameter_tables read it from the
 * library (parameters.c; the topics after it use it). */
size_t bond_field_id(const char *keyword);
size_t bond_field_count(void);

/* ------------------------------------------------------------------------ */
/* Tests, by topic (each returns non-zero at its first failed check)         */
/* ------------------------------------------------------------------------ */

/* bond_fields.c */
int test_bond_fields(void);
/* store.c */
int test_bond_store(void);
int test_bond_store_listed(void);

/* layout.c */
int test_version_and_layout(void);
int test_state_layout(void);
/* parameters.c */
int test_parameter_tables(void);
int test_bond_params(void);
int test_voigt_params(void);
int test_deck_phrases(void);
int test_coeff_lines(void);
int test_restart_rows(void);
int test_liggghts_lines(void);
/* bond.c */
int test_bond_create_and_force(void);
int test_bond_errors(void);
int test_bond_indexed_results(void);
int test_bond_indexed(void);
int test_bond_break(void);
int test_bond_limits(void);
/* bond_output.c */
int test_bond_output_slots(void);
int test_bond_centre(void);
/* wall_bond.c */
int test_wall_bond(void);

/* wall_store.c */
int test_wall_store(void);
/* run_checks.c */
int test_run_checks(void);
int test_ledger(void);
/* voigt.c */
int test_voigt_contact(void);
int test_voigt_wall(void);
int test_voigt_timestep(void);
int test_contact_frames(void);
int test_voigt_parts(void);
/* errors_and_nulls.c */
int test_error_state_and_free(void);
int test_null_arguments(void);

#endif /* GRANBOND_TEST_HARNESS_H */
