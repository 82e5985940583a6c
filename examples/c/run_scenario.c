/* Runs an OpenSCENARIO scenario through the oscsim C API and prints where every entity
   ends: one line per entity, "name,x,y,z,h" with 6 decimals (the trajectory CSV's), after a
   line "time,T" with the final simulation time.

   Build (from the repository root, after cargo build -p oscsim-capi):
     cc -std=c99 -Icrates/capi/include examples/c/run_scenario.c \
        -Ltarget/debug -loscsim -Wl,-rpath,$PWD/target/debug -o run_scenario
     ./run_scenario examples/scenarios/cut_in_highway.xosc [NAME=VALUE ...]
   Exit status: 0 after a run; 1 when the scenario does not load or a step fails (the
   message, with file:line:col where there is one, on stderr); 2 on bad usage. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "oscsim.h"

static int fail(const char *what, OscsimStatus status) {
    fprintf(stderr, "%s failed (status %d): %s\n", what, (int)status, oscsim_last_error_message());
    return 1;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s SCENARIO.xosc [NAME=VALUE ...]\n", argv[0]);
        return 2;
    }
    /* Parameter overrides NAME=VALUE, as oscsim run --param. */
    int n_params = argc - 2;
    OscsimParameter *params = calloc(n_params > 0 ? (size_t)n_params : 1, sizeof *params);
    if (params == NULL) return 1;
    for (int i = 0; i < n_params; i++) {
        char *eq = strchr(argv[i + 2], '=');
        if (eq == NULL) {
            fprintf(stderr, "expected NAME=VALUE, found %s\n", argv[i + 2]);
            free(params);
            return 2;
        }
        *eq = '\0';
        params[i].name = argv[i + 2];
        params[i].value = eq + 1;
    }

    OscsimConfig config = oscsim_config_default();
    OscsimSimulation *sim = NULL;
    OscsimStatus status = oscsim_simulation_new(argv[1], params, (size_t)n_params, &config, &sim);
    free(params);
    if (status != OSCSIM_STATUS_OK) return fail("loading", status);

    /* Step by step until the storyboard ends (oscsim_simulation_run does the same loop). */
    OscsimStopReason reason = OSCSIM_STOP_REASON_RUNNING;
    while (reason == OSCSIM_STOP_REASON_RUNNING) {
        status = oscsim_simulation_step(sim, &reason);
        if (status != OSCSIM_STATUS_OK) {
            oscsim_simulation_free(sim);
            return fail("a step", status);
        }
    }

    double time = 0.0;
    size_t count = 0;
    if ((status = oscsim_simulation_time(sim, &time)) != OSCSIM_STATUS_OK ||
        (status = oscsim_simulation_entity_count(sim, &count)) != OSCSIM_STATUS_OK) {
        oscsim_simulation_free(sim);
        return fail("reading the simulation", status);
    }
    printf("time,%.3f\n", time);
    for (size_t i = 0; i < count; i++) {
        OscsimEntityState state;
        const char *name = NULL;
        if ((status = oscsim_simulation_entity_state(sim, i, &state)) != OSCSIM_STATUS_OK ||
            (status = oscsim_simulation_entity_name(sim, i, &name)) != OSCSIM_STATUS_OK) {
            oscsim_simulation_free(sim);
            return fail("reading an entity", status);
        }
        printf("%s,%.6f,%.6f,%.6f,%.6f\n", name, state.x, state.y, state.z, state.h);
    }
    oscsim_simulation_free(sim);
    return 0;
}
