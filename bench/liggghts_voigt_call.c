/* Cost of one Voigt contact through the core's unchecked entry the LIGGGHTS
 * adapter calls (granbond_voigt_compute_normal_unchecked), called the two
 * ways an engine adapter can call it: the normal written component by
 * component just before the call, or passed from the engine's own arrays;
 * the output read
 * back one double at a time. 4096 touching contacts with their own history
 * (one copy per way), best of 300 passes, the two ways alternating: a pass
 * is short enough to be rarely interrupted on a shared machine. Built and
 * run by
 * bench/liggghts_voigt.sh --call. */
#include "granbond.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#define CONTACTS 4096
#define PASSES 300

static double en[CONTACTS][3], vi[CONTACTS][3], vj[CONTACTS][3], wi[CONTACTS][3], wj[CONTACTS][3];
static double distance[CONTACTS], history[2][CONTACTS][GRANBOND_CONTACT_STATE_LEN];

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double pass(const GbVoigtModel *m, int fields)
{
    double sum = 0.0;
    for (int k = 0; k < CONTACTS; k++) {
        GbContactOutput out;
        GbStatus s;
        if (fields) {
            s = granbond_voigt_compute_normal_unchecked(m, en[k], distance[k], 1e-3, 1e-3, vi[k], vj[k], wi[k], wj[k],
                                                        1e-6, history[1][k], &out);
        } else {
            double n[3];
            n[0] = en[k][0], n[1] = en[k][1], n[2] = en[k][2];
            s = granbond_voigt_compute_normal_unchecked(m, n, distance[k], 1e-3, 1e-3, vi[k], vj[k], wi[k], wj[k], 1e-6,
                                                        history[0][k], &out);
        }
        const volatile double *const force = out.force_i;
        sum += (s == GB_STATUS_OK) ? force[0] + force[1] + force[2] : NAN;
    }
    return sum;
}

int main(void)
{
    GbVoigtParams p;
    GbVoigtModel *m = NULL;
    granbond_voigt_params_default(&p);
    if (granbond_voigt_model_new(&p, &m) != GB_STATUS_OK) {
        fprintf(stderr, "%s\n", granbond_last_error_message());
        return 1;
    }
    memset(history, 0, sizeof history);
    for (int k = 0; k < CONTACTS; k++) {
        const double a = 1e-3 * k;
        en[k][0] = cos(a), en[k][1] = sin(a), en[k][2] = 0.0;
        for (int c = 0; c < 3; c++) {
            vi[k][c] = 1e-3 * sin(k + c), vj[k][c] = -vi[k][c];
            wi[k][c] = 0.3 * cos(k * c), wj[k][c] = 0.1 * c;
        }
        distance[k] = 2e-3 - 1e-6 * (1.0 + 0.5 * sin(3.0 * k));
    }
    const char *names[2] = {"normal written just before, granbond_voigt_compute_normal_unchecked",
                            "normal from the engine's arrays, granbond_voigt_compute_normal_unchecked"};
    double best[2] = {1e9, 1e9}, check = 0.0;
    for (int r = 0; r < PASSES; r++)
        for (int fields = 0; fields < 2; fields++) {
            const double t0 = seconds();
            check += pass(m, fields);
            const double t = seconds() - t0;
            best[fields] = t < best[fields] ? t : best[fields];
        }
    if (!isfinite(check)) {
        fprintf(stderr, "a call failed\n");
        return 1;
    }
    for (int fields = 0; fields < 2; fields++)
        printf("%-75s %5.1f ns per contact\n", names[fields], best[fields] / CONTACTS * 1e9);
    granbond_voigt_model_free(m);
    return 0;
}
