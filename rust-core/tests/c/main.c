/*
 * Runs the topics in order and reports the count of checks.
 */

#include "harness.h"

int main(void)
{
    int failed = test_version_and_layout() || test_state_layout() || test_parameter_tables() || test_bond_params() ||
                 test_bond_create_and_force() || test_bond_errors() ||
                 test_bond_indexed_results() || test_bond_indexed() || test_bond_store() || test_bond_store_listed() || test_bond_break() || test_wall_bond() || test_wall_store() ||
                 test_bond_limits() || test_bond_output_slots() || test_bond_centre() || test_bond_fields() || test_run_checks() || test_ledger() || test_voigt_params() || test_deck_phrases() || test_coeff_lines() || test_restart_rows() || test_liggghts_lines() || test_voigt_contact() ||
                 test_voigt_wall() || test_voigt_timestep() || test_contact_frames() ||
                 test_voigt_parts() || test_error_state_and_free() || test_null_arguments();
    if (failed) {
        printf("abi_harness: FAILED after %d checks\n", n_checks);
        return 1;
    }
    printf("abi_harness: all %d checks passed\n", n_checks);
    return 0;
}
