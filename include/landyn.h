/*
 * landyn.h - the C API of LANDYN: a touchdown simulation as a handle that a caller creates from
 * deck text, drives with inputs between steps, advances to the times it chooses, reads and frees.
 * Reference: docs/api.md.
 *
 * Conventions
 *   - Every call returns a status (LANDYN_OK = 0, otherwise one of the codes below) and, where it
 *     takes (msg, msg_len), writes a NUL-terminated message into msg (truncated to msg_len - 1
 *     characters; msg may be NULL when msg_len is 0). Nothing in the library stops, prints or
 *     exits the process.
 *   - Units are SI (m, s, N, N m, kg) unless an output's unit says otherwise; the frames are those of
 *     the result file (docs/output.md): global frame z down, lander frame fixed to the body.
 *   - Thread safety: the library has no global mutable state. Two handles may be used from two
 *     threads at the same time; one handle must not be used from two threads at once. Writing
 *     result files from several threads at once needs an HDF5 built thread-safe.
 *   - Handles: landyn_free(&sim) frees and sets sim to NULL; every call given a NULL handle, or a
 *     pointer that is not a live LANDYN handle (checked by a magic number), returns
 *     LANDYN_ERR_HANDLE. As with any C API, using a copy of a pointer after it was freed is
 *     undefined; the Python package never does.
 */
#ifndef LANDYN_H
#define LANDYN_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- status codes ---------------------------------------------------------------------------- */
#define LANDYN_OK 0           /* success */
#define LANDYN_ERR_INPUT 1    /* invalid deck text or argument (msg names group, variable, value) */
#define LANDYN_ERR_HANDLE 2   /* NULL, freed or foreign handle */
#define LANDYN_ERR_ORDER 3    /* call out of order: time going backwards, past t_end, after a failure */
#define LANDYN_ERR_FAILED 4   /* the simulation failed (diverged); the handle can still write its result */
#define LANDYN_ERR_FILE 5     /* the result file could not be written (msg says why) */
#define LANDYN_ENDED 6        /* not an error: the run ended before the requested time (at rest,
                                 tipped over); the state stays at the end time */

/* ---- outcome codes (output "outcome"; 1 to 4 are the result file's /summary/outcome codes) ------ */
#define LANDYN_OUTCOME_RUNNING 0       /* the run has not ended */
#define LANDYN_OUTCOME_NO_TOUCHDOWN 1  /* ended at t_end without a footpad touching the ground */
#define LANDYN_OUTCOME_AT_REST 2       /* came to rest */
#define LANDYN_OUTCOME_MOVING 3        /* still moving at t_end: inconclusive */
#define LANDYN_OUTCOME_TIPPED_OVER 4   /* tilt passed &simulation tipover_angle */
#define LANDYN_OUTCOME_FAILED 5        /* the simulation failed */

typedef struct landyn_sim landyn_sim;  /* opaque */

/* The library's version, git revision and compiler, one line (static storage). */
const char *landyn_version(void);

/* Creates a simulation at t = 0. deck_text: a deck as a file holds it (NULL or "" = the defaults,
 * the paper's lander in load case LC-1); overrides: deck text applied on top of it (NULL or "" for
 * none). Every input check of the landyn program applies (reader, registry ranges, cross-variable
 * rules, input health); on failure *sim is NULL and msg lists every problem. */
int landyn_create(const char *deck_text, const char *overrides, landyn_sim **sim,
                  char *msg, size_t msg_len);

/* landyn_create with the deck's name (e.g. its file path) for messages and the result file's
 * provenance; NULL or "" gives landyn_create's "(deck text)". */
int landyn_create_named(const char *deck_text, const char *deck_name, const char *overrides,
                        landyn_sim **sim, char *msg, size_t msg_len);

/* Frees the simulation and sets *sim to NULL. LANDYN_ERR_HANDLE if sim or *sim is NULL. */
int landyn_free(landyn_sim **sim);

/* Engine inputs, lander frame, held from now until the next call: force [N] applied at the
 * &engine point and a pure moment [N m] (NULL for either: zeros). They add to the deck's &engine
 * thrust (zero inputs give the deck's run). Non-finite values are LANDYN_ERR_INPUT; after the run
 * ended, LANDYN_ERR_ORDER. The result file records every call (/api/inputs). */
int landyn_set_input(landyn_sim *sim, const double force[3], const double moment[3],
                     char *msg, size_t msg_len);

/* Advances to time t [s] (t_now <= t <= &simulation t_end); the integrator of the deck takes its own
 * steps and ends one exactly at t ('fixed': t must be a whole number of steps dt, else
 * LANDYN_ERR_INPUT). Returns LANDYN_ENDED when the run ended before t (and for any later t after
 * that), LANDYN_ERR_FAILED when it failed. t = t_now does nothing and returns LANDYN_OK. */
int landyn_advance_to(landyn_sim *sim, double t, char *msg, size_t msg_len);

/* The simulation's time [s]. */
int landyn_time(const landyn_sim *sim, double *t);

/* The outputs of this simulation: their number (it depends on the deck's gears and struts), and
 * for 0 <= i < count their name, unit and one-line meaning (each buffer may be NULL with length 0;
 * an index out of range is LANDYN_ERR_INPUT). Table: docs/api.md. */
int landyn_output_count(const landyn_sim *sim, int *count);
int landyn_output_info(const landyn_sim *sim, int i, char *name, size_t name_len,
                       char *unit, size_t unit_len, char *meaning, size_t meaning_len);

/* All outputs at the current time into values[0 .. count-1] (n >= landyn_output_count, else
 * LANDYN_ERR_INPUT): the values the result file would record as a sample now; after the run
 * ended or failed, those of its last sample. */
int landyn_get_outputs(const landyn_sim *sim, double *values, int n, char *msg, size_t msg_len);

/* One output by name. LANDYN_ERR_INPUT for an unknown name (msg suggests the closest). */
int landyn_get_output(const landyn_sim *sim, const char *name, double *value,
                      char *msg, size_t msg_len);

/* Writes the result file (docs/output.md) of what was run so far, with its provenance; the
 * output-file policy of the landyn program (docs/files.md) applies: an existing file that is not
 * an HDF5 file (an input deck) is never overwritten, the file is published whole. A run not yet
 * at its end is written with the end reason "stopped by the caller at t = ... s" and the outcome
 * still_moving (inconclusive); the simulation can go on afterwards. */
int landyn_write_result(landyn_sim *sim, const char *path, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif

#endif /* LANDYN_H */
