/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_report.h - the parts of the batch report that batch_run (batch.c)
 * prints in order: the header block (batch_header.c), the collision table
 * and its error bars (batch_table.c), the jumps and the summary
 * (batch_summary.c), the check lines (batch_check.c); and how they write a
 * value and a paragraph (batch_text.c).  Each prints to out, the report's
 * stream (stdout, or stderr when a CSV goes to stdout).
 */
#ifndef HYBOUNCE_CLI_BATCH_REPORT_H
#define HYBOUNCE_CLI_BATCH_REPORT_H

#include <stddef.h>
#include <stdio.h>

#include "hybounce/units.h"

struct hb_arc;
struct hb_collision;
struct hb_error_estimate;
struct hb_scene;
struct hb_sim;
struct hb_sim_stats;

/* A value with its unit, 6 significant digits ("inf", "-" for NaN), into buf; returns buf. */
const char *
batch_fmt(double v, struct hb_unit_dim d, char *buf, size_t n);

/*
 * Prints text word-wrapped to 79 columns, every line starting with indent
 * (the first line too).
 */
void
batch_print_wrapped(FILE *out, const char *indent, const char *text);

/*
 * The header block: the preset (its name as given and its path), the
 * scene sc, and the run settings; with st, the scales of the absolute
 * tolerance at the last contact.  Ends with a blank line.
 */
void
batch_print_header(FILE *out, const char *preset, const char *path,
                   const struct hb_scene *sc, const struct hb_sim_stats *st);

/*
 * The table of s's completed collisions and, below a rule, the contacts in
 * progress (a chain's side by side, by increasing interface); with est
 * (--error), the error bars of each value after it.
 */
void
batch_print_table(FILE *out, const struct hb_sim *s, const struct hb_error_estimate *est);

/* --jumps: the location record of every jump of the arc a. */
void
batch_print_jumps(FILE *out, const struct hb_arc *a);

/*
 * The summary: why the run ended (sig: the signal that stopped it, or 0),
 * the end state, the observables (with est, their error bars), the work
 * done and, for a chain, its bodies.
 */
void
batch_print_summary(FILE *out, const struct hb_sim *s, int sig,
                    const struct hb_error_estimate *est);

/*
 * The check lines: with check (--check), the solution pair and, with est,
 * the error bars; the physics always (a failure said as a warning without
 * check, on stderr too when out is not stderr).  Returns 1 when a check
 * failed that makes the exit status 1 (every failure with check), else 0.
 */
int
batch_print_checks(FILE *out, const struct hb_sim *s, int check,
                   const struct hb_error_estimate *est);

#endif
