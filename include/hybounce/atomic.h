/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * atomic.h - the one way the program writes files: a set of files replaced
 * together, each written to a temporary name beside it, flushed to disk and
 * renamed over its target only when every file of the set is complete.
 *
 * What happens to a target depends on what is there:
 *  - nothing: a new file is created (HB_ATOMIC_NEW);
 *  - a regular file: it is replaced (HB_ATOMIC_REPLACE), and the caller is
 *    told so that it can say it;
 *  - a symbolic link: the link is kept and the file it resolves to is
 *    written (HB_ATOMIC_NEW or HB_ATOMIC_REPLACE there; `via_link` set);
 *  - anything else that can be opened for writing (a device such as
 *    /dev/null, a FIFO, a terminal): it is written in place, never
 *    replaced (HB_ATOMIC_IN_PLACE); no promise of atomicity can be kept there;
 *    so is any existing path under /dev/ or /proc/ (/dev/stdout leads to
 *    whatever standard output is, a regular file too);
 *  - a folder: refused.
 *
 * Every file of a set gets the same modification time, the set's identifier
 * (atomic_set.id is that time in UTC with nanoseconds).  The renames of a
 * set are separate steps, so a process killed between two of them leaves
 * some targets new and some old: each target is always a complete version,
 * and a mixed set shows as different modification times.  Temporary files
 * are named TARGET.hbtmp-PID-XXXXXX; a process killed while writing leaves
 * one, and the next set that writes beside it removes those whose process
 * is gone.
 *
 * Errors come back as HB_EIO (or HB_EINVAL for a folder) with
 * "PATH: reason" in msg.  Not thread-safe for one set; sets are independent.
 */
#ifndef HB_ATOMIC_H
#define HB_ATOMIC_H

#include <stddef.h>
#include <stdio.h>
#include <time.h>

#include "export.h"
HB_BEGIN_DECLS

enum hb_atomic_how {
	HB_ATOMIC_NEW = 0,       /* no file there: created */
	HB_ATOMIC_REPLACE,       /* a regular file there: replaced by rename */
	HB_ATOMIC_IN_PLACE,      /* a device, FIFO, ...: written in place */
};

/* Where and how a path would be written (see hb_atomic_probe). */
struct hb_atomic_target {
	char real[4096];      /* the file written: the path with its links resolved */
	int how;              /* enum hb_atomic_how */
	int via_link;         /* the path named a symbolic link */
};

enum { HB_ATOMIC_MAX = 4 };

/* What a temporary file's name has after its target's: TARGET.hbtmp-PID-... */
#define HB_ATOMIC_TMP_TAG ".hbtmp-"

/*
 * 1 if name (a file name without folder) is a temporary file of the atomic
 * writer for the target named target (also without folder; NULL: any
 * target); *pid gets its writer's process id (may be NULL).
 */
int
hb_atomic_is_temp(const char *name, const char *target, long *pid);

/*
 * 1 if name, a temporary file in folder dir (hb_atomic_is_temp), was left
 * by a process that is gone; such a file is never renamed over its target
 * and may be removed.
 */
int
hb_atomic_temp_stale(const char *dir, const char *name);

struct hb_atomic_file {
	const char *path;     /* as named by the caller (borrowed) */
	struct hb_atomic_target target;
	char tmp[4200];       /* temporary name; "" when written in place */
	char bak[4210];       /* hard link to the replaced file during commit */
	FILE *f;
	int has_bak;
};

struct hb_atomic_set {
	struct hb_atomic_file file[HB_ATOMIC_MAX];
	int n;
	struct timespec stamp;   /* the modification time of every file */
	char id[48];             /* stamp as YYYY-MM-DDTHH:MM:SS.NNNNNNNNNZ */
};

/*
 * Finds out, without writing, how path would be written, and whether it
 * can be: the folder of a new or replaced file must exist and be writable,
 * a file written in place must be writable.  Returns HB_OK, or HB_EINVAL
 * (a folder, a link loop) / HB_EIO with "PATH: reason" in msg.
 */
int
hb_atomic_probe(const char *path, struct hb_atomic_target *t, char *msg, size_t n);

/* Starts an empty set and stamps it with the current time. */
void
hb_atomic_begin(struct hb_atomic_set *set);

/*
 * Adds path to the set and returns a stream to write its new contents to
 * (owned by the set), or NULL with msg set.  Removes stale temporary files
 * beside the target first.  Up to HB_ATOMIC_MAX files per set.
 */
FILE *
hb_atomic_add(struct hb_atomic_set *set, const char *path, char *msg, size_t n);

/*
 * Flushes every file to disk and puts all of them in place.  Should any
 * step fail, no target is changed (renames already made are undone) and
 * every temporary file is removed.  Returns HB_OK or HB_EIO with msg.
 * The set is finished either way (the streams are closed).
 */
int
hb_atomic_commit(struct hb_atomic_set *set, char *msg, size_t n);

/* Gives up the set: closes the streams, removes the temporary files. */
void
hb_atomic_abort(struct hb_atomic_set *set);

/*
 * The POSIX cksum of what file k of the set (in the order added) holds so
 * far, read back from its temporary file: the two numbers cksum(1) prints
 * for the file once committed.  HB_EIO for a file written in place.
 */
int
hb_atomic_cksum(struct hb_atomic_set *set, int k, unsigned long *crc, unsigned long long *len);

/* Writes len bytes to path alone, atomically as above. */
int
hb_atomic_write_file(const char *path, const void *buf, size_t len, char *msg, size_t n);

/*
 * Writes path alone, atomically as above, with what fill(f, ctx) writes to
 * its stream; fill's result is not looked at: a failed write shows in the
 * stream's error flag, which the commit reports.
 */
int
hb_atomic_write_with(const char *path, void (*fill)(FILE *f, const void *ctx), const void *ctx,
                  char *msg, size_t n);

HB_END_DECLS

#endif
