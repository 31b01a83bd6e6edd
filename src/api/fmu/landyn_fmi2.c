/*
 * landyn_fmi2.c - the FMI 2.0 co-simulation interface of LANDYN over its C API (include/landyn.h).
 * Reference: docs/api.md, "FMU".
 *
 * One instance holds the values of every variable of the generated table (landyn_fmu_vars.h; value
 * reference = row), and after initialization one landyn_sim. At fmi2ExitInitializationMode the
 * deck is built: deck_file's text (or the defaults) and an overrides text with one block per group
 * of the parameters whose value differs from their start; fmi2DoStep passes the engine inputs and
 * advances to t + h; LANDYN_ENDED (at rest, tipped over) is fmi2Discard with fmi2Terminated true.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "landyn.h"
#include "landyn_fmu_vars.h"

#define MSG_LEN 8192

enum { ST_INSTANTIATED, ST_INIT, ST_STEP, ST_TERMINATED, ST_ERROR };

typedef struct {
  char *name;                    /* instance name */
  fmi2CallbackLogger logger;     /* may be NULL */
  fmi2ComponentEnvironment env;  /* the importer's environment pointer */
  int state;                     /* ST_* */
  double *reals;                 /* per value reference: Real value */
  int *ints;                     /* per value reference: Integer or Boolean value */
  char **strings;                /* per value reference: String value (malloc'd) */
  int *out_index;                /* per value reference: output index in the simulation, -1 if absent */
  double *out_values;            /* the simulation's outputs at its current time */
  int n_out;                     /* their number */
  landyn_sim *sim;               /* NULL until initialized */
  int stop_defined;              /* fmi2SetupExperiment gave a stop time */
  double stop_time;              /* [s] */
  int ended;                     /* the run ended (LANDYN_ENDED): fmi2Terminated */
} landyn_fmu;

/* ---- messages --------------------------------------------------------------------------------- */

static void say(landyn_fmu *c, fmi2Status status, const char *fmt, ...) {
  char msg[MSG_LEN];
  va_list ap;
  if (c == NULL || c->logger == NULL) return;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  /* the logger takes a format: pass the message as an argument so '%' in it is safe */
  c->logger(c->env, c->name, status, status == fmi2Discard ? "logStatusDiscard" : "logStatusError", "%s", msg);
}

static fmi2Status fail(landyn_fmu *c, const char *fmt, ...) {
  char msg[MSG_LEN];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  say(c, fmi2Error, "%s", msg);
  return fmi2Error;
}

static char *copy_text(const char *s) {
  size_t n = strlen(s ? s : "");
  char *t = malloc(n + 1);
  if (t) memcpy(t, s ? s : "", n + 1);
  return t;
}

/* ---- a growing text --------------------------------------------------------------------------- */

typedef struct {
  char *s;
  size_t n, cap;
  int bad;
} text_t;

static void put(text_t *t, const char *s) {
  size_t k = strlen(s);
  if (t->bad) return;
  if (t->n + k + 1 > t->cap) {
    size_t cap = 2 * (t->n + k + 1) + 256;
    char *p = malloc(cap); /* not realloc: under LTO it meets gfortran's own declaration of it */
    if (p == NULL) {
      t->bad = 1;
      return;
    }
    if (t->s != NULL) memcpy(p, t->s, t->n + 1);
    free(t->s);
    t->s = p;
    t->cap = cap;
  }
  memcpy(t->s + t->n, s, k + 1);
  t->n += k;
}

/* The shortest of %.15g .. %.17g that reads back as x. */
static void real_text(double x, char *buf, size_t n) {
  int d;
  for (d = 15; d <= 17; d++) {
    snprintf(buf, n, "%.*g", d, x);
    if (strtod(buf, NULL) == x) return;
  }
}

/* ---- values ----------------------------------------------------------------------------------- */

static void set_starts(landyn_fmu *c) {
  int i;
  for (i = 0; i < landyn_fmu_n_vars; i++) {
    const landyn_fmu_var *v = &landyn_fmu_vars[i];
    c->reals[i] = v->type == LANDYN_FMU_REAL && v->role != LANDYN_FMU_INPUT ? v->real_start : 0.0;
    c->ints[i] = v->role == LANDYN_FMU_INPUT ? 0 : v->int_start;
    free(c->strings[i]);
    c->strings[i] = v->type == LANDYN_FMU_STRING ? copy_text(v->string_start) : NULL;
  }
}

/* Whether parameter i differs from its start (only those go into the overrides). */
static int changed(const landyn_fmu *c, int i) {
  const landyn_fmu_var *v = &landyn_fmu_vars[i];
  switch (v->type) {
    case LANDYN_FMU_REAL: return c->reals[i] != v->real_start;
    case LANDYN_FMU_STRING: return strcmp(c->strings[i] ? c->strings[i] : "", v->string_start) != 0;
    default: return c->ints[i] != v->int_start;
  }
}

/* "  item = value" of parameter i. */
static void put_item(text_t *t, const landyn_fmu *c, int i) {
  const landyn_fmu_var *v = &landyn_fmu_vars[i];
  char buf[64];
  const char *p;
  put(t, "  ");
  put(t, v->item);
  put(t, " = ");
  switch (v->type) {
    case LANDYN_FMU_REAL: real_text(c->reals[i], buf, sizeof buf); put(t, buf); break;
    case LANDYN_FMU_INTEGER: snprintf(buf, sizeof buf, "%d", c->ints[i]); put(t, buf); break;
    case LANDYN_FMU_BOOLEAN: put(t, c->ints[i] ? ".true." : ".false."); break;
    default:
      put(t, "'");
      for (p = c->strings[i] ? c->strings[i] : ""; *p; p++) {
        char ch[2] = {*p, 0};
        put(t, *p == '\'' ? "''" : ch);
      }
      put(t, "'");
  }
  put(t, "\n");
}

/* The overrides: one block per group of the changed parameters (the table lists a group's
 * parameters together); the experiment's stop time is &simulation t_end unless that was set. */
static char *overrides_text(const landyn_fmu *c) {
  text_t t = {NULL, 0, 0, 0};
  const char *open = NULL;
  int i, t_end_set = 0, t_end_done = 0;
  char buf[64];
  put(&t, "");
  for (i = 0; i < landyn_fmu_n_vars; i++)
    if (landyn_fmu_vars[i].role == LANDYN_FMU_PARAMETER && strcmp(landyn_fmu_vars[i].group, "simulation") == 0 &&
        strcmp(landyn_fmu_vars[i].item, "t_end") == 0 && changed(c, i))
      t_end_set = 1;
  for (i = 0; i <= landyn_fmu_n_vars; i++) {
    const landyn_fmu_var *v = i < landyn_fmu_n_vars ? &landyn_fmu_vars[i] : NULL;
    int param = v != NULL && v->role == LANDYN_FMU_PARAMETER;
    if (open != NULL && (!param || strcmp(v->group, open) != 0)) {
      put(&t, "/\n");
      open = NULL;
    }
    if (!param) continue;
    if (strcmp(v->group, "simulation") == 0 && c->stop_defined && !t_end_set && !t_end_done) {
      if (open == NULL) put(&t, "&simulation\n");
      open = v->group;
      real_text(c->stop_time, buf, sizeof buf);
      put(&t, "  t_end = ");
      put(&t, buf);
      put(&t, "\n");
      t_end_done = 1;
    }
    if (!changed(c, i)) continue;
    if (open == NULL) {
      put(&t, "&");
      put(&t, v->group);
      put(&t, "\n");
      open = v->group;
    }
    put_item(&t, c, i);
  }
  if (t.bad) {
    free(t.s);
    return NULL;
  }
  return t.s;
}

/* The whole text of a file, or NULL (errno-style message in msg). */
static char *file_text(const char *path, char *msg, size_t n) {
  FILE *f = fopen(path, "rb");
  char *s = NULL;
  long len;
  if (f == NULL) {
    snprintf(msg, n, "deck_file = '%s' cannot be read: no such file or no permission", path);
    return NULL;
  }
  if (fseek(f, 0, SEEK_END) == 0 && (len = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
    s = malloc((size_t)len + 1);
    if (s != NULL && fread(s, 1, (size_t)len, f) == (size_t)len) {
      s[len] = '\0';
    } else {
      free(s);
      s = NULL;
    }
  }
  fclose(f);
  if (s == NULL) snprintf(msg, n, "deck_file = '%s' cannot be read", path);
  return s;
}

static int vr_of(const char *name) {
  int i;
  for (i = 0; i < landyn_fmu_n_vars; i++)
    if (strcmp(landyn_fmu_vars[i].name, name) == 0) return i;
  return -1;
}

static fmi2Status refresh_outputs(landyn_fmu *c) {
  char msg[MSG_LEN];
  if (landyn_get_outputs(c->sim, c->out_values, c->n_out, msg, sizeof msg) != LANDYN_OK)
    return fail(c, "landyn_get_outputs: %s", msg);
  return fmi2OK;
}

/* Creates the simulation from deck_file and the parameters; maps the outputs by name. */
static fmi2Status create_sim(landyn_fmu *c) {
  char msg[MSG_LEN], name[256];
  char *deck = NULL, *over;
  const char *path = c->strings[vr_of("deck_file")];
  int i, k, rc;
  if (path != NULL && path[0] != '\0') {
    deck = file_text(path, msg, sizeof msg);
    if (deck == NULL) return fail(c, "%s", msg);
  }
  over = overrides_text(c);
  if (over == NULL) {
    free(deck);
    return fail(c, "out of memory");
  }
  rc = landyn_create_named(deck, path, over, &c->sim, msg, sizeof msg);
  free(deck);
  free(over);
  if (rc != LANDYN_OK) return fail(c, "the deck is invalid:\n%s", msg);
  if (landyn_output_count(c->sim, &c->n_out) != LANDYN_OK || c->n_out < 0) return fail(c, "landyn_output_count failed");
  free(c->out_values);
  c->out_values = calloc((size_t)c->n_out + 1, sizeof(double));
  if (c->out_values == NULL) return fail(c, "out of memory");
  for (i = 0; i < landyn_fmu_n_vars; i++) c->out_index[i] = -1;
  for (k = 0; k < c->n_out; k++) {
    if (landyn_output_info(c->sim, k, name, sizeof name, NULL, 0, NULL, 0) != LANDYN_OK) continue;
    i = vr_of(name);
    if (i >= 0 && landyn_fmu_vars[i].role == LANDYN_FMU_OUTPUT) c->out_index[i] = k;
  }
  return refresh_outputs(c);
}

static void drop_sim(landyn_fmu *c) {
  if (c->sim != NULL) landyn_free(&c->sim);
  c->sim = NULL;
  c->ended = 0;
}

/* ---- common functions ------------------------------------------------------------------------- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean on, size_t n, const fmi2String cats[]) {
  (void)on;
  (void)n;
  (void)cats;
  return comp == NULL ? fmi2Error : fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible, fmi2Boolean logging) {
  landyn_fmu *c;
  size_t n = (size_t)landyn_fmu_n_vars;
  (void)location;
  (void)visible;
  (void)logging;
  c = calloc(1, sizeof *c);
  if (c == NULL) return NULL;
  c->name = copy_text(name ? name : "landyn");
  c->logger = functions ? functions->logger : NULL;
  c->env = functions ? functions->componentEnvironment : NULL;
  c->reals = calloc(n, sizeof(double));
  c->ints = calloc(n, sizeof(int));
  c->strings = calloc(n, sizeof(char *));
  c->out_index = calloc(n, sizeof(int));
  if (c->name == NULL || c->reals == NULL || c->ints == NULL || c->strings == NULL || c->out_index == NULL) {
    fmi2FreeInstance(c);
    return NULL;
  }
  if (type != fmi2CoSimulation) {
    fail(c, "fmi2Instantiate: landyn is a co-simulation FMU only (fmuType %d asked)", (int)type);
    fmi2FreeInstance(c);
    return NULL;
  }
  if (guid == NULL || strcmp(guid, landyn_fmu_guid) != 0) {
    fail(c, "fmi2Instantiate: guid '%s' is not this FMU's %s", guid ? guid : "(null)", landyn_fmu_guid);
    fmi2FreeInstance(c);
    return NULL;
  }
  set_starts(c);
  c->state = ST_INSTANTIATED;
  return c;
}

void fmi2FreeInstance(fmi2Component comp) {
  landyn_fmu *c = comp;
  int i;
  if (c == NULL) return;
  drop_sim(c);
  if (c->strings)
    for (i = 0; i < landyn_fmu_n_vars; i++) free(c->strings[i]);
  free(c->strings);
  free(c->reals);
  free(c->ints);
  free(c->out_index);
  free(c->out_values);
  free(c->name);
  free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean tol_defined, fmi2Real tol, fmi2Real start,
                               fmi2Boolean stop_defined, fmi2Real stop) {
  landyn_fmu *c = comp;
  (void)tol_defined;
  (void)tol;
  if (c == NULL) return fmi2Error;
  if (c->state != ST_INSTANTIATED) return fail(c, "fmi2SetupExperiment: only after fmi2Instantiate");
  if (start != 0.0) return fail(c, "fmi2SetupExperiment: startTime = %g; a LANDYN run starts at t = 0", start);
  c->stop_defined = stop_defined ? 1 : 0;
  c->stop_time = stop;
  return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp) {
  landyn_fmu *c = comp;
  if (c == NULL) return fmi2Error;
  if (c->state != ST_INSTANTIATED) return fail(c, "fmi2EnterInitializationMode: only after fmi2Instantiate");
  c->state = ST_INIT;
  return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp) {
  landyn_fmu *c = comp;
  fmi2Status s;
  if (c == NULL) return fmi2Error;
  if (c->state != ST_INIT) return fail(c, "fmi2ExitInitializationMode: only in initialization mode");
  if (c->sim == NULL) {
    s = create_sim(c);
    if (s != fmi2OK) {
      drop_sim(c);
      c->state = ST_ERROR;
      return s;
    }
  }
  c->state = ST_STEP;
  return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp) {
  landyn_fmu *c = comp;
  char msg[MSG_LEN];
  const char *path;
  if (c == NULL) return fmi2Error;
  if (c->state != ST_STEP) return fail(c, "fmi2Terminate: only after initialization");
  c->state = ST_TERMINATED;
  path = c->strings[vr_of("result_file")];
  if (path != NULL && path[0] != '\0' && landyn_write_result(c->sim, path, msg, sizeof msg) != LANDYN_OK)
    return fail(c, "result_file = '%s': %s", path, msg);
  return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp) {
  landyn_fmu *c = comp;
  if (c == NULL) return fmi2Error;
  drop_sim(c);
  set_starts(c);
  c->stop_defined = 0;
  c->state = ST_INSTANTIATED;
  return fmi2OK;
}

/* ---- get and set ------------------------------------------------------------------------------ */

static fmi2Status check_vr(landyn_fmu *c, const char *fn, fmi2ValueReference vr, int type) {
  static const char *types[] = {"Real", "Integer", "Boolean", "String"};
  if (vr >= (fmi2ValueReference)landyn_fmu_n_vars) return fail(c, "%s: no variable has value reference %u", fn, vr);
  if (landyn_fmu_vars[vr].type != type)
    return fail(c, "%s: %s is a %s variable", fn, landyn_fmu_vars[vr].name, types[landyn_fmu_vars[vr].type]);
  return fmi2OK;
}

/* Whether variable vr may be set now: parameters before initialization ends, inputs always. */
static fmi2Status settable(landyn_fmu *c, const char *fn, fmi2ValueReference vr) {
  int role = landyn_fmu_vars[vr].role;
  if (c->state == ST_ERROR || c->state == ST_TERMINATED) return fail(c, "%s: the instance is terminated or failed", fn);
  if (role == LANDYN_FMU_OUTPUT) return fail(c, "%s: %s is an output", fn, landyn_fmu_vars[vr].name);
  if (role != LANDYN_FMU_INPUT && c->state == ST_STEP)
    return fail(c, "%s: parameter %s can be set only before fmi2ExitInitializationMode", fn, landyn_fmu_vars[vr].name);
  if (role != LANDYN_FMU_INPUT && c->sim != NULL && c->state == ST_INIT) drop_sim(c);  /* outputs read early */
  return fmi2OK;
}

/* The value of Real variable vr: its own for parameters and inputs, the simulation's for outputs
 * (created here when read during initialization). */
static fmi2Status real_value(landyn_fmu *c, const char *fn, fmi2ValueReference vr, fmi2Real *value) {
  if (landyn_fmu_vars[vr].role != LANDYN_FMU_OUTPUT) {
    *value = c->reals[vr];
    return fmi2OK;
  }
  if (c->sim == NULL && c->state == ST_INIT && create_sim(c) != fmi2OK) {
    drop_sim(c);
    return fmi2Error;
  }
  if (c->sim == NULL) return fail(c, "%s: %s: no simulation (initialization failed or not done)", fn,
                                  landyn_fmu_vars[vr].name);
  *value = c->out_index[vr] >= 0 ? c->out_values[c->out_index[vr]] : 0.0;
  return fmi2OK;
}

/* fmi2Get<type> (fn): value is the caller's array of n fmi2Real, fmi2Integer, fmi2Boolean or fmi2String,
 * as type (LANDYN_FMU_*) says. */
static fmi2Status get_values(fmi2Component comp, const char *fn, const fmi2ValueReference vr[], size_t n, int type,
                             void *value) {
  landyn_fmu *c = comp;
  size_t i;
  if (c == NULL) return fmi2Error;
  for (i = 0; i < n; i++) {
    fmi2ValueReference r = vr[i];
    if (check_vr(c, fn, r, type) != fmi2OK) return fmi2Error;
    switch (type) {
      case LANDYN_FMU_REAL:
        if (real_value(c, fn, r, &((fmi2Real *)value)[i]) != fmi2OK) return fmi2Error;
        break;
      case LANDYN_FMU_INTEGER: ((fmi2Integer *)value)[i] = c->ints[r]; break;
      case LANDYN_FMU_BOOLEAN: ((fmi2Boolean *)value)[i] = c->ints[r] ? fmi2True : fmi2False; break;
      default: ((fmi2String *)value)[i] = c->strings[r] ? c->strings[r] : ""; break;
    }
  }
  return fmi2OK;
}

/* Sets variable vr of type (LANDYN_FMU_*) to value[i] of fmi2Set<type> (fn)'s array value. */
static fmi2Status set_value(landyn_fmu *c, const char *fn, fmi2ValueReference vr, int type, const void *value,
                            size_t i) {
  double x;
  char *s;
  switch (type) {
    case LANDYN_FMU_REAL:
      x = ((const fmi2Real *)value)[i];
      if (!isfinite(x)) return fail(c, "%s: %s = %g is invalid; valid: a finite number", fn, landyn_fmu_vars[vr].name, x);
      c->reals[vr] = x;
      break;
    case LANDYN_FMU_INTEGER: c->ints[vr] = ((const fmi2Integer *)value)[i]; break;
    case LANDYN_FMU_BOOLEAN: c->ints[vr] = ((const fmi2Boolean *)value)[i] ? 1 : 0; break;
    default:
      s = copy_text(((const fmi2String *)value)[i]);
      if (s == NULL) return fail(c, "out of memory");
      free(c->strings[vr]);
      c->strings[vr] = s;
  }
  return fmi2OK;
}

/* fmi2Set<type> (fn): value is the caller's array of n values of that type (LANDYN_FMU_*). */
static fmi2Status set_values(fmi2Component comp, const char *fn, const fmi2ValueReference vr[], size_t n, int type,
                             const void *value) {
  landyn_fmu *c = comp;
  size_t i;
  if (c == NULL) return fmi2Error;
  for (i = 0; i < n; i++) {
    if (check_vr(c, fn, vr[i], type) != fmi2OK) return fmi2Error;
    if (settable(c, fn, vr[i]) != fmi2OK) return fmi2Error;
    if (set_value(c, fn, vr[i], type, value, i) != fmi2OK) return fmi2Error;
  }
  return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  return get_values(comp, "fmi2GetReal", vr, n, LANDYN_FMU_REAL, value);
}

fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t n, fmi2Integer value[]) {
  return get_values(comp, "fmi2GetInteger", vr, n, LANDYN_FMU_INTEGER, value);
}

fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t n, fmi2Boolean value[]) {
  return get_values(comp, "fmi2GetBoolean", vr, n, LANDYN_FMU_BOOLEAN, value);
}

fmi2Status fmi2GetString(fmi2Component comp, const fmi2ValueReference vr[], size_t n, fmi2String value[]) {
  return get_values(comp, "fmi2GetString", vr, n, LANDYN_FMU_STRING, value);
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
  return set_values(comp, "fmi2SetReal", vr, n, LANDYN_FMU_REAL, value);
}

fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t n, const fmi2Integer value[]) {
  return set_values(comp, "fmi2SetInteger", vr, n, LANDYN_FMU_INTEGER, value);
}

fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t n, const fmi2Boolean value[]) {
  return set_values(comp, "fmi2SetBoolean", vr, n, LANDYN_FMU_BOOLEAN, value);
}

fmi2Status fmi2SetString(fmi2Component comp, const fmi2ValueReference vr[], size_t n, const fmi2String value[]) {
  return set_values(comp, "fmi2SetString", vr, n, LANDYN_FMU_STRING, value);
}

/* ---- co-simulation ---------------------------------------------------------------------------- */

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_set_prior) {
  landyn_fmu *c = comp;
  char msg[MSG_LEN];
  double force[3] = {0, 0, 0}, moment[3] = {0, 0, 0}, target = t + h;
  int i, rc;
  (void)no_set_prior;
  if (c == NULL) return fmi2Error;
  if (c->state != ST_STEP)
    return fail(c, "fmi2DoStep: not in step mode (before fmi2ExitInitializationMode, after a failure or fmi2Terminate)");
  if (c->ended) {
    say(c, fmi2Discard, "fmi2DoStep: the run has ended (fmi2Terminated)");
    return fmi2Discard;
  }
  if (!(h >= 0.0)) return fail(c, "fmi2DoStep: communicationStepSize = %g is invalid; valid: >= 0", h);
  /* the importer's last point may miss the stop time (= &simulation t_end) by rounding */
  if (c->stop_defined && target > c->stop_time && target - c->stop_time <= 1e-12 * fmax(1.0, c->stop_time))
    target = c->stop_time;
  for (i = 0; i < landyn_fmu_n_vars; i++)
    if (landyn_fmu_vars[i].role == LANDYN_FMU_INPUT) {
      int k = landyn_fmu_vars[i].int_start;
      if (k < 3) force[k] = c->reals[i];
      else moment[k - 3] = c->reals[i];
    }
  if (landyn_set_input(c->sim, force, moment, msg, sizeof msg) != LANDYN_OK) {
    c->state = ST_ERROR;
    return fail(c, "fmi2DoStep: %s", msg);
  }
  rc = landyn_advance_to(c->sim, target, msg, sizeof msg);
  if (rc == LANDYN_OK) return refresh_outputs(c);
  if (rc == LANDYN_ENDED) {
    c->ended = 1;
    say(c, fmi2Discard, "fmi2DoStep: the run ended before t = %g: %s", target, msg);
    return refresh_outputs(c) == fmi2OK ? fmi2Discard : fmi2Error;
  }
  if (rc == LANDYN_ERR_FAILED) refresh_outputs(c);
  c->state = rc == LANDYN_ERR_FAILED ? ST_STEP : ST_ERROR;
  if (rc == LANDYN_ERR_FAILED) c->ended = 1;
  return fail(c, "fmi2DoStep to t = %g: %s", target, msg);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Boolean *value) {
  landyn_fmu *c = comp;
  if (c == NULL) return fmi2Error;
  if (s != fmi2Terminated) return fail(c, "fmi2GetBooleanStatus: only fmi2Terminated is provided");
  *value = c->ended ? fmi2True : fmi2False;
  return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value) {
  landyn_fmu *c = comp;
  if (c == NULL) return fmi2Error;
  if (s != fmi2LastSuccessfulTime) return fail(c, "fmi2GetRealStatus: only fmi2LastSuccessfulTime is provided");
  if (c->sim == NULL) return fail(c, "fmi2GetRealStatus: no simulation (not initialized)");
  return landyn_time(c->sim, value) == LANDYN_OK ? fmi2OK : fail(c, "fmi2GetRealStatus: landyn_time failed");
}

fmi2Status fmi2GetStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Status *value) {
  (void)s;
  (void)value;
  return fail(comp, "fmi2GetStatus: not provided (fmi2DoStep is synchronous)");
}

fmi2Status fmi2GetIntegerStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Integer *value) {
  (void)s;
  (void)value;
  return fail(comp, "fmi2GetIntegerStatus: not provided");
}

fmi2Status fmi2GetStringStatus(fmi2Component comp, const fmi2StatusKind s, fmi2String *value) {
  (void)s;
  (void)value;
  return fail(comp, "fmi2GetStringStatus: not provided (fmi2DoStep is synchronous)");
}

fmi2Status fmi2CancelStep(fmi2Component comp) {
  return fail(comp, "fmi2CancelStep: not provided (fmi2DoStep is synchronous)");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[]) {
  (void)vr;
  (void)n;
  (void)order;
  (void)value;
  return fail(comp, "fmi2SetRealInputDerivatives: not provided (canInterpolateInputs is false)");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real value[]) {
  (void)vr;
  (void)n;
  (void)order;
  (void)value;
  return fail(comp, "fmi2GetRealOutputDerivatives: not provided (maxOutputDerivativeOrder is 0)");
}

/* ---- not provided: FMU state, directional derivatives ---------------------------------------- */

fmi2Status fmi2GetFMUstate(fmi2Component comp, fmi2FMUstate *state) {
  (void)state;
  return fail(comp, "fmi2GetFMUstate: not provided (canGetAndSetFMUstate is false)");
}

fmi2Status fmi2SetFMUstate(fmi2Component comp, fmi2FMUstate state) {
  (void)state;
  return fail(comp, "fmi2SetFMUstate: not provided (canGetAndSetFMUstate is false)");
}

fmi2Status fmi2FreeFMUstate(fmi2Component comp, fmi2FMUstate *state) {
  (void)state;
  return fail(comp, "fmi2FreeFMUstate: not provided (canGetAndSetFMUstate is false)");
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component comp, fmi2FMUstate state, size_t *size) {
  (void)state;
  (void)size;
  return fail(comp, "fmi2SerializedFMUstateSize: not provided (canSerializeFMUstate is false)");
}

fmi2Status fmi2SerializeFMUstate(fmi2Component comp, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
  (void)state;
  (void)bytes;
  (void)size;
  return fail(comp, "fmi2SerializeFMUstate: not provided (canSerializeFMUstate is false)");
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component comp, const fmi2Byte bytes[], size_t size, fmi2FMUstate *state) {
  (void)bytes;
  (void)size;
  (void)state;
  return fail(comp, "fmi2DeSerializeFMUstate: not provided (canSerializeFMUstate is false)");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component comp, const fmi2ValueReference unknowns[], size_t n_unknown,
                                        const fmi2ValueReference knowns[], size_t n_known, const fmi2Real dv_known[],
                                        fmi2Real dv_unknown[]) {
  (void)unknowns;
  (void)n_unknown;
  (void)knowns;
  (void)n_known;
  (void)dv_known;
  (void)dv_unknown;
  return fail(comp, "fmi2GetDirectionalDerivative: not provided (providesDirectionalDerivative is false)");
}
