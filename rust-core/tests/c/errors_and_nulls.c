/*
 * The thread's error record, freeing, and every pointer argument the ABI
 * must refuse when NULL: one table of entries, each with a function that
 * calls the entry with its argument k set to NULL (valid others), and one
 * loop that checks status and message of each call.
 */

#include "harness.h"

/* ------------------------------------------------------------------------ */
/* Error state and freeing                                                   */
/* ------------------------------------------------------------------------ */

int test_error_state_and_free(void)
{
    GbBondParams p = bond_fixture();
    GbBondModel *m = NULL;
    GbLayout l = caller_layout();

    /* A parameter failure, then a success: the error is cleared. */
    p.k_fn1 = -1.0;
    EXPECT(granbond_bond_model_new(&p, &m), GB_STATUS_INVALID_PARAMETER, "granbond_bond_model_new(k_fn1 = -1)");
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1"), "parameter id set");
    CHECK(granbond_last_error_message()[0] != '\0', "message set");
    /* Reading the error does not clear it. */
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1"), "parameter id still set");
    /* Functions without a status leave it alone. */
    CHECK(granbond_abi_version() == GRANBOND_ABI_VERSION && granbond_bond_parameter_count() == bond_field_count() &&
              granbond_state_len(GB_STATE_KIND_BOND) == GRANBOND_BOND_STATE_LEN,
          "abi_version, parameter_count, state_len");
    CHECK(granbond_last_error_parameter() == (int32_t)bond_field_id("k_fn1") &&
              granbond_last_error_message()[0] != '\0',
          "error unchanged by functions without a status");
    EXPECT_OK(granbond_check_layout(&l), "granbond_check_layout after a failure");
    CHECK(strcmp(granbond_last_error_message(), "") == 0, "granbond_last_error_message() = \"\" after a success");
    CHECK(granbond_last_error_parameter() == -1, "granbond_last_error_parameter() = -1 after a success");

    /* A non-parameter failure reports no parameter id. */
    EXPECT(granbond_bond_model_new(&p, &m), GB_STATUS_INVALID_PARAMETER, "granbond_bond_model_new(k_fn1 = -1)");
    EXPECT_NULL_ARG(granbond_check_layout(NULL), "granbond_check_layout", "expected");

    /* Freeing NULL is a no-op. */
    granbond_bond_model_free(NULL);
    CHECK(1, "granbond_bond_model_free(NULL) returns");
    granbond_voigt_model_free(NULL);
    CHECK(1, "granbond_voigt_model_free(NULL) returns");
    return 0;
}

/* ------------------------------------------------------------------------ */
/* NULL arguments                                                            */
/* ------------------------------------------------------------------------ */

#define N_ITEMS 2
#define MAX_NULLS 9

/* Valid arguments for every entry; the states are checked after each call
 * (a refused call advances nothing). */
struct world {
    GbBondModel *bond;
    GbVoigtModel *voigt;
    GbBondParams bond_params;
    GbVoigtParams voigt_params;
    GbLayout layout;
    GbPairKinematics pair[N_ITEMS];
    GbSphereKinematics sphere;
    GbContactFrame frame;
    GbParameterInfo info;
    GbAtomArrays atoms;
    double x[3 * N_ITEMS * 2], v[3 * N_ITEMS * 2], w[3 * N_ITEMS * 2], radius[N_ITEMS * 2];
    int32_t pairs[2 * N_ITEMS];
    double bond_states[N_ITEMS * GRANBOND_BOND_STATE_LEN];
    double *bond_state_pointers[N_ITEMS];
    double wall_state[GRANBOND_WALL_BOND_STATE_LEN];
    double contact_states[N_ITEMS * GRANBOND_CONTACT_STATE_LEN];
    double point[3];
    GbBondOutput bond_out[N_ITEMS];
    double output_slots[GRANBOND_BOND_OUTPUT_LEN];
    GbContactOutput contact_out[N_ITEMS];
    GbTangentialOutput tangential;
    GbCheckReport report;
    GbTypeBodies bodies[2];
    const GbBondModel *bond_table[4];
    const GbVoigtModel *voigt_table[4];
    double number, vector[3];
    int32_t flag;
    size_t index;
    const char *text[2];
    GbBondModel *made_bond;
    GbVoigtModel *made_voigt;
};

/* `p`, or NULL when argument `i` is the one set to NULL. */
#define ARG(k, i, p) ((k) == (i) ? NULL : (p))

static GbStatus null_check_layout(struct world *c, int k)
{
    return granbond_check_layout(ARG(k, 0, &c->layout));
}

static GbStatus null_state_slot(struct world *c, int k)
{
    return granbond_state_slot(GB_STATE_KIND_BOND, 0, ARG(k, 0, &c->text[0]), ARG(k, 1, &c->flag));
}

static GbStatus null_bond_params_default(struct world *c, int k)
{
    return granbond_bond_params_default(ARG(k, 0, &c->bond_params));
}

static GbStatus null_bond_params_default_in_units(struct world *c, int k)
{
    return granbond_bond_params_default_in_units(ARG(k, 0, "si"), 0, ARG(k, 1, &c->bond_params));
}

static GbStatus null_bond_params_contact_under_bond_by_law(struct world *c, int k)
{
    return granbond_bond_params_contact_under_bond_by_law(ARG(k, 0, &c->bond_params));
}

static const char *const COEFF_WORDS[] = {"voigt", "1e5", "0", "1e5", "0", "0.5", "bond/nonlinear", "k_fn1", "1e3"};

static GbStatus null_pair_coeff_read(struct world *c, int k)
{
    return granbond_pair_coeff_read(ARG(k, 0, "pair_coeff 1 1"), ARG(k, 1, COEFF_WORDS), 9, ARG(k, 2, "si"),
                                    ARG(k, 3, &c->voigt_params), ARG(k, 4, &c->bond_params), ARG(k, 5, &c->flag));
}

static GbStatus null_bond_coeff_read(struct world *c, int k)
{
    return granbond_bond_coeff_read(ARG(k, 0, "bond_coeff 1"), ARG(k, 1, COEFF_WORDS + 7), 2,
                                    ARG(k, 2, &c->bond_params));
}

static const char *const PROPERTY_LINE[] = {"p", "all", "property/global", "k_n", "peratomtypepair", "1", "1e5"};

static GbStatus null_liggghts_property_line_check(struct world *c, int k)
{
    int32_t infinite[7];
    return granbond_liggghts_property_line_check(ARG(k, 0, PROPERTY_LINE), 7, ARG(k, 1, infinite), ARG(k, 2, &c->flag));
}

static GbStatus null_liggghts_settings_check(struct world *c, int k)
{
    (void)c;
    return granbond_liggghts_settings_check(ARG(k, 0, "pair_style gran"), ARG(k, 1, PROPERTY_LINE + 5), 2);
}

/* Restart rows of the world's parameters, valid for the `_from_rows` calls. */
static uint8_t ROWS[4096];

static GbStatus null_bond_params_rows(struct world *c, int k)
{
    return granbond_bond_params_rows(ARG(k, 0, &c->bond_params), ARG(k, 1, ROWS), sizeof ROWS, ARG(k, 2, &c->index));
}

static GbStatus null_bond_params_from_rows(struct world *c, int k)
{
    granbond_bond_params_rows(&c->bond_params, ROWS, sizeof ROWS, &c->index);
    return granbond_bond_params_from_rows(ARG(k, 0, ROWS), c->index, ARG(k, 1, "bond type 1"), ARG(k, 2, &c->bond_params));
}

static GbStatus null_voigt_params_rows(struct world *c, int k)
{
    return granbond_voigt_params_rows(ARG(k, 0, &c->voigt_params), ARG(k, 1, ROWS), sizeof ROWS, ARG(k, 2, &c->index));
}

static GbStatus null_voigt_params_from_rows(struct world *c, int k)
{
    granbond_voigt_params_rows(&c->voigt_params, ROWS, sizeof ROWS, &c->index);
    return granbond_voigt_params_from_rows(ARG(k, 0, ROWS), c->index, ARG(k, 1, "types 1 1"), ARG(k, 2, &c->voigt_params));
}

static GbStatus null_bond_model_new(struct world *c, int k)
{
    return granbond_bond_model_new(ARG(k, 0, &c->bond_params), ARG(k, 1, &c->made_bond));
}

static GbStatus null_bond_parameter_info(struct world *c, int k)
{
    return granbond_bond_parameter_info(0, ARG(k, 0, &c->info));
}

static GbStatus null_bond_params_set(struct world *c, int k)
{
    return granbond_bond_params_set(ARG(k, 0, &c->bond_params), ARG(k, 1, "lambda"), 1.0);
}

static GbStatus null_bond_parameter_needed(struct world *c, int k)
{
    return granbond_bond_parameter_needed(ARG(k, 0, &c->bond_params), 0, ARG(k, 1, &c->flag));
}

static GbStatus null_bond_parameter_liggghts_name(struct world *c, int k)
{
    const char *name = 0;
    (void)c;
    return granbond_bond_parameter_liggghts_name(1, 0, ARG(k, 0, &name));
}

static GbStatus null_bond_try_create(struct world *c, int k)
{
    return granbond_bond_try_create(ARG(k, 0, c->bond), ARG(k, 1, &c->pair[0]), CREATE_STEP,
                                    ARG(k, 2, c->bond_states), ARG(k, 3, &c->flag));
}

static GbStatus null_bond_create_now(struct world *c, int k)
{
    return granbond_bond_create_now(ARG(k, 0, c->bond), ARG(k, 1, &c->pair[0]), ARG(k, 2, c->bond_states),
                                    ARG(k, 3, &c->flag));
}

static GbStatus null_bond_compute(struct world *c, int k)
{
    return granbond_bond_compute(ARG(k, 0, c->bond), ARG(k, 1, &c->pair[0]), DT, ARG(k, 2, c->bond_states),
                                 ARG(k, 3, &c->bond_out[0]));
}

static GbStatus null_bond_compute_indexed(struct world *c, int k)
{
    GbAtomArrays atoms = c->atoms;
    if (k == 5)
        atoms.x = NULL;
    if (k == 6)
        atoms.v = NULL;
    if (k == 7)
        atoms.omega = NULL;
    if (k == 8)
        atoms.radius = NULL;
    return granbond_bond_compute_indexed(ARG(k, 0, c->bond), N_ITEMS, ARG(k, 1, &atoms), ARG(k, 2, c->pairs), DT,
                                         ARG(k, 3, c->bond_state_pointers), ARG(k, 4, c->bond_out), &c->index);
}

static GbStatus null_wall_bond_try_create(struct world *c, int k)
{
    return granbond_wall_bond_try_create(ARG(k, 0, c->bond), ARG(k, 1, &c->sphere), ARG(k, 2, c->point),
                                         CREATE_STEP, ARG(k, 3, c->wall_state), ARG(k, 4, &c->flag));
}

static GbStatus null_wall_bond_compute(struct world *c, int k)
{
    return granbond_wall_bond_compute(ARG(k, 0, c->bond), ARG(k, 1, &c->sphere), ARG(k, 2, c->vector), DT,
                                      ARG(k, 3, c->wall_state), ARG(k, 4, &c->bond_out[0]));
}

static GbStatus null_bond_contact_loads_under_bond(struct world *c, int k)
{
    return granbond_bond_contact_loads_under_bond(ARG(k, 0, c->bond), ARG(k, 1, c->point), 1.0e-6,
                                                  ARG(k, 2, &c->contact_out[0]));
}

static GbStatus null_bond_output_store(struct world *c, int k)
{
    return granbond_bond_output_store(ARG(k, 0, &c->bond_out[0]), ARG(k, 1, c->output_slots));
}

static GbStatus null_bond_output_load(struct world *c, int k)
{
    return granbond_bond_output_load(ARG(k, 0, c->output_slots), ARG(k, 1, &c->bond_out[0]));
}

static GbStatus null_bond_centre(struct world *c, int k)
{
    return granbond_bond_centre(ARG(k, 0, c->pair[0].x_i), ARG(k, 1, c->pair[0].x_j), c->pair[0].radius_i,
                                c->pair[0].radius_j, ARG(k, 2, c->vector));
}

static GbStatus null_bond_max_distance(struct world *c, int k)
{
    return granbond_bond_max_distance(ARG(k, 0, c->bond), R0_NOMINAL, ARG(k, 1, &c->number));
}

static GbStatus null_bond_contact_distance_factor(struct world *c, int k)
{
    return granbond_bond_contact_distance_factor(ARG(k, 0, c->bond), R_J, ARG(k, 1, &c->number));
}

static GbStatus null_bond_critical_timestep(struct world *c, int k)
{
    return granbond_bond_critical_timestep(ARG(k, 0, c->bond), R_I, R_J, 1.0e-5, 1.0e-5, ARG(k, 1, &c->number));
}

static GbStatus null_bond_recommended_timestep(struct world *c, int k)
{
    return granbond_bond_recommended_timestep(ARG(k, 0, c->bond), R_I, R_J, 1.0e-5, 1.0e-5, ARG(k, 1, &c->number));
}

static GbStatus null_bond_timestep_check(struct world *c, int k)
{
    return granbond_bond_timestep_check(ARG(k, 0, c->bond_table), 1, ARG(k, 1, c->bodies), 1.0e-6, 0,
                                        ARG(k, 2, "si"), ARG(k, 3, "s"), ARG(k, 4, &c->report));
}

static GbStatus null_voigt_timestep_check(struct world *c, int k)
{
    return granbond_voigt_timestep_check(ARG(k, 0, c->voigt_table), 1, ARG(k, 1, c->bodies), 1.0e-6,
                                         ARG(k, 2, "si"), ARG(k, 3, "v"), ARG(k, 4, &c->report));
}

static GbStatus null_bond_creation_check(struct world *c, int k)
{
    return granbond_bond_creation_check(ARG(k, 0, c->bond_table), 1, ARG(k, 1, c->bodies), 0, 0, 0, 0,
                                        ARG(k, 2, "si"), ARG(k, 3, "c"), ARG(k, 4, &c->report));
}

static GbStatus null_voigt_params_default(struct world *c, int k)
{
    return granbond_voigt_params_default(ARG(k, 0, &c->voigt_params));
}

static GbStatus null_voigt_model_new(struct world *c, int k)
{
    return granbond_voigt_model_new(ARG(k, 0, &c->voigt_params), ARG(k, 1, &c->made_voigt));
}

static GbStatus null_voigt_parameter_info(struct world *c, int k)
{
    return granbond_voigt_parameter_info(0, ARG(k, 0, &c->info));
}

static GbStatus null_voigt_params_set(struct world *c, int k)
{
    return granbond_voigt_params_set(ARG(k, 0, &c->voigt_params), ARG(k, 1, "k_n"), 1.0e4);
}

static GbStatus null_voigt_parameter_needed(struct world *c, int k)
{
    return granbond_voigt_parameter_needed(ARG(k, 0, &c->voigt_params), 0, ARG(k, 1, &c->flag));
}

static GbStatus null_voigt_compute(struct world *c, int k)
{
    return granbond_voigt_compute(ARG(k, 0, c->voigt), ARG(k, 1, &c->pair[0]), DT, ARG(k, 2, c->contact_states),
                                  ARG(k, 3, &c->contact_out[0]));
}

static GbStatus null_voigt_critical_timestep(struct world *c, int k)
{
    return granbond_voigt_critical_timestep(ARG(k, 0, c->voigt), R_C, R_C, 1.0e-5, 1.0e-5, ARG(k, 1, &c->number));
}

/* The separation x_i - x_j of the first pair and its square. */
static double pair_separation(const struct world *c, double del[3])
{
    int d;
    for (d = 0; d < 3; d++)
        del[d] = c->pair[0].x_i[d] - c->pair[0].x_j[d];
    return dot3(del, del);
}

static GbStatus null_contact_frame_separation(struct world *c, int k)
{
    const GbPairKinematics *q = &c->pair[0];
    GbContactFrame frame;
    double del[3], rsq = pair_separation(c, del);
    return granbond_contact_frame_separation(ARG(k, 0, del), rsq, q->radius_i, q->radius_j, ARG(k, 1, q->v_i),
                                             ARG(k, 2, q->v_j), ARG(k, 3, q->w_i), ARG(k, 4, q->w_j),
                                             ARG(k, 5, &frame));
}

static GbStatus null_contact_frame_normal(struct world *c, int k)
{
    const GbPairKinematics *q = &c->pair[0];
    GbContactFrame frame;
    double del[3], distance = sqrt(pair_separation(c, del));
    return granbond_contact_frame_normal(ARG(k, 0, c->frame.n), distance, q->radius_i, q->radius_j, ARG(k, 1, q->v_i),
                                         ARG(k, 2, q->v_j), ARG(k, 3, q->w_i), ARG(k, 4, q->w_j), ARG(k, 5, &frame));
}

static GbStatus null_voigt_normal_force(struct world *c, int k)
{
    return granbond_voigt_normal_force(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), ARG(k, 2, &c->number));
}

static GbStatus null_voigt_tangential(struct world *c, int k)
{
    return granbond_voigt_tangential(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), 1.0e-3, DT,
                                     ARG(k, 2, c->contact_states), ARG(k, 3, &c->tangential));
}

static GbStatus null_voigt_rolling(struct world *c, int k)
{
    return granbond_voigt_rolling(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), 1.0e-3, DT,
                                  ARG(k, 2, c->contact_states + 3), ARG(k, 3, c->vector), ARG(k, 4, &c->flag));
}

static GbStatus null_voigt_evaluate_frame(struct world *c, int k)
{
    return granbond_voigt_evaluate_frame(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), ARG(k, 2, c->contact_states),
                                         ARG(k, 3, &c->contact_out[0]));
}

static GbStatus null_voigt_tangential_evaluate(struct world *c, int k)
{
    return granbond_voigt_tangential_evaluate(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), 1.0e-3,
                                              ARG(k, 2, c->contact_states), ARG(k, 3, &c->tangential));
}

static GbStatus null_voigt_rolling_evaluate(struct world *c, int k)
{
    return granbond_voigt_rolling_evaluate(ARG(k, 0, c->voigt), ARG(k, 1, &c->frame), 1.0e-3,
                                           ARG(k, 2, c->contact_states + 3), ARG(k, 3, c->vector),
                                           ARG(k, 4, &c->flag));
}

struct null_entry {
    const char *function;
    GbStatus (*call)(struct world *c, int k);
    /* The pointer arguments, in the order `call` numbers them. */
    const char *arguments[MAX_NULLS + 1];
};

static const char *const BREAKLOG_WORDS[] = {"log", "all", "bond/breaklog", "breaks.txt"};
static const char *const COLUMN_WORDS[] = {"id", "r0"};
static const int64_t LEDGER_COUNTS[4] = {1, 0, 0, 0};
static const int32_t PERIODIC[3] = {1, 1, 1};

static GbStatus null_store_counts_row(struct world *c, int k)
{
    GbStoreCounts counts;
    double row[GRANBOND_COUNTS_ROW_LEN];
    (void)c;
    memset(&counts, 0, sizeof counts);
    return granbond_store_counts_row(ARG(k, 0, &counts), ARG(k, 1, row));
}

static GbStatus null_ledger_notice(struct world *c, int k)
{
    return granbond_ledger_notice(GRANBOND_NOTICE_WALL_LOST_LIGGGHTS, ARG(k, 0, LEDGER_COUNTS), 1, ARG(k, 1, "w"),
                                  ARG(k, 2, &c->report));
}

static GbStatus null_break_event(struct world *c, int k)
{
    GbBreakEvent e;
    return granbond_break_event(ARG(k, 0, c->bond), ARG(k, 1, &c->bond_out[0]), ARG(k, 2, c->pair[0].x_i),
                                ARG(k, 3, c->pair[0].x_j), c->pair[0].radius_i, c->pair[0].radius_j, 1.0, 2.0, 3.0,
                                ARG(k, 4, &e));
}

static GbStatus null_break_log_text(struct world *c, int k)
{
    GbBreakEvent e;
    char text[2 * GRANBOND_BREAK_LOG_LINE_LEN];
    (void)c;
    memset(&e, 0, sizeof e);
    return granbond_break_log_text(ARG(k, 0, &e), 1, 1, ARG(k, 1, text), sizeof text);
}

static GbStatus null_break_log_words(struct world *c, int k)
{
    return granbond_break_log_words(ARG(k, 0, BREAKLOG_WORDS), 4, ARG(k, 1, &c->flag));
}

static GbStatus null_bond_columns_new(struct world *c, int k)
{
    GbBondColumns *cols = NULL;
    GbStatus s = granbond_bond_columns_new(ARG(k, 0, COLUMN_WORDS), 2, 0, ARG(k, 1, &cols));
    (void)c;
    granbond_bond_columns_free(cols);
    return s;
}

static GbStatus null_bond_columns_info(struct world *c, int k)
{
    GbBondColumns *cols = NULL;
    GbStatus s = granbond_bond_columns_new(COLUMN_WORDS, 2, 0, &cols);
    if (s == GB_STATUS_OK)
        s = granbond_bond_columns_info(ARG(k, 0, cols), ARG(k, 1, &c->index), ARG(k, 2, &c->flag));
    granbond_bond_columns_free(cols);
    return s;
}

static GbStatus null_bond_columns_row(struct world *c, int k)
{
    GbBondColumns *cols = NULL;
    double record[GRANBOND_BOND_STATE_LEN + GRANBOND_BOND_OUTPUT_LEN] = {0}, energy[16] = {0}, row[3];
    GbStatus s = granbond_bond_columns_new(COLUMN_WORDS, 2, 0, &cols);
    memcpy(record, c->bond_states, GRANBOND_BOND_STATE_LEN * sizeof(double));
    if (s == GB_STATUS_OK)
        s = granbond_bond_columns_row(ARG(k, 0, cols), ARG(k, 1, c->bond), ARG(k, 2, record), ARG(k, 3, energy), 1.0,
                                      2.0, ARG(k, 4, c->pair[0].x_i), ARG(k, 5, c->pair[0].x_j), ARG(k, 6, row));
    granbond_bond_columns_free(cols);
    return s;
}

static GbStatus null_thin_periodic_box_check(struct world *c, int k)
{
    return granbond_thin_periodic_box_check(ARG(k, 0, "s"), 3, ARG(k, 1, PERIODIC), ARG(k, 2, c->vector), 1.0, 0.1, -1,
                                            ARG(k, 3, &c->report));
}

static GbStatus null_store_check_findings(struct world *c, int k)
{
    double keys[2] = {1.0, 2.0};
    return granbond_store_check_findings(ARG(k, 0, keys), 1, ARG(k, 1, LEDGER_COUNTS), 0, ARG(k, 2, &c->report));
}

/* One atom of id 0, and room for a key: the store checks' arguments. */
static const int64_t ONE_ID[1] = {0};
static const GbAtomIds ONE_ATOM = {NULL, ONE_ID, 1};

static GbStatus null_bond_store_check_keys(struct world *c, int k)
{
    GbBondStore *store = NULL;
    double keys[2];
    GbStatus s = granbond_bond_store_new(&store);
    if (s == GB_STATUS_OK)
        s = granbond_bond_store_check_keys(ARG(k, 0, store), ARG(k, 1, &ONE_ATOM), 1, ARG(k, 2, keys), 2,
                                           ARG(k, 3, &c->index), ARG(k, 4, &c->report));
    granbond_bond_store_free(store);
    return s;
}

static GbStatus null_bond_store_check_flag(struct world *c, int k)
{
    GbBondStore *store = NULL;
    GbStatus s = granbond_bond_store_new(&store);
    if (s == GB_STATUS_OK)
        s = granbond_bond_store_check_flag(ARG(k, 0, store), 0, 0, ARG(k, 1, &ONE_ATOM), 0, ARG(k, 2, &c->report));
    granbond_bond_store_free(store);
    return s;
}

static GbStatus null_wall_store_check_keys(struct world *c, int k)
{
    GbWallStore *store = NULL;
    double keys[2];
    GbStatus s = granbond_wall_store_new(&store);
    if (s == GB_STATUS_OK)
        s = granbond_wall_store_check_keys(ARG(k, 0, store), ARG(k, 1, &ONE_ATOM), ARG(k, 2, keys), 2,
                                           ARG(k, 3, &c->index), ARG(k, 4, &c->report));
    granbond_wall_store_free(store);
    return s;
}

/* A record of no bonds (zero counts and sums; never written). */
static GbStoreCounts NO_COUNTS;
static GbEnergySums NO_ENERGY;

static GbStatus null_store_record_write(struct world *c, int k)
{
    uint8_t record[GRANBOND_STORE_RECORD_LEN];
    (void)c;
    return granbond_store_record_write(ARG(k, 0, &NO_COUNTS), ARG(k, 1, &NO_ENERGY), ARG(k, 2, record), sizeof record);
}

static GbStatus null_store_record_read(struct world *c, int k)
{
    GbStoreCounts counts;
    GbEnergySums energy;
    uint8_t record[GRANBOND_STORE_RECORD_LEN];
    (void)c;
    if (granbond_store_record_write(&NO_COUNTS, &NO_ENERGY, record, sizeof record) != GB_STATUS_OK)
        return GB_STATUS_INVALID_ARGUMENT;
    return granbond_store_record_read(ARG(k, 0, record), ARG(k, 1, &counts), ARG(k, 2, &energy));
}

static const struct null_entry NULL_ENTRIES[] = {
    {"granbond_check_layout", null_check_layout, {"expected"}},
    {"granbond_state_slot", null_state_slot, {"name", "flips_on_swap"}},
    {"granbond_bond_params_default", null_bond_params_default, {"params"}},
    {"granbond_bond_params_default_in_units", null_bond_params_default_in_units, {"units", "params"}},
    {"granbond_bond_params_contact_under_bond_by_law", null_bond_params_contact_under_bond_by_law, {"params"}},
    {"granbond_pair_coeff_read", null_pair_coeff_read, {"command", "words", "units", "voigt", "bond", "has_bond"}},
    {"granbond_bond_coeff_read", null_bond_coeff_read, {"command", "words", "bond"}},
    {"granbond_liggghts_property_line_check", null_liggghts_property_line_check, {"words", "infinite", "ours"}},
    {"granbond_liggghts_settings_check", null_liggghts_settings_check, {"command", "words"}},
    {"granbond_bond_params_rows", null_bond_params_rows, {"params", "buf", "len"}},
    {"granbond_bond_params_from_rows", null_bond_params_from_rows, {"rows", "what", "params"}},
    {"granbond_voigt_params_rows", null_voigt_params_rows, {"params", "buf", "len"}},
    {"granbond_voigt_params_from_rows", null_voigt_params_from_rows, {"rows", "what", "params"}},
    {"granbond_bond_model_new", null_bond_model_new, {"params", "model"}},
    {"granbond_bond_parameter_info", null_bond_parameter_info, {"info"}},
    {"granbond_bond_params_set", null_bond_params_set, {"params", "name"}},
    {"granbond_bond_parameter_needed", null_bond_parameter_needed, {"params", "needed"}},
    {"granbond_bond_parameter_liggghts_name", null_bond_parameter_liggghts_name, {"name"}},
    {"granbond_bond_try_create", null_bond_try_create, {"model", "kinematics", "state", "created"}},
    {"granbond_bond_create_now", null_bond_create_now, {"model", "kinematics", "state", "created"}},
    {"granbond_bond_compute", null_bond_compute, {"model", "kinematics", "state", "out"}},
    {"granbond_bond_compute_indexed",
     null_bond_compute_indexed,
     {"model", "atoms", "pairs", "states", "out", "atoms->x", "atoms->v", "atoms->omega", "atoms->radius"}},
    {"granbond_wall_bond_try_create",
     null_wall_bond_try_create,
     {"model", "sphere", "contact_point", "state", "created"}},
    {"granbond_wall_bond_compute", null_wall_bond_compute, {"model", "sphere", "wall_velocity", "state", "out"}},
    {"granbond_bond_contact_loads_under_bond", null_bond_contact_loads_under_bond, {"model", "del", "out"}},
    {"granbond_bond_output_store", null_bond_output_store, {"out", "slots"}},
    {"granbond_bond_output_load", null_bond_output_load, {"slots", "out"}},
    {"granbond_store_counts_row", null_store_counts_row, {"counts", "row"}},
    {"granbond_ledger_notice", null_ledger_notice, {"counts", "name", "out"}},
    {"granbond_break_event", null_break_event, {"model", "out", "x_i", "x_j", "event"}},
    {"granbond_break_log_text", null_break_log_text, {"events", "text"}},
    {"granbond_break_log_words", null_break_log_words, {"words", "every"}},
    {"granbond_bond_columns_new", null_bond_columns_new, {"words", "columns"}},
    {"granbond_bond_columns_info", null_bond_columns_info, {"columns", "count", "wants_energy"}},
    {"granbond_bond_columns_row", null_bond_columns_row, {"columns", "model", "record", "energy", "x_i", "x_j", "row"}},
    {"granbond_thin_periodic_box_check", null_thin_periodic_box_check, {"style", "periodic", "length", "out"}},
    {"granbond_store_check_findings", null_store_check_findings, {"keys", "sums", "out"}},
    {"granbond_bond_store_check_keys", null_bond_store_check_keys, {"store", "ids", "keys", "written", "out"}},
    {"granbond_bond_store_check_flag", null_bond_store_check_flag, {"store", "ids", "out"}},
    {"granbond_wall_store_check_keys", null_wall_store_check_keys, {"store", "ids", "keys", "written", "out"}},
    {"granbond_store_record_write", null_store_record_write, {"counts", "energy", "record"}},
    {"granbond_store_record_read", null_store_record_read, {"record", "counts", "energy"}},
    {"granbond_bond_centre", null_bond_centre, {"x_i", "x_j", "centre"}},
    {"granbond_bond_max_distance", null_bond_max_distance, {"model", "out"}},
    {"granbond_bond_contact_distance_factor", null_bond_contact_distance_factor, {"model", "out"}},
    {"granbond_bond_critical_timestep", null_bond_critical_timestep, {"model", "out"}},
    {"granbond_bond_recommended_timestep", null_bond_recommended_timestep, {"model", "out"}},
    {"granbond_bond_timestep_check", null_bond_timestep_check, {"models", "bodies", "units", "style", "out"}},
    {"granbond_voigt_timestep_check", null_voigt_timestep_check, {"models", "bodies", "units", "style", "out"}},
    {"granbond_bond_creation_check", null_bond_creation_check, {"models", "bodies", "units", "style", "out"}},
    {"granbond_voigt_params_default", null_voigt_params_default, {"params"}},
    {"granbond_voigt_model_new", null_voigt_model_new, {"params", "model"}},
    {"granbond_voigt_parameter_info", null_voigt_parameter_info, {"info"}},
    {"granbond_voigt_params_set", null_voigt_params_set, {"params", "name"}},
    {"granbond_voigt_parameter_needed", null_voigt_parameter_needed, {"params", "needed"}},
    {"granbond_voigt_compute", null_voigt_compute, {"model", "kinematics", "state", "out"}},
    {"granbond_voigt_critical_timestep", null_voigt_critical_timestep, {"model", "out"}},
    {"granbond_contact_frame_separation",
     null_contact_frame_separation,
     {"del", "v_i", "v_j", "w_i", "w_j", "frame"}},
    {"granbond_contact_frame_normal", null_contact_frame_normal, {"n", "v_i", "v_j", "w_i", "w_j", "frame"}},
    {"granbond_voigt_normal_force", null_voigt_normal_force, {"model", "frame", "normal_force"}},
    {"granbond_voigt_tangential", null_voigt_tangential, {"model", "frame", "spring", "out"}},
    {"granbond_voigt_rolling", null_voigt_rolling, {"model", "frame", "angle", "torque_i", "slip"}},
    {"granbond_voigt_evaluate_frame", null_voigt_evaluate_frame, {"model", "frame", "state", "out"}},
    {"granbond_voigt_tangential_evaluate", null_voigt_tangential_evaluate, {"model", "frame", "spring", "out"}},
    {"granbond_voigt_rolling_evaluate",
     null_voigt_rolling_evaluate,
     {"model", "frame", "angle", "torque_i", "slip"}},
};

static int world_new(struct world *c)
{
    int b, d;
    memset(c, 0, sizeof *c);
    c->bond_params = bond_fixture();
    c->voigt_params = voigt_fixture();
    c->layout = caller_layout();
    if (new_bond_model(&c->bond_params, &c->bond) || new_voigt_model(&c->voigt_params, &c->voigt))
        return 1;
    /* bond b joins atoms 2b (i) and 2b + 1 (j), created at rest length */
    for (b = 0; b < N_ITEMS; b++) {
        contact_at(&c->pair[b], 1.0e-6 * (b + 1), 0.01);
        c->bond_state_pointers[b] = c->bond_states + b * GRANBOND_BOND_STATE_LEN;
        if (create_bond(c->bond, c->bond_state_pointers[b]))
            return 1;
        for (d = 0; d < 3; d++) {
            c->x[6 * b + d] = c->pair[b].x_i[d];
            c->x[6 * b + 3 + d] = c->pair[b].x_j[d];
        }
        c->radius[2 * b] = c->pair[b].radius_i;
        c->radius[2 * b + 1] = c->pair[b].radius_j;
        c->pairs[2 * b] = 2 * b;
        c->pairs[2 * b + 1] = 2 * b + 1;
    }
    c->atoms.x = c->x;
    c->atoms.v = c->v;
    c->atoms.omega = c->w;
    c->atoms.radius = c->radius;
    c->atoms.count = 2 * N_ITEMS;
    c->sphere.radius = R_C;
    c->sphere.x[2] = R_C - 1.0e-5;
    {
        double del[3], rsq = pair_separation(c, del);
        const GbPairKinematics *q = &c->pair[0];
        EXPECT_OK(granbond_contact_frame_separation(del, rsq, q->radius_i, q->radius_j, q->v_i, q->v_j, q->w_i, q->w_j,
                                                    &c->frame),
                  "granbond_contact_frame_separation");
    }
    c->bodies[1].radius_min = c->bodies[1].radius_max = R_C;
    c->bodies[1].mass_min = 1.0e-5;
    c->bond_table[3] = c->bond;
    c->voigt_table[3] = c->voigt;
    return 0;
}

int test_null_arguments(void)
{
    struct world c, before;
    size_t e;
    int k;

    if (world_new(&c))
        return 1;
    for (e = 0; e < sizeof NULL_ENTRIES / sizeof NULL_ENTRIES[0]; e++) {
        const struct null_entry *entry = &NULL_ENTRIES[e];
        for (k = 0; k < MAX_NULLS && entry->arguments[k] != NULL; k++) {
            memcpy(&before, &c, sizeof c);
            if (!null_arg_(entry->call(&c, k), entry->function, entry->arguments[k], __FILE__, __LINE__))
                return 1;
            CHECK(memcmp(before.bond_states, c.bond_states, sizeof c.bond_states) == 0 &&
                      memcmp(before.wall_state, c.wall_state, sizeof c.wall_state) == 0 &&
                      memcmp(before.contact_states, c.contact_states, sizeof c.contact_states) == 0,
                  say("%s with %s = NULL leaves every state alone", entry->function, entry->arguments[k]));
        }
    }
    /* A failed model_new leaves no pointer behind. */
    c.made_bond = (GbBondModel *)(void *)sentinel_object;
    granbond_bond_model_new(NULL, &c.made_bond);
    CHECK(c.made_bond == NULL, "granbond_bond_model_new(NULL params) sets *model = NULL");
    c.made_voigt = (GbVoigtModel *)(void *)sentinel_object;
    granbond_voigt_model_new(NULL, &c.made_voigt);
    CHECK(c.made_voigt == NULL, "granbond_voigt_model_new(NULL params) sets *model = NULL");
    granbond_bond_model_free(c.bond);
    granbond_voigt_model_free(c.voigt);
    return 0;
}
