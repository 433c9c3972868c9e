/*
 * The checks every file reports through, number helpers and fixtures
 * (declared in harness.h).
 */

#include "harness.h"

/* ------------------------------------------------------------------------ */
/* Reporting                                                                 */
/* ------------------------------------------------------------------------ */

int n_checks = 0;

const char *status_name(GbStatus s)
{
    switch (s) {
    case GB_STATUS_OK:
        return "GB_STATUS_OK";
    case GB_STATUS_NULL_POINTER:
        return "GB_STATUS_NULL_POINTER";
    case GB_STATUS_INVALID_PARAMETER:
        return "GB_STATUS_INVALID_PARAMETER";
    case GB_STATUS_NON_FINITE_INPUT:
        return "GB_STATUS_NON_FINITE_INPUT";
    case GB_STATUS_COINCIDENT_CENTRES:
        return "GB_STATUS_COINCIDENT_CENTRES";
    case GB_STATUS_NON_POSITIVE_RADIUS:
        return "GB_STATUS_NON_POSITIVE_RADIUS";
    case GB_STATUS_LAYOUT_MISMATCH:
        return "GB_STATUS_LAYOUT_MISMATCH";
    case GB_STATUS_INVALID_ARGUMENT:
        return "GB_STATUS_INVALID_ARGUMENT";
    case GB_STATUS_PANIC:
        return "GB_STATUS_PANIC";
    case GB_STATUS_MISALIGNED:
        return "GB_STATUS_MISALIGNED";
    case GB_STATUS_NON_FINITE_RESULT:
        return "GB_STATUS_NON_FINITE_RESULT";
    }
    return "(unknown status)";
}

/* printf into a static buffer: a check description, used at once. */
const char *say(const char *format, ...)
{
    static char buffer[512];
    va_list args;
    va_start(args, format);
    vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return buffer;
}

const char *last_message(void)
{
    const char *m = granbond_last_error_message();
    return m != NULL ? m : "(NULL)";
}

int check_(int ok, const char *what, const char *condition, const char *file, int line)
{
    n_checks++;
    if (!ok) {
        printf("FAIL %s\n     at %s:%d: %s is false\n     last error message: \"%s\"\n", what, file, line,
               condition, last_message());
        return 0;
    }
    printf("ok   %s\n", what);
    return 1;
}

/* A call's status; on success the thread's error must be cleared, on
 * failure there must be a message. */
int expect_(GbStatus got, GbStatus want, const char *what, const char *file, int line)
{
    const char *message = granbond_last_error_message();
    int32_t parameter = granbond_last_error_parameter();
    n_checks++;
    if (message == NULL) {
        printf("FAIL %s\n     at %s:%d: granbond_last_error_message() returned NULL\n", what, file, line);
        return 0;
    }
    if (got != want) {
        printf("FAIL %s\n     at %s:%d: status %s (%d), expected %s (%d)\n     last error message: \"%s\"\n",
               what, file, line, status_name(got), (int)got, status_name(want), (int)want, message);
        return 0;
    }
    if (want == GB_STATUS_OK && (message[0] != '\0' || parameter != -1)) {
        printf("FAIL %s\n     at %s:%d: success left an error behind: message \"%s\", parameter %d\n", what,
               file, line, message, (int)parameter);
        return 0;
    }
    if (want != GB_STATUS_OK && message[0] == '\0') {
        printf("FAIL %s\n     at %s:%d: %s without a message\n", what, file, line, status_name(got));
        return 0;
    }
    if (want == GB_STATUS_OK)
        printf("ok   %s -> %s\n", what, status_name(got));
    else
        printf("ok   %s -> %s: %s\n", what, status_name(got), message);
    return 1;
}

/* The last error message contains `needle`. */
int message_has_(const char *needle, const char *file, int line)
{
    const char *m = last_message();
    n_checks++;
    if (strstr(m, needle) == NULL) {
        printf("FAIL message names \"%s\"\n     at %s:%d: message is \"%s\"\n", needle, file, line, m);
        return 0;
    }
    printf("ok   message names \"%s\"\n", needle);
    return 1;
}

/* A NULL pointer argument: NULL_POINTER, a message naming the function and
 * the argument, no parameter id. */
int null_arg_(GbStatus got, const char *function, const char *argument, const char *file, int line)
{
    char what[256];
    char needle[128];
    const char *m;
    snprintf(what, sizeof what, "%s with %s = NULL", function, argument);
    if (!expect_(got, GB_STATUS_NULL_POINTER, what, file, line))
        return 0;
    m = last_message();
    snprintf(needle, sizeof needle, "`%s`", argument);
    n_checks++;
    if (strstr(m, needle) == NULL || strstr(m, function) == NULL || strstr(m, "null") == NULL) {
        printf("FAIL %s\n     at %s:%d: message \"%s\" does not name the function and %s\n", what, file, line,
               m, needle);
        return 0;
    }
    if (granbond_last_error_parameter() != -1) {
        printf("FAIL %s\n     at %s:%d: parameter id %d after a pointer error\n", what, file, line,
               (int)granbond_last_error_parameter());
        return 0;
    }
    printf("ok   %s: message names %s\n", what, needle);
    return 1;
}

/* ------------------------------------------------------------------------ */
/* Numbers and vectors                                                       */
/* ------------------------------------------------------------------------ */

int close_to(double got, double want, double rel)
{
    if (!isfinite(got))
        return 0;
    if (want == 0.0)
        return fabs(got) <= rel;
    return fabs(got - want) <= rel * fabs(want);
}

double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double norm3(const double a[3])
{
    return sqrt(dot3(a, a));
}

double distance3(const double a[3], const double b[3])
{
    double d[3];
    d[0] = a[0] - b[0];
    d[1] = a[1] - b[1];
    d[2] = a[2] - b[2];
    return norm3(d);
}

/* |got - want| <= rel |want| */
int vec_close(const double got[3], const double want[3], double rel)
{
    double d[3];
    int c;
    for (c = 0; c < 3; c++) {
        if (!isfinite(got[c]))
            return 0;
        d[c] = got[c] - want[c];
    }
    return norm3(d) <= rel * norm3(want);
}

int vec_zero(const double v[3])
{
    return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

int vec_equal(const double a[3], const double b[3])
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* ------------------------------------------------------------------------ */
/* Fixtures                                                                  */
/* ------------------------------------------------------------------------ */

const double AXIS[3] = {2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0};
const double X_J[3] = {1.0e-3, -2.0e-3, 0.5e-3};
unsigned char sentinel_object[16];

/* Sphere j at X_J, sphere i at distance r along AXIS; at rest. */
void pair_at(GbPairKinematics *k, double r, double radius_i, double radius_j)
{
    int c;
    memset(k, 0, sizeof *k);
    for (c = 0; c < 3; c++) {
        k->x_j[c] = X_J[c];
        k->x_i[c] = X_J[c] + r * AXIS[c];
    }
    k->radius_i = radius_i;
    k->radius_j = radius_j;
}

/* Two spheres of radius R_C overlapping by `overlap`, i approaching j at
 * `speed` along the centre line. */
void contact_at(GbPairKinematics *k, double overlap, double speed)
{
    int c;
    pair_at(k, 2.0 * R_C - overlap, R_C, R_C);
    for (c = 0; c < 3; c++)
        k->v_i[c] = -speed * AXIS[c];
}

GbBondParams bond_fixture(void)
{
    GbBondParams p;
    memset(&p, 0, sizeof p);
    granbond_bond_params_default(&p);
    p.lambda = LAMBDA;
    p.k_fn1 = 2.0e9;
    p.ku_fn1 = 4.0e9;
    p.kc_fn1 = 1.0e8;
    p.k_fn2 = 1.0e10;
    p.ku_fn2 = 1.0e10;
    p.kc_fn2 = 1.0e9;
    p.k_ft = 5.0e9;
    p.k_tn = 1.0e9;
    p.ku_tn = 2.0e9;
    p.kc_tn = 1.0e8;
    p.k_tt = 1.0e9;
    p.ku_tt = 2.0e9;
    p.kc_tt = 1.0e8;
    p.max_distance = MAX_DISTANCE;
    p.create_distance = CREATE_DISTANCE;
    p.create_step = CREATE_STEP;
    return p;
}

GbVoigtParams voigt_fixture(void)
{
    GbVoigtParams p;
    memset(&p, 0, sizeof p);
    granbond_voigt_params_default(&p);
    return p;
}

GbLayout caller_layout(void)
{
    return granbond_header_layout();
}

/* Index of the slot called `name` in a state of `kind`, or -1. */
int slot_index(int32_t kind, const char *name)
{
    size_t i, len = granbond_state_len(kind);
    for (i = 0; i < len; i++) {
        const char *slot = NULL;
        int32_t flips = 0;
        if (granbond_state_slot(kind, i, &slot, &flips) == GB_STATUS_OK && strcmp(slot, name) == 0)
            return (int)i;
    }
    return -1;
}

int new_bond_model(const GbBondParams *p, GbBondModel **m)
{
    *m = NULL;
    EXPECT_OK(granbond_bond_model_new(p, m), "granbond_bond_model_new");
    CHECK(*m != NULL, "model is not NULL");
    return 0;
}

/* A bond created at the fixture's rest length in `state`. */
int create_bond(const GbBondModel *m, double *state)
{
    GbPairKinematics k;
    int32_t created = -1;
    memset(state, 0, GRANBOND_BOND_STATE_LEN * sizeof(double));
    pair_at(&k, R0_NOMINAL, R_I, R_J);
    {
        /* Immediate creation ignores the step, not the distance. */
        double fresh[GRANBOND_BOND_STATE_LEN] = {0};
        int32_t now = -1;
        EXPECT_OK(granbond_bond_create_now(m, &k, fresh, &now), "granbond_bond_create_now");
        CHECK(now == 1 && fresh[0] > 0.0, "granbond_bond_create_now bonds at any step (a positive rest length)");
        EXPECT_OK(granbond_bond_create_now(m, &k, fresh, &now), "granbond_bond_create_now, intact");
        CHECK(now == 0, "granbond_bond_create_now keeps an intact bond");
    }
    EXPECT_OK(granbond_bond_try_create(m, &k, CREATE_STEP, state, &created), "granbond_bond_try_create");
    CHECK(created == 1, "bond created");
    return 0;
}

int new_voigt_model(const GbVoigtParams *p, GbVoigtModel **m)
{
    *m = NULL;
    EXPECT_OK(granbond_voigt_model_new(p, m), "granbond_voigt_model_new");
    CHECK(*m != NULL, "model is not NULL");
    return 0;
}
