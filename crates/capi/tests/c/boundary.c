/* Errors and panics across the C boundary (crates/capi/tests/c_example.rs runs it with a
   malformed scenario as argv[1]): every failure is a status code and a message, and the
   program lives on. Prints one line per check; exits 0 when all hold. */
#include <stdio.h>
#include <string.h>

#include "oscsim.h"

static int failures = 0;

static void check(int ok, const char *what) {
    printf("%s %s\n", ok ? "ok" : "FAILED", what);
    if (!ok) failures++;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: %s MALFORMED.xosc GOOD.xosc\n", argv[0]);
        return 2;
    }
    OscsimSimulation *sim = (OscsimSimulation *)1;
    OscsimStatus status = oscsim_simulation_new(argv[1], NULL, 0, NULL, &sim);
    check(status == OSCSIM_STATUS_LOAD && sim == NULL, "malformed scenario: OSCSIM_STATUS_LOAD, null handle");
    printf("message %s\n", oscsim_last_error_message());

    status = oscsim_test_panic();
    check(status == OSCSIM_STATUS_PANIC, "panic: OSCSIM_STATUS_PANIC");
    check(strstr(oscsim_last_error_message(), "oscsim_test_panic") != NULL, "panic: message");

    status = oscsim_simulation_step(NULL, NULL);
    check(status == OSCSIM_STATUS_ARGUMENT, "null handle: OSCSIM_STATUS_ARGUMENT");

    status = oscsim_simulation_new(argv[2], NULL, 0, NULL, &sim);
    check(status == OSCSIM_STATUS_OK && sim != NULL, "good scenario loads after a panic");
    OscsimStopReason reason;
    check(oscsim_simulation_step(sim, &reason) == OSCSIM_STATUS_OK, "step");
    check(oscsim_simulation_test_panic(sim) == OSCSIM_STATUS_PANIC, "panic inside a simulation");
    check(oscsim_simulation_step(sim, &reason) == OSCSIM_STATUS_PANIC, "the panicked simulation refuses steps");
    oscsim_simulation_free(sim);

    OscsimSimulation *other = NULL;
    check(oscsim_simulation_new(argv[2], NULL, 0, NULL, &other) == OSCSIM_STATUS_OK, "another simulation loads");
    check(oscsim_simulation_run(other, &reason) == OSCSIM_STATUS_OK && reason == OSCSIM_STOP_REASON_STOP_TRIGGER,
          "and runs to its stop trigger");
    size_t index = 0;
    check(oscsim_simulation_find_entity(other, "Nobody", &index) == OSCSIM_STATUS_NOT_FOUND, "unknown name: NOT_FOUND");
    check(oscsim_simulation_entity_state(other, 99, NULL) == OSCSIM_STATUS_ARGUMENT, "bad index: ARGUMENT");
    oscsim_simulation_free(other);
    printf("alive\n");
    return failures == 0 ? 0 : 1;
}
