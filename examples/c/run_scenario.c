/* Runs an OpenSCENARIO scenario (XML .xosc or DSL .osc) through the oscsim C API and prints
   where every entity ends: one line per entity, "name,x,y,z,h" with 6 decimals (the trajectory
   CSV's), after a line "time,T" with the final simulation time.

   Build (from the repository root, after cargo build -p oscsim-capi):
     cc -std=c99 -Icrates/capi/include examples/c/run_scenario.c \
        -Ltarget/debug -loscsim -Wl,-rpath,$PWD/target/debug -o run_scenario
     ./run_scenario examples/scenarios/cut_in_highway.xosc [NAME=VALUE ...]
     ./run_scenario examples/scenarios/cut_in_highway.osc --road examples/roads/highway.xodr [--seed N]
   (--seed is also the seed of the engine's random streams, as with oscsim run.)
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
        fprintf(stderr, "usage: %s SCENARIO [--road ROAD.xodr] [--seed N] [NAME=VALUE ...]\n", argv[0]);
        return 2;
    }
    /* The options of oscsim run: --road and --seed (a DSL scenario), NAME=VALUE (--param, an
       XML scenario). */
    OscsimLoadOptions options = oscsim_load_options_default();
    OscsimConfig config = oscsim_config_default();
    OscsimParameter *params = calloc((size_t)argc, sizeof *params);
    if (params == NULL) return 1;
    size_t n_params = 0;
    for (int i = 2; i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (strcmp(argv[i], "--road") == 0 && i + 1 < argc) {
            options.road = argv[++i];
        } else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
            options.seed = config.seed = strtoull(argv[++i], NULL, 10);
        } else if (eq != NULL) {
            *eq = '\0';
            params[n_params].name = argv[i];
            params[n_params].value = eq + 1;
            n_params++;
        } else {
            fprintf(stderr, "expected --road FILE, --seed N or NAME=VALUE, found %s\n", argv[i]);
            free(params);
            return 2;
        }
    }
    options.params = params;
    options.n_params = n_params;

    OscsimScenario *scenario = NULL;
    OscsimStatus status = oscsim_scenario_load(argv[1], &options, &scenario);
    free(params);
    if (status != OSCSIM_STATUS_OK) return fail("loading", status);
    OscsimSimulation *sim = NULL;
    status = oscsim_simulation_from_scenario(scenario, &config, &sim);
    /* The simulation keeps what it needs of the scenario. */
    oscsim_scenario_free(scenario);
    if (status != OSCSIM_STATUS_OK) return fail("building the simulation", status);

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
