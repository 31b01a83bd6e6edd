/* Runs a deck through the C API and writes its result file:
 *   test_api_run DECK T_END STEP OUT
 * STEP <= 0: one landyn_advance_to(T_END); otherwise calls at STEP, 2 STEP, ... and T_END.
 * check_api_runs.py compares the file with the landyn program's on the same deck. */
#include "landyn.h"
#include "api_test_util.h"

int main(int argc, char **argv) {
  if (argc != 5) {
    fprintf(stderr, "usage: test_api_run DECK T_END STEP OUT\n");
    return 2;
  }
  char *deck = read_text(argv[1]);
  double t_end = atof(argv[2]), step = atof(argv[3]);
  char msg[1024];
  landyn_sim *sim = NULL;
  if (!deck) {
    fprintf(stderr, "cannot read %s\n", argv[1]);
    return 2;
  }
  int rc = landyn_create(deck, NULL, &sim, msg, sizeof msg);
  if (rc != LANDYN_OK) {
    fprintf(stderr, "landyn_create: %d %s\n", rc, msg);
    return 1;
  }
  if (step > 0) {
    for (long k = 1; k * step < t_end - 1e-12; k++) {
      rc = landyn_advance_to(sim, k * step, msg, sizeof msg);
      if (rc != LANDYN_OK) break;
    }
  }
  if (rc == LANDYN_OK) rc = landyn_advance_to(sim, t_end, msg, sizeof msg);
  if (rc != LANDYN_OK && rc != LANDYN_ENDED) {
    fprintf(stderr, "landyn_advance_to: %d %s\n", rc, msg);
    return 1;
  }
  rc = landyn_write_result(sim, argv[4], msg, sizeof msg);
  if (rc != LANDYN_OK) {
    fprintf(stderr, "landyn_write_result: %d %s\n", rc, msg);
    return 1;
  }
  landyn_free(&sim);
  free(deck);
  return 0;
}
