/*
 * Runs a case through soilcut's C API and prints its history as CSV:
 *
 *     run CASE.toml [KEY=VALUE ...]
 *
 * The KEY=VALUE arguments override keys of the case as `soilcut run --set`
 * does. The first line is history.csv's header, then one row per increment
 * with every number printed with %.17g, which reads back to the same
 * double: the rows are `soilcut run`'s history.csv, bit for bit
 * (crates/ffi/tests/examples.rs checks it). The final surface's highest
 * point goes to stderr. Exit status 2 on bad input, 1 on any other error.
 *
 * Build (see README.md, "C and C++"):
 *     cargo build --release -p soilcut-ffi
 *     cc -I crates/ffi/include crates/ffi/examples/c/run.c \
 *        target/release/libsoilcut_ffi.a -lpthread -ldl -lm -o run
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#include "soilcut.h"

/* Prints the last error of `sim` (NULL: of this thread), after `what`
 * unless it is NULL (a constructor's message names the file itself), and
 * returns the exit status for `code`. */
static int report(const SoilcutSimulation *sim, const char *what, int code)
{
    size_t needed = soilcut_last_error(sim, NULL, 0);
    char *message = malloc(needed);
    if (message != NULL) {
        soilcut_last_error(sim, message, needed);
        if (what != NULL) {
            fprintf(stderr, "error: %s: %s\n", what, message);
        } else {
            fprintf(stderr, "error: %s\n", message);
        }
        free(message);
    }
    return code == SOILCUT_ERR_INPUT || code == SOILCUT_ERR_STEP ? 2 : 1;
}

static void print_row(const SoilcutStep *r)
{
    printf("%" PRIu64
           ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
           r->step, r->u, r->u_over_d, r->force, r->force_norm, r->force_h, r->force_v, r->beta_deg,
           r->x_emergence, r->mass, r->y_emergence, r->friction_deg, r->slip, r->dilation_deg,
           r->dilation_area, r->depth, r->mass_spilled, r->weight, r->force_factor,
           r->face_friction_deg, r->moment, r->tool_x, r->tool_y, r->tool_rotation);
}

/* The final surface's highest point, on stderr. */
static int print_crest(const SoilcutSimulation *sim)
{
    size_t n = 0;
    int code = soilcut_surface_len(sim, &n);
    if (code != SOILCUT_OK) {
        return code;
    }
    double *x = malloc(n * sizeof *x);
    double *y = malloc(n * sizeof *y);
    if (x == NULL || y == NULL) {
        free(x);
        free(y);
        return SOILCUT_ERR_NULL;
    }
    code = soilcut_surface(sim, x, y, NULL, NULL, NULL, n);
    if (code == SOILCUT_OK) {
        size_t top = 0;
        for (size_t i = 1; i < n; i++) {
            if (y[i] > y[top]) {
                top = i;
            }
        }
        fprintf(stderr, "final surface: %zu points, highest y = %g at x = %g\n", n, y[top], x[top]);
    }
    free(x);
    free(y);
    return code;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s CASE.toml [KEY=VALUE ...]\n", argv[0]);
        return 2;
    }
    SoilcutSimulation *sim = NULL;
    int code = soilcut_new_from_file(argv[1], (const char *const *)(argv + 2), (size_t)(argc - 2), &sim);
    if (code != SOILCUT_OK) {
        /* No handle yet: the thread keeps the message, which starts with
         * the file's path. */
        return report(NULL, NULL, code);
    }
    printf("%s\n", soilcut_history_header());
    SoilcutState state;
    SoilcutStep record;
    while ((code = soilcut_state(sim, &state)) == SOILCUT_OK && !state.done) {
        code = soilcut_step(sim, &record);
        if (code != SOILCUT_OK) {
            break;
        }
        print_row(&record);
    }
    if (code == SOILCUT_OK) {
        code = print_crest(sim);
    }
    int status = code == SOILCUT_OK ? 0 : report(sim, argv[1], code);
    soilcut_free(sim);
    return status;
}
