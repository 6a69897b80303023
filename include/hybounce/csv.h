/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * csv.h - export of a run: RFC 4180 CSV, one header row, SI units,
 * numbers as %.17g so that they round-trip.
 *
 * Arc columns: t,j,q_c,x,v,x_c,z_c1[,z_c2],F_c,F_er and in the full system
 * x_m,v_m,v_m1,v_m2 (z columns as many as the law has).
 * Collision columns: i,t_e,t_s,t_d,t_f,v_i,e,x_c_max,F_c_max,x_c_r,W,J_Fc,J_Fe,Lambda.
 *
 * Every file goes through the atomic writer (atomic.h): written to a
 * temporary name in its folder and renamed, so a failed export never leaves
 * a half file or clobbers a good one; an existing device or FIFO is written
 * in place; a symbolic link is kept and the file it leads to is written.  The
 * csv_stream_* functions write the same bytes to an open stream (e.g.
 * stdout), where no such promise can be kept.
 */
#ifndef HB_CSV_H
#define HB_CSV_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include <stdio.h>
#include "atomic.h"
#include "sim.h"

int
hb_csv_write_arc(const char *path, const struct hb_sim *s, char *msg, size_t n);

int
hb_csv_write_collisions(const char *path, const struct hb_sim *s, char *msg, size_t n);

/*
 * Write the arc, or the completed collisions, as CSV to the open stream f
 * (borrowed: neither closed nor rewound), byte for byte what the path
 * writers above put in a file, then flush f.  Writing stops at the first
 * row after a write fails, so a reader that went away (EPIPE) does not
 * cost the rest of a long arc.  Returns HB_OK, or HB_EIO with
 * "write error: REASON" in msg and errno set to the failed write's error
 * (EPIPE, ENOSPC, ...) so that the caller can tell a closed pipe from a
 * full disk.  A stream whose error indicator is already set fails too.
 */
int
hb_csv_stream_arc(FILE *f, const struct hb_sim *s, char *msg, size_t n);

int
hb_csv_stream_collisions(FILE *f, const struct hb_sim *s, char *msg, size_t n);

/* As hb_csv_stream_collisions, with err's NAME_err columns (error.h; NULL: none). */
struct hb_error_estimate;
int
hb_csv_stream_collisions_err(FILE *f, const struct hb_sim *s,
                             const struct hb_error_estimate *err, char *msg, size_t n);

/*
 * Writes the arc to trace_path and/or the collisions to coll_path (either
 * may be NULL), and the scene beside the first of them as a preset
 * (PATH with its extension replaced by ".preset"), whose path is written to
 * scene_out (may be NULL).  All or nothing: on error no new file is left.
 */
int
hb_csv_export(const struct hb_sim *s, const char *trace_path, const char *coll_path,
           char *scene_out, size_t sn, char *msg, size_t n);

/* How an export went: what hb_csv_export_files() wrote, and how. */
struct hb_csv_export_report {
	char scene[4096];        /* the .preset written; "" when none */
	int scene_of;            /* 0 beside the trace, 1 beside the collisions, -1 none */
	char id[48];             /* the export's identifier (atomic_set.id) */
	struct hb_atomic_target target[3];  /* trace, collisions, scene: how each went */
};

/*
 * hb_csv_export with the rules of a front end: the trace and/or the
 * collisions (either may be NULL), the scene beside the first of them
 * that is a file (not beside a device or FIFO written in place), with a
 * last comment line naming the export's identifier and each CSV file with
 * its cksum(1) numbers; every file of the export gets that
 * identifier as its modification time, so that a set mixed by a kill
 * between two renames shows.  Refuses (HB_EINVAL, nothing written) to
 * overwrite run_preset (the preset being run; may be NULL) or a shipped
 * preset (a .preset in one of hb_preset_dirs()), to write both CSVs to one
 * file or the scene over a CSV.  *r says which targets were replaced, are
 * links, or were written in place.
 */
int
hb_csv_export_files(const struct hb_sim *s, const char *trace, const char *coll,
                 const char *run_preset, struct hb_csv_export_report *r, char *msg, size_t n);

/*
 * hb_csv_export_files with the scene's file named by the caller (the
 * explorer's BASE.preset beside BASE-trace.csv) instead of derived from
 * the first CSV; scene NULL: derived.  Same rules and checks otherwise.
 */
int
hb_csv_export_files_scene(const struct hb_sim *s, const char *trace, const char *coll,
                       const char *scene, const char *run_preset,
                       struct hb_csv_export_report *r, char *msg, size_t n);

struct hb_outputs;

/* An export with every setting (hb_csv_export_with). */
struct hb_csv_export_opts {
	const char *trace;        /* the arc CSV, or NULL */
	const char *coll;         /* the collisions CSV, or NULL */
	const char *scene;        /* the scene's file; NULL: beside the first CSV file */
	const char *run_preset;   /* the preset being run (never overwritten); may be NULL */
	/* A comment line (outputs.h: hb_outputs_provenance) written into the
	 * scene before the export line: which program and command made it.
	 * NULL: none. */
	const char *provenance;
	/* The command's other inputs and outputs (outputs.h), which the
	 * export's files must not be; NULL: none.  Not changed. */
	const struct hb_outputs *outputs;
	/* Error bars (error.h) for the collisions CSV: a NAME_err column
	 * after the others for each value column; NULL: none. */
	const struct hb_error_estimate *errors;
};

/*
 * hb_csv_export_files_scene with the options above: the same rules, with
 * the command's other inputs and outputs and the provenance line.
 */
int
hb_csv_export_with(const struct hb_sim *s, const struct hb_csv_export_opts *o,
                   struct hb_csv_export_report *r, char *msg, size_t n);

/* Every check of hb_csv_export_with that can be made before the run. */
int
hb_csv_export_check_with(const struct hb_csv_export_opts *o, char *msg, size_t n);

/* Every check of hb_csv_export_files that can be made before the run. */
int
hb_csv_export_check(const char *trace, const char *coll, const char *run_preset,
                 char *msg, size_t n);

HB_END_DECLS

#endif
