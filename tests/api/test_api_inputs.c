/* Engine inputs of the C API:
 *   test_api_inputs DECK WORKDIR
 * 1. DECK with &engine thrust T along -z (cutoff after t_end) against DECK without engine and
 *    landyn_set_input(force = T (0, 0, -1)) at t = 0, both advanced in steps of 10 ms: every
 *    output identical at every stop (adaptive and fixed).
 * 2. A pitching moment that changes every millisecond (WORKDIR/moment.h5; check_energy.py checks
 *    its energy audit) and a zero input, which leaves the run as it was. */
#include <math.h>

#include "landyn.h"
#include "api_test_util.h"

#define THRUST 15000.0

static double *run(const char *deck, const char *overrides, const double *force, int *n_out, int n_stops,
                   double dt_stop) {
  char msg[1024];
  landyn_sim *sim = NULL;
  if (landyn_create(deck, overrides, &sim, msg, sizeof msg) != LANDYN_OK) {
    fprintf(stderr, "create: %s\n", msg);
    return NULL;
  }
  int n;
  landyn_output_count(sim, &n);
  double *v = calloc((size_t)n * (size_t)n_stops, sizeof(double));
  if (force && landyn_set_input(sim, force, NULL, msg, sizeof msg) != LANDYN_OK) fprintf(stderr, "input: %s\n", msg);
  for (int k = 0; k < n_stops; k++) {
    int rc = landyn_advance_to(sim, dt_stop * (k + 1), msg, sizeof msg);
    if (rc != LANDYN_OK) {
      fprintf(stderr, "advance: %d %s\n", rc, msg);
      free(v);
      landyn_free(&sim);
      return NULL;
    }
    landyn_get_outputs(sim, v + (size_t)k * n, n, msg, sizeof msg);
  }
  *n_out = n;
  landyn_free(&sim);
  return v;
}

static void thrust_vs_input(const char *deck, const char *integrator) {
  char with_engine[256], without[256], label[200];
  snprintf(with_engine, sizeof with_engine, "&simulation\n integrator = '%s'\n dt = 1.0e-5\n t_end = 0.3\n/\n"
           "&engine\n thrust = %.1f\n direction = 0.0, 0.0, -1.0\n cutoff_time = 1.0\n/\n", integrator, THRUST);
  snprintf(without, sizeof without, "&simulation\n integrator = '%s'\n dt = 1.0e-5\n t_end = 0.3\n/\n", integrator);
  double force[3] = {0.0, 0.0, -THRUST};
  int na = 0, nb = 0, nc = 0;
  double *a = run(deck, with_engine, NULL, &na, 30, 0.01);
  double *b = run(deck, without, force, &nb, 30, 0.01);
  double *c = run(deck, without, NULL, &nc, 30, 0.01);
  snprintf(label, sizeof label, "%s: &engine thrust and the same input force: every output identical", integrator);
  CHECK(a && b && na == nb && memcmp(a, b, sizeof(double) * (size_t)na * 30) == 0, label);
  snprintf(label, sizeof label, "%s: the thrust changes the run (the test can fail)", integrator);
  CHECK(a && c && na == nc && memcmp(a, c, sizeof(double) * (size_t)na * 30) != 0, label);
  free(a);
  free(b);
  free(c);
}

static void moment_input(const char *deck, const char *workdir) {
  char msg[1024], path[1024];
  landyn_sim *sim = NULL, *zero = NULL, *plain = NULL;
  const char *ov = "&simulation\n t_end = 0.3\n/\n";
  if (landyn_create(deck, ov, &sim, msg, sizeof msg) != LANDYN_OK || landyn_create(deck, ov, &zero, msg, sizeof msg) ||
      landyn_create(deck, ov, &plain, msg, sizeof msg)) {
    CHECK(0, "create");
    return;
  }
  int n;
  landyn_output_count(sim, &n);
  double *vz = calloc((size_t)n, sizeof(double)), *vp = calloc((size_t)n, sizeof(double));
  double nothing[3] = {0.0, 0.0, 0.0};
  int rc = LANDYN_OK;
  for (int k = 1; k <= 300 && rc == LANDYN_OK; k++) {
    double t = 0.001 * (k - 1);
    double m[3] = {0.0, 100000.0 * sin(2.0 * M_PI * 5.0 * t), 0.0};
    rc = landyn_set_input(sim, NULL, m, msg, sizeof msg);
    if (rc == LANDYN_OK) rc = landyn_advance_to(sim, 0.001 * k, msg, sizeof msg);
    if (rc == LANDYN_OK) rc = landyn_set_input(zero, nothing, nothing, msg, sizeof msg);
    if (rc == LANDYN_OK) rc = landyn_advance_to(zero, 0.001 * k, msg, sizeof msg);
    if (rc == LANDYN_OK) rc = landyn_advance_to(plain, 0.001 * k, msg, sizeof msg);
  }
  CHECK(rc == LANDYN_OK, "the moment run");
  if (rc != LANDYN_OK) fprintf(stderr, "%s\n", msg);
  landyn_get_outputs(zero, vz, n, msg, sizeof msg);
  landyn_get_outputs(plain, vp, n, msg, sizeof msg);
  CHECK(memcmp(vz, vp, sizeof(double) * (size_t)n) == 0, "zero inputs leave the run as it was");
  double pitch_m, pitch_p;
  landyn_get_output(sim, "euler.pitch", &pitch_m, msg, sizeof msg);
  landyn_get_output(plain, "euler.pitch", &pitch_p, msg, sizeof msg);
  CHECK(fabs(pitch_m - pitch_p) > 0.01, "the moment pitches the lander (the test can fail)");
  snprintf(path, sizeof path, "%s/moment.h5", workdir);
  remove(path);
  CHECK(landyn_write_result(sim, path, msg, sizeof msg) == LANDYN_OK, "write moment.h5");
  snprintf(path, sizeof path, "%s/moment_plain.h5", workdir);
  remove(path);
  CHECK(landyn_write_result(plain, path, msg, sizeof msg) == LANDYN_OK, "write moment_plain.h5");
  free(vz);
  free(vp);
  landyn_free(&sim);
  landyn_free(&zero);
  landyn_free(&plain);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: test_api_inputs DECK WORKDIR\n");
    return 2;
  }
  char *deck = read_text(argv[1]);
  if (!deck) return 2;
  thrust_vs_input(deck, "adaptive");
  thrust_vs_input(deck, "fixed");
  moment_input(deck, argv[2]);
  free(deck);
  printf("%s: %d failed checks\n", argv[0], n_failed);
  return n_failed ? 1 : 0;
}
