/* Two simulations in one process, in two threads at once, give the results of separate runs:
 *   test_api_threads DECK_A DECK_B
 * Each deck is run alone first (outputs every 10 ms), then both in two pthreads at the same time,
 * then deck A in both threads; every output at every stop must be identical (bit for bit). */
#include <pthread.h>

#include "landyn.h"
#include "api_test_util.h"

#define N_STOPS 40

typedef struct {
  const char *deck;
  int n;              /* outputs */
  double *values;     /* N_STOPS x n */
  int rc;
} job_t;

static void *run(void *arg) {
  job_t *job = arg;
  char msg[512];
  landyn_sim *sim = NULL;
  job->rc = landyn_create(job->deck, "&simulation\n  t_end = 0.4\n/\n", &sim, msg, sizeof msg);
  if (job->rc != LANDYN_OK) return NULL;
  landyn_output_count(sim, &job->n);
  job->values = calloc((size_t)N_STOPS * (size_t)job->n, sizeof(double));
  for (int k = 0; k < N_STOPS && job->rc == LANDYN_OK; k++) {
    job->rc = landyn_advance_to(sim, 0.01 * (k + 1), msg, sizeof msg);
    if (job->rc == LANDYN_OK) job->rc = landyn_get_outputs(sim, job->values + (size_t)k * job->n, job->n, msg, sizeof msg);
  }
  landyn_free(&sim);
  return NULL;
}

static int same(const job_t *a, const job_t *b) {
  return a->rc == LANDYN_OK && b->rc == LANDYN_OK && a->n == b->n &&
         memcmp(a->values, b->values, (size_t)N_STOPS * (size_t)a->n * sizeof(double)) == 0;
}

static void in_threads(job_t *x, job_t *y) {
  pthread_t tx, ty;
  pthread_create(&tx, NULL, run, x);
  pthread_create(&ty, NULL, run, y);
  pthread_join(tx, NULL);
  pthread_join(ty, NULL);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: test_api_threads DECK_A DECK_B\n");
    return 2;
  }
  char *deck_a = read_text(argv[1]), *deck_b = read_text(argv[2]);
  if (!deck_a || !deck_b) return 2;
  job_t a = {deck_a}, b = {deck_b}, ta = {deck_a}, tb = {deck_b}, t1 = {deck_a}, t2 = {deck_a};
  run(&a);
  run(&b);
  CHECK(a.rc == LANDYN_OK && b.rc == LANDYN_OK, "the separate runs");
  CHECK(!same(&a, &b), "the two decks give different results (the test can fail)");
  in_threads(&ta, &tb);
  CHECK(same(&a, &ta), "deck A in a thread, B in another at the same time: A's separate result");
  CHECK(same(&b, &tb), "deck A in a thread, B in another at the same time: B's separate result");
  in_threads(&t1, &t2);
  CHECK(same(&a, &t1) && same(&a, &t2), "deck A in two threads at once: its separate result in both");
  printf("%s: %d failed checks\n", argv[0], n_failed);
  return n_failed ? 1 : 0;
}
