/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * outputs.h - the rules every file a command writes obeys, whatever the
 * front end (batch, sweep, fit, the explorer):
 *
 *  - it is written through the atomic writer (atomic.h): a complete new
 *    version renamed over the old one, a device or FIFO written in place
 *    (never replaced), a symbolic link kept and written through;
 *  - it is never an input of the same command (the data file, the preset
 *    being run: whatever the caller declared with hb_outputs_input);
 *  - it is never a shipped preset (a .preset in one of hb_preset_dirs());
 *  - two outputs of one command are never the same file (by name, by
 *    link or by hard link);
 *  - what happens to it is said: hb_outputs_how() gives the words for the
 *    front end's "wrote PATH" line (replaced, through a link, in place).
 *
 *     struct hb_outputs o;
 *     hb_outputs_init(&o);
 *     hb_outputs_input(&o, data_path, "the data file");
 *     if (hb_outputs_add(&o, out, "--out", msg, sizeof msg) != HB_OK) ... refuse, exit 2
 *     ... write out with hb_atomic_* ..., then say "wrote OUT" + hb_outputs_how()
 *
 * Paths are borrowed: they must outlive the struct.  Nothing here prints
 * or writes a file.
 */
#ifndef HB_OUTPUTS_H
#define HB_OUTPUTS_H

#include <stddef.h>

#include "atomic.h"
#include "export.h"
HB_BEGIN_DECLS

enum { HB_OUTPUTS_MAX = 8 };

struct hb_outputs {
	int nin, nout;
	struct {
		const char *path;
		const char *what;   /* "the data file", "the preset being run" ... */
	} in[HB_OUTPUTS_MAX];
	struct {
		const char *path;
		const char *what;   /* "--out", "--residuals" ... */
		struct hb_atomic_target target;   /* how it will be written */
	} out[HB_OUTPUTS_MAX];
};

void
hb_outputs_init(struct hb_outputs *o);

/*
 * Declares an input of the command (path NULL: ignored).  HB_EINVAL when
 * more than HB_OUTPUTS_MAX are declared.
 */
int
hb_outputs_input(struct hb_outputs *o, const char *path, const char *what);

/*
 * Checks that path may be written as an output of the command, before
 * anything is written, and records it.  Returns HB_OK; HB_EINVAL with a
 * message naming path, `what` and the rule (an input, a shipped preset,
 * another output of the command); HB_EINVAL or HB_EIO with "PATH: reason"
 * and what is accepted (hb_outputs_probe) when it cannot be written (an
 * empty name, a folder, a missing or read-only folder).  The target (how it will be written) is
 * o->out[o->nout - 1].target once accepted.
 */
int
hb_outputs_add(struct hb_outputs *o, const char *path, const char *what, char *msg, size_t n);

/* What an output may be, for a refusal's "accepted: ..." (every front end). */
#define HB_OUTPUTS_ACCEPTED "a file in a writable folder"

/*
 * hb_atomic_probe with the policy's words for a refusal: HB_EINVAL
 * "empty file name; accepted: ..." for "", else the writer's
 * "PATH: reason" followed by "; accepted: " HB_OUTPUTS_ACCEPTED (unless the
 * reason already says what is expected).
 */
int
hb_outputs_probe(const char *path, struct hb_atomic_target *t, char *msg, size_t n);

/* 1 if a and b name one file: the same existing file, or the same new name. */
int
hb_outputs_same_file(const char *a, const char *b);

/* 1 if path is an existing .preset in one of the preset folders. */
int
hb_outputs_is_shipped_preset(const char *path);

/*
 * The words after "wrote PATH" for a target: "" for a new file,
 * " (replaced the existing file)", " (written in place)", " (through the
 * link, to REAL)", " (through the link, to REAL, replacing it)".  Like
 * snprintf.
 */
size_t
hb_outputs_how(const struct hb_atomic_target *t, char *buf, size_t n);

/*
 * The provenance line outputs carry as a preset comment:
 *     "; hybounce VERSION (commit COMMIT): ARGV0 ARG1 ..."
 * each argument quoted so that the line pasted into a POSIX shell (after
 * "; ...: ") runs the same command.  The front end passes the version,
 * commit and command line (the library never looks at its host's argv).
 * No newline at the end.  Like snprintf (truncated output ends in "...").
 */
size_t
hb_outputs_provenance(char *buf, size_t n, const char *version, const char *commit,
                      int argc, const char *const *argv);

HB_END_DECLS

#endif
