/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * atomic.c - sets of files replaced together (see atomic.h).
 *
 * A target is resolved once, when it is added: stat() says what the path
 * leads to.  A regular file at the end of the path (after any links) is
 * replaced by renaming a temporary file over it, in the same folder, so
 * that the link and the folder entry stay what they were.  Anything else
 * that is not a folder is opened and written in place.
 *
 * Commit: every temporary file is flushed, stamped with the set's time and
 * fsync()ed; each replaced file gets a hard link TMP.old; the renames
 * follow; the links are removed.  Should a rename fail, the ones made are
 * undone from those links.  A kill can strike between any two of these
 * steps; what it leaves is a temporary file or a .old link, both named
 * TARGET.hbtmp-PID-..., which hb_atomic_add() removes the next time a set
 * writes beside them once PID is no longer running.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/status.h"

#define TMP_TAG HB_ATOMIC_TMP_TAG

/* The folder of path into dir ("." when it has none). */
static void
dir_of(const char *path, char *dir, size_t n)
{
	const char *slash = strrchr(path, '/');

	if (slash == NULL)
		snprintf(dir, n, ".");
	else if (slash == path)
		snprintf(dir, n, "/");
	else
		snprintf(dir, n, "%.*s", (int)(slash - path), path);
}

/* Follows a dangling chain of links from path to the name it ends at. */
static int
follow_dangling(const char *path, char *out, size_t n, char *msg, size_t mn)
{
	char cur[4096], link[4096], dir[4096];
	struct stat st;

	if (strlen(path) >= sizeof cur)
		return hb_status_set(msg, mn, HB_EIO, "%s: %s", path, strerror(ENAMETOOLONG));
	strcpy(cur, path);
	for (int hop = 0; hop < 40; hop++) {
		ssize_t len;

		if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode)) {
			if (strlen(cur) >= n)
				return hb_status_set(msg, mn, HB_EIO, "%s: %s", path,
				                  strerror(ENAMETOOLONG));
			strcpy(out, cur);
			return HB_OK;
		}
		len = readlink(cur, link, sizeof link - 1);
		if (len < 0)
			return hb_status_set(msg, mn, HB_EIO, "%s: %s", path, strerror(errno));
		link[len] = '\0';
		if (link[0] == '/') {
			strcpy(cur, link);
		} else {
			dir_of(cur, dir, sizeof dir);
			if (strlen(dir) + 1 + strlen(link) >= sizeof link)
				return hb_status_set(msg, mn, HB_EIO, "%s: %s", path,
				                  strerror(ENAMETOOLONG));
			size_t dl = strlen(dir);

			memmove(link + dl + 1, link, strlen(link) + 1);
			memcpy(link, dir, dl);
			link[dl] = '/';
			strcpy(cur, link);
		}
	}
	return hb_status_set(msg, mn, HB_EINVAL, "%s: %s", path, strerror(ELOOP));
}

int
hb_atomic_probe(const char *path, struct hb_atomic_target *t, char *msg, size_t n)
{
	struct stat st, lst;
	char dir[4096];
	int islink = lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode);

	memset(t, 0, sizeof *t);
	t->via_link = islink;
	if (path[0] == '\0')
		return hb_status_set(msg, n, HB_EINVAL, "empty file name");
	if (strlen(path) >= sizeof t->real)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(ENAMETOOLONG));
	if (stat(path, &st) == 0) {
		if (S_ISDIR(st.st_mode))
			return hb_status_set(msg, n, HB_EINVAL, "%s: is a folder; expected a file",
			                  path);
		/* /dev/stdout, /dev/fd/N, /proc/PID/fd/N lead to an open file of
		 * some process: written in place, like the device they stand for. */
		if (!S_ISREG(st.st_mode) || strncmp(path, "/dev/", 5) == 0 ||
		    strncmp(path, "/proc/", 6) == 0) {
			strcpy(t->real, path);
			t->how = HB_ATOMIC_IN_PLACE;
			if (access(path, W_OK) != 0)
				return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
			return HB_OK;
		}
		t->how = HB_ATOMIC_REPLACE;
		if (!islink)
			strcpy(t->real, path);
		else if (realpath(path, t->real) == NULL)
			return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	} else if (errno == ENOENT && islink) {
		int st2 = follow_dangling(path, t->real, sizeof t->real, msg, n);

		if (st2 != HB_OK)
			return st2;
		t->how = HB_ATOMIC_NEW;
	} else if (errno == ENOENT) {
		strcpy(t->real, path);
		t->how = HB_ATOMIC_NEW;
	} else if (errno == ELOOP) {
		return hb_status_set(msg, n, HB_EINVAL, "%s: %s", path, strerror(errno));
	} else {
		return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	}
	dir_of(t->real, dir, sizeof dir);
	if (stat(dir, &st) != 0)
		return hb_status_set(msg, n, HB_EIO, "%s: folder %s: %s", path, dir, strerror(errno));
	if (!S_ISDIR(st.st_mode))
		return hb_status_set(msg, n, HB_EIO, "%s: %s is not a folder", path, dir);
	if (access(dir, W_OK | X_OK) != 0)
		return hb_status_set(msg, n, HB_EIO, "%s: folder %s: %s", path, dir, strerror(errno));
	return HB_OK;
}

void
hb_atomic_begin(struct hb_atomic_set *set)
{
	struct tm tm;
	char when[32];

	memset(set, 0, sizeof *set);
	clock_gettime(CLOCK_REALTIME, &set->stamp);
	gmtime_r(&set->stamp.tv_sec, &tm);
	strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%S", &tm);
	snprintf(set->id, sizeof set->id, "%s.%09ldZ", when, set->stamp.tv_nsec);
}

int
hb_atomic_is_temp(const char *name, const char *target, long *pid)
{
	const char *tag = strstr(name, TMP_TAG), *p;
	char *end;
	long v;

	if (target != NULL) {
		size_t bl = strlen(target);

		if (strncmp(name, target, bl) != 0 || strncmp(name + bl, TMP_TAG, strlen(TMP_TAG)) != 0)
			return 0;
		tag = name + bl;
	}
	if (tag == NULL || tag == name)
		return 0;
	p = tag + strlen(TMP_TAG);
	errno = 0;
	v = strtol(p, &end, 10);
	if (end == p || *end != '-' || v <= 0 || errno != 0)
		return 0;
	if (pid != NULL)
		*pid = v;
	return 1;
}

int
hb_atomic_temp_stale(const char *dir, const char *name)
{
	long pid;

	(void)dir;
	if (!hb_atomic_is_temp(name, NULL, &pid) || pid == (long)getpid())
		return 0;
	return kill((pid_t)pid, 0) != 0 && errno == ESRCH;
}

/*
 * Removes TARGET.hbtmp-PID-* beside real whose PID is not running: what a
 * killed writer left.
 */
static void
clean_stale(const char *real)
{
	char dir[4096], full[8300];
	const char *slash = strrchr(real, '/');
	const char *base = slash != NULL ? slash + 1 : real;
	DIR *d;
	struct dirent *de;

	dir_of(real, dir, sizeof dir);
	d = opendir(dir);
	if (d == NULL)
		return;
	while ((de = readdir(d)) != NULL) {
		if (!hb_atomic_is_temp(de->d_name, base, NULL) ||
		    !hb_atomic_temp_stale(dir, de->d_name))
			continue;
		snprintf(full, sizeof full, "%s/%s", dir, de->d_name);
		unlink(full);
	}
	closedir(d);
}

FILE *
hb_atomic_add(struct hb_atomic_set *set, const char *path, char *msg, size_t n)
{
	struct hb_atomic_file *af;
	struct stat st;
	int fd;

	if (set->n >= HB_ATOMIC_MAX) {
		hb_status_set(msg, n, HB_EINVAL, "%s: too many files in one export", path);
		return NULL;
	}
	af = &set->file[set->n];
	memset(af, 0, sizeof *af);
	af->path = path;
	if (hb_atomic_probe(path, &af->target, msg, n) != HB_OK)
		return NULL;
	if (af->target.how == HB_ATOMIC_IN_PLACE) {
		/* O_APPEND: a regular file behind /dev/stdout keeps what the
		 * process wrote there before (a report). */
		fd = open(af->target.real, O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
		if (fd < 0) {
			hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
			return NULL;
		}
	} else {
		clean_stale(af->target.real);
		char tmp[sizeof af->tmp];

		snprintf(tmp, sizeof tmp, "%s" TMP_TAG "%ld-XXXXXX", af->target.real,
		         (long)getpid());
		memcpy(af->tmp, tmp, sizeof tmp);
		fd = mkstemp(af->tmp);
		if (fd < 0) {
			hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
			return NULL;
		}
		/* The replaced file's permissions, or what creat() would give. */
		if (af->target.how == HB_ATOMIC_REPLACE && stat(af->target.real, &st) == 0) {
			(void)fchmod(fd, st.st_mode & 07777);
		} else {
			mode_t um = umask(0);

			umask(um);
			(void)fchmod(fd, 0666 & ~um);
		}
	}
	af->f = fdopen(fd, "w");
	if (af->f == NULL) {
		int e = errno;

		close(fd);
		if (af->tmp[0])
			unlink(af->tmp);
		hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(e));
		return NULL;
	}
	set->n++;
	return af->f;
}

void
hb_atomic_abort(struct hb_atomic_set *set)
{
	for (int k = 0; k < set->n; k++) {
		struct hb_atomic_file *af = &set->file[k];

		if (af->f != NULL)
			fclose(af->f);
		af->f = NULL;
		if (af->tmp[0])
			unlink(af->tmp);
		af->tmp[0] = '\0';
	}
}

/* Flushes, stamps, syncs and closes one file; 0 or the errno. */
static int
finish(struct hb_atomic_set *set, struct hb_atomic_file *af)
{
	int e = 0, fd = fileno(af->f);

	if (ferror(af->f))
		e = errno != 0 ? errno : EIO;
	if (fflush(af->f) != 0 && e == 0)
		e = errno != 0 ? errno : EIO;
	if (e == 0 && af->tmp[0]) {
		struct timespec ts[2] = { set->stamp, set->stamp };

		(void)futimens(fd, ts);
		if (fsync(fd) != 0)
			e = errno;
	}
	if (fclose(af->f) != 0 && e == 0)
		e = errno != 0 ? errno : EIO;
	af->f = NULL;
	return e;
}

/* fsync()s the folder of path, so that a rename in it is on disk. */
static void
sync_dir(const char *path)
{
	char dir[4096];
	int fd;

	dir_of(path, dir, sizeof dir);
	fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (fd >= 0) {
		(void)fsync(fd);
		close(fd);
	}
}

int
hb_atomic_commit(struct hb_atomic_set *set, char *msg, size_t n)
{
	int k, e = 0, failed = -1, done = 0;

	for (k = 0; k < set->n; k++) {
		int ek = finish(set, &set->file[k]);

		if (ek != 0 && e == 0) {
			e = ek;
			failed = k;
		}
	}
	if (e != 0) {
		hb_atomic_abort(set);
		return hb_status_set(msg, n, HB_EIO, "%s: %s", set->file[failed].path, strerror(e));
	}
	for (k = 0; k < set->n; k++) {
		struct hb_atomic_file *af = &set->file[k];

		if (af->tmp[0] && af->target.how == HB_ATOMIC_REPLACE) {
			size_t tl = strlen(af->tmp);

			memcpy(af->bak, af->tmp, tl);           /* tmp is shorter than bak - 4 */
			memcpy(af->bak + tl, ".old", 5);
			af->has_bak = link(af->target.real, af->bak) == 0;
		}
	}
	for (k = 0; k < set->n; k++) {
		struct hb_atomic_file *af = &set->file[k];

		if (!af->tmp[0])
			continue;
		if (rename(af->tmp, af->target.real) != 0) {
			e = errno;
			failed = k;
			break;
		}
		af->tmp[0] = '\0';
		done = k + 1;
	}
	if (e != 0) {
		/* Undo: the replaced files come back, the new ones go. */
		for (k = 0; k < done; k++) {
			struct hb_atomic_file *af = &set->file[k];

			if (af->has_bak)
				rename(af->bak, af->target.real);
			else if (af->target.how == HB_ATOMIC_NEW)
				unlink(af->target.real);
		}
		hb_atomic_abort(set);
	}
	for (k = 0; k < set->n; k++) {
		struct hb_atomic_file *af = &set->file[k];

		if (af->has_bak)
			unlink(af->bak);
		af->has_bak = 0;
		if (e == 0 && af->target.how != HB_ATOMIC_IN_PLACE)
			sync_dir(af->target.real);
	}
	if (e != 0)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", set->file[failed].path, strerror(e));
	return HB_OK;
}

/* The table of the CRC of cksum(1): polynomial 0x04C11DB7, most significant bit first. */
static void
crc_table(uint32_t t[256])
{
	for (uint32_t i = 0; i < 256; i++) {
		uint32_t c = i << 24;

		for (int b = 0; b < 8; b++)
			c = c & 0x80000000u ? (c << 1) ^ 0x04C11DB7u : c << 1;
		t[i] = c;
	}
}

int
hb_atomic_cksum(struct hb_atomic_set *set, int k, unsigned long *crc, unsigned long long *len)
{
	struct hb_atomic_file *af = &set->file[k];
	unsigned char buf[65536];
	uint32_t t[256], c = 0;
	unsigned long long n = 0;
	ssize_t got;
	int fd;

	if (k < 0 || k >= set->n || af->f == NULL || !af->tmp[0] || fflush(af->f) != 0)
		return HB_EIO;
	fd = open(af->tmp, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return HB_EIO;
	crc_table(t);
	while ((got = read(fd, buf, sizeof buf)) != 0) {
		if (got < 0) {
			if (errno == EINTR)
				continue;
			close(fd);
			return HB_EIO;
		}
		for (ssize_t i = 0; i < got; i++)
			c = (c << 8) ^ t[(c >> 24) ^ buf[i]];
		n += (unsigned long long)got;
	}
	close(fd);
	for (unsigned long long m = n; m != 0; m >>= 8)
		c = (c << 8) ^ t[((c >> 24) ^ m) & 0xFF];
	*crc = (unsigned long)(uint32_t)~c;
	*len = n;
	return HB_OK;
}

int
hb_atomic_write_with(const char *path, void (*fill)(FILE *f, const void *ctx), const void *ctx,
                  char *msg, size_t n)
{
	struct hb_atomic_set set;
	FILE *f;

	hb_atomic_begin(&set);
	f = hb_atomic_add(&set, path, msg, n);
	if (f == NULL)
		return HB_EIO;
	errno = 0;
	fill(f, ctx);   /* a failure shows in ferror() at commit */
	return hb_atomic_commit(&set, msg, n);
}

struct bytes {
	const void *buf;
	size_t len;
};

static void
fill_bytes(FILE *f, const void *ctx)
{
	const struct bytes *b = ctx;

	if (b->len > 0)
		(void)fwrite(b->buf, 1, b->len, f);
}

int
hb_atomic_write_file(const char *path, const void *buf, size_t len, char *msg, size_t n)
{
	const struct bytes b = { buf, len };

	return hb_atomic_write_with(path, fill_bytes, &b, msg, n);
}
