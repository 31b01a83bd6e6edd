/* Misuse of the C API (include/landyn.h): every call gets a status and a message, never a crash.
 *   test_api_misuse WORKDIR */
#include <math.h>
#include <stdint.h>

#include "landyn.h"
#include "api_test_util.h"

static const char *short_deck = "&simulation\n  t_end = 0.05\n/\n";

static void bad_decks(void) {
  char msg[2048];
  landyn_sim *sim = (landyn_sim *)&msg;  /* must come back NULL */
  int rc = landyn_create("&simulation\n  t_endd = 1.0\n/\n", NULL, &sim, msg, sizeof msg);
  CHECK(rc == LANDYN_ERR_INPUT, "unknown variable: LANDYN_ERR_INPUT");
  CHECK(sim == NULL, "unknown variable: the handle is NULL");
  CHECK(strstr(msg, "simulation") && strstr(msg, "t_endd"), "unknown variable: the message names group and variable");
  rc = landyn_create(NULL, "&simulation\n  t_end = -1.0\n/\n", &sim, msg, sizeof msg);
  CHECK(rc == LANDYN_ERR_INPUT, "value out of range: LANDYN_ERR_INPUT");
  CHECK(strstr(msg, "simulation") && strstr(msg, "t_end") && strstr(msg, "-1"),
        "value out of range: the message names group, variable and value");
  fprintf(stderr, "out-of-range message: %s\n", msg);
  rc = landyn_create("&simulation t_end = 0.05 /", "&nogroup x = 1 /", &sim, msg, sizeof msg);
  CHECK(rc == LANDYN_ERR_INPUT && strstr(msg, "nogroup"), "unknown group in the overrides");
  rc = landyn_create(NULL, NULL, NULL, msg, sizeof msg);
  CHECK(rc == LANDYN_ERR_HANDLE, "landyn_create with a NULL handle pointer");
  rc = landyn_create("&simulation\n  t_endd = 1.0\n/\n", NULL, &sim, NULL, 0);
  CHECK(rc == LANDYN_ERR_INPUT, "a bad deck without a message buffer");
}

/* Every function given the handle h must return LANDYN_ERR_HANDLE. */
static void all_refuse(landyn_sim *h, const char *what) {
  char msg[256], name[64], unit[16], meaning[128];
  double f[3] = {0, 0, 0}, t, v[8];
  int n;
  char label[160];
  snprintf(label, sizeof label, "%s: every function returns LANDYN_ERR_HANDLE", what);
  CHECK(landyn_set_input(h, f, f, msg, sizeof msg) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_advance_to(h, 0.01, msg, sizeof msg) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_time(h, &t) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_output_count(h, &n) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_output_info(h, 0, name, sizeof name, unit, sizeof unit, meaning, sizeof meaning) == LANDYN_ERR_HANDLE,
        label);
  CHECK(landyn_get_outputs(h, v, 8, msg, sizeof msg) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_get_output(h, "time", v, msg, sizeof msg) == LANDYN_ERR_HANDLE, label);
  CHECK(landyn_write_result(h, "never.h5", msg, sizeof msg) == LANDYN_ERR_HANDLE, label);
  landyn_sim *copy = h;
  CHECK(landyn_free(&copy) == LANDYN_ERR_HANDLE, label);
}

static void handles(void) {
  char msg[256];
  static uint64_t foreign[512];  /* zeros: not a LANDYN handle */
  landyn_sim *sim = NULL;
  all_refuse(NULL, "NULL handle");
  CHECK(landyn_free(NULL) == LANDYN_ERR_HANDLE, "landyn_free(NULL)");
  CHECK(landyn_free(&sim) == LANDYN_ERR_HANDLE, "landyn_free of a NULL handle");
  all_refuse((landyn_sim *)foreign, "foreign pointer");
  foreign[0] = 0x4C414E44594E3235ull;  /* close to the magic number, not it */
  all_refuse((landyn_sim *)foreign, "foreign pointer with a near magic number");
  CHECK(landyn_create(short_deck, NULL, &sim, msg, sizeof msg) == LANDYN_OK && sim != NULL, "create");
  CHECK(landyn_free(&sim) == LANDYN_OK, "free");
  CHECK(sim == NULL, "landyn_free sets the handle to NULL");
  all_refuse(sim, "handle after landyn_free");
}

static void order_and_values(const char *workdir) {
  char msg[512], name[64], unit[16], meaning[128], path[1024];
  landyn_sim *sim = NULL;
  double f[3] = {0, 0, 0}, m[3] = {0, 0, 0}, t = -1, v;
  int n = 0;
  if (landyn_create(short_deck, NULL, &sim, msg, sizeof msg) != LANDYN_OK) {
    CHECK(0, "create the short deck");
    return;
  }
  CHECK(landyn_advance_to(sim, 0.01, msg, sizeof msg) == LANDYN_OK, "advance to 0.01");
  CHECK(landyn_time(sim, &t) == LANDYN_OK && t == 0.01, "the time is exactly 0.01");
  CHECK(landyn_advance_to(sim, 0.005, msg, sizeof msg) == LANDYN_ERR_ORDER && strstr(msg, "backwards"),
        "advance backwards: LANDYN_ERR_ORDER");
  CHECK(landyn_advance_to(sim, 0.06, msg, sizeof msg) == LANDYN_ERR_ORDER && strstr(msg, "t_end"),
        "advance past t_end: LANDYN_ERR_ORDER naming t_end");
  CHECK(landyn_advance_to(sim, NAN, msg, sizeof msg) == LANDYN_ERR_INPUT, "advance to NaN: LANDYN_ERR_INPUT");
  CHECK(landyn_time(sim, NULL) == LANDYN_ERR_INPUT, "landyn_time with a NULL result");
  f[1] = NAN;
  CHECK(landyn_set_input(sim, f, m, msg, sizeof msg) == LANDYN_ERR_INPUT && strstr(msg, "force"),
        "set_input NaN force: LANDYN_ERR_INPUT");
  f[1] = 0;
  m[2] = INFINITY;
  CHECK(landyn_set_input(sim, f, m, msg, sizeof msg) == LANDYN_ERR_INPUT && strstr(msg, "moment"),
        "set_input infinite moment: LANDYN_ERR_INPUT");
  CHECK(landyn_get_output(sim, "gear1.strut1.strok", &v, msg, sizeof msg) == LANDYN_ERR_INPUT &&
            strstr(msg, "gear1.strut1.stroke"),
        "unknown output name: LANDYN_ERR_INPUT suggesting the closest");
  CHECK(landyn_get_output(sim, NULL, &v, msg, sizeof msg) == LANDYN_ERR_INPUT, "NULL output name");
  CHECK(landyn_output_count(sim, &n) == LANDYN_OK && n > 100, "output count");
  double *values = calloc((size_t)n, sizeof(double));
  CHECK(landyn_get_outputs(sim, values, n - 1, msg, sizeof msg) == LANDYN_ERR_INPUT, "values too small");
  CHECK(landyn_get_outputs(sim, NULL, n, msg, sizeof msg) == LANDYN_ERR_INPUT, "values NULL");
  CHECK(landyn_get_outputs(sim, values, n, msg, sizeof msg) == LANDYN_OK && values[0] == 0.01, "values");
  free(values);
  CHECK(landyn_output_info(sim, n, name, sizeof name, unit, sizeof unit, meaning, sizeof meaning) == LANDYN_ERR_INPUT,
        "output_info past the count");
  CHECK(landyn_output_info(sim, -1, NULL, 0, NULL, 0, NULL, 0) == LANDYN_ERR_INPUT, "output_info -1");
  /* buffers too small: truncated, NUL-terminated */
  memset(name, 'X', sizeof name);
  CHECK(landyn_output_info(sim, 3, name, 5, unit, 1, NULL, 0) == LANDYN_OK, "output_info with small buffers");
  CHECK(strcmp(name, "posi") == 0 && unit[0] == '\0' && name[6] == 'X', "name truncated to 4 characters and a NUL");
  memset(msg, 'X', sizeof msg);
  CHECK(landyn_advance_to(sim, 0.005, msg, 8) == LANDYN_ERR_ORDER && strlen(msg) == 7 && msg[9] == 'X',
        "message truncated to the buffer");
  CHECK(landyn_advance_to(sim, 0.005, NULL, 0) == LANDYN_ERR_ORDER, "message buffer NULL");
  /* write_result onto an existing input deck: refused, the deck kept */
  snprintf(path, sizeof path, "%s/misuse_deck.nml", workdir);
  FILE *fp = fopen(path, "w");
  fputs(short_deck, fp);
  fclose(fp);
  CHECK(landyn_write_result(sim, path, msg, sizeof msg) == LANDYN_ERR_FILE, "write onto a deck: LANDYN_ERR_FILE");
  fprintf(stderr, "write onto a deck: %s\n", msg);
  char *kept = read_text(path);
  CHECK(kept && strcmp(kept, short_deck) == 0, "the deck is unchanged");
  free(kept);
  CHECK(landyn_write_result(sim, NULL, msg, sizeof msg) == LANDYN_ERR_FILE, "write to a NULL path");
  snprintf(path, sizeof path, "%s/no/such/dir/x.h5", workdir);
  CHECK(landyn_write_result(sim, path, msg, sizeof msg) == LANDYN_ERR_FILE, "write into a missing directory");
  /* the end: advance to t_end, then inputs are out of order */
  CHECK(landyn_advance_to(sim, 0.05, msg, sizeof msg) == LANDYN_OK, "advance to t_end");
  CHECK(landyn_get_output(sim, "outcome", &v, msg, sizeof msg) == LANDYN_OK &&
            v != LANDYN_OUTCOME_RUNNING && v != LANDYN_OUTCOME_FAILED,
        "an outcome at t_end");
  f[1] = 1.0;
  CHECK(landyn_set_input(sim, f, NULL, msg, sizeof msg) == LANDYN_ERR_ORDER, "set_input after the end");
  CHECK(landyn_advance_to(sim, 0.05, msg, sizeof msg) == LANDYN_OK, "advance to t_end again: nothing to do");
  landyn_free(&sim);
}

static void fixed_steps(void) {
  char msg[512];
  landyn_sim *sim = NULL;
  if (landyn_create("&simulation\n integrator = 'fixed'\n dt = 1.0e-4\n t_end = 0.01\n/\n", NULL, &sim, msg,
                    sizeof msg) != LANDYN_OK) {
    CHECK(0, "create a fixed-step deck");
    return;
  }
  CHECK(landyn_advance_to(sim, 0.00125, msg, sizeof msg) == LANDYN_ERR_INPUT &&
            (strstr(msg, "0.00125") || strstr(msg, "1.25e-3")) && strstr(msg, "dt ="),
        "fixed: a time between steps is LANDYN_ERR_INPUT naming the value and dt");
  fprintf(stderr, "fixed step message: %s\n", msg);
  CHECK(landyn_advance_to(sim, 0.0013, msg, sizeof msg) == LANDYN_OK, "fixed: a whole number of steps");
  landyn_free(&sim);
}

/* A run stopped before t_end and written, before touchdown: check_stopped.py reads stopped.h5. */
static void stopped_early(const char *workdir) {
  char msg[512], path[1024];
  landyn_sim *sim = NULL;
  double f[3] = {0.0, 0.0, -1000.0};
  if (landyn_create(short_deck, "&initial_state\n clearance = 1.0\n/\n", &sim, msg, sizeof msg) != LANDYN_OK) {
    CHECK(0, "create a deck starting 1 m up");
    return;
  }
  CHECK(landyn_set_input(sim, f, NULL, msg, sizeof msg) == LANDYN_OK, "an input at t = 0");
  CHECK(landyn_advance_to(sim, 0.0105, msg, sizeof msg) == LANDYN_OK, "advance to 0.0105 s");
  snprintf(path, sizeof path, "%s/stopped.h5", workdir);
  remove(path);
  CHECK(landyn_write_result(sim, path, msg, sizeof msg) == LANDYN_OK, "write a run stopped before t_end");
  CHECK(landyn_advance_to(sim, 0.02, msg, sizeof msg) == LANDYN_OK, "the run goes on after writing");
  landyn_free(&sim);
}

/* A run that comes to rest before the requested time: LANDYN_ENDED, the state at its end. */
static void ended_early(void) {
  char msg[512];
  landyn_sim *sim = NULL;
  double t = 0, outcome = -1, f[3] = {1.0, 0.0, 0.0};
  const char *deck = "&simulation\n t_end = 3.0\n stop_at_rest = .true.\n rest_speed = 0.02\n rest_time = 0.1\n/\n"
                     "&initial_state\n clearance = 0.0\n velocity = 0.0, 0.0, 1.0\n/\n";
  if (landyn_create(deck, NULL, &sim, msg, sizeof msg) != LANDYN_OK) {
    CHECK(0, "create a deck that comes to rest");
    return;
  }
  CHECK(landyn_advance_to(sim, 3.0, msg, sizeof msg) == LANDYN_ENDED && strstr(msg, "at rest"),
        "at rest before t: LANDYN_ENDED saying why");
  fprintf(stderr, "ended: %s\n", msg);
  CHECK(landyn_time(sim, &t) == LANDYN_OK && t > 1.0 && t < 3.0, "the state stays at the end time");
  CHECK(landyn_get_output(sim, "outcome", &outcome, msg, sizeof msg) == LANDYN_OK && outcome == LANDYN_OUTCOME_AT_REST,
        "outcome at rest");
  CHECK(landyn_advance_to(sim, 3.0, msg, sizeof msg) == LANDYN_ENDED, "LANDYN_ENDED again");
  CHECK(landyn_set_input(sim, f, NULL, msg, sizeof msg) == LANDYN_ERR_ORDER, "no input after the end");
  landyn_free(&sim);
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: test_api_misuse WORKDIR\n");
    return 2;
  }
  printf("%s\n", landyn_version());
  bad_decks();
  handles();
  order_and_values(argv[1]);
  fixed_steps();
  stopped_early(argv[1]);
  ended_early();
  printf("%s: %d failed checks\n", argv[0], n_failed);
  return n_failed ? 1 : 0;
}
