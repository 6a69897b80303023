/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * outputs.c - the output policy of every front end (see outputs.h).
 *
 * Two names are one file when stat() gives the same device and inode (an
 * existing file, through links and hard links), or, for a file not there
 * yet, when their canonical names agree: the real path of the folder and
 * the last component.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"

void
hb_outputs_init(struct hb_outputs *o)
{
	memset(o, 0, sizeof *o);
}

int
hb_outputs_input(struct hb_outputs *o, const char *path, const char *what)
{
	if (path == NULL)
		return HB_OK;
	if (o->nin >= HB_OUTPUTS_MAX)
		return HB_EINVAL;
	o->in[o->nin].path = path;
	o->in[o->nin].what = what != NULL ? what : "an input";
	o->nin++;
	return HB_OK;
}

/* The canonical name of path (existing or not) into out; -1 if none. */
static int
canonical(const char *path, char *out, size_t n)
{
	char dir[PATH_MAX], rdir[PATH_MAX];
	const char *slash, *base;

	if (realpath(path, rdir) != NULL) {
		if (strlen(rdir) >= n)
			return -1;
		strcpy(out, rdir);
		return 0;
	}
	slash = strrchr(path, '/');
	base = slash != NULL ? slash + 1 : path;
	if (slash == NULL)
		snprintf(dir, sizeof dir, ".");
	else if (slash == path)
		snprintf(dir, sizeof dir, "/");
	else
		snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
	if (realpath(dir, rdir) == NULL)
		return -1;
	if ((size_t)snprintf(out, n, "%s/%s", strcmp(rdir, "/") == 0 ? "" : rdir, base) >= n)
		return -1;
	return 0;
}

int
hb_outputs_same_file(const char *a, const char *b)
{
	struct stat sa, sb;
	char ca[PATH_MAX], cb[PATH_MAX];

	if (a == NULL || b == NULL)
		return 0;
	if (strcmp(a, b) == 0)
		return 1;
	if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
		return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
	return canonical(a, ca, sizeof ca) == 0 && canonical(b, cb, sizeof cb) == 0 &&
	       strcmp(ca, cb) == 0;
}

int
hb_outputs_is_shipped_preset(const char *path)
{
	char dir[PATH_MAX], rdir[PATH_MAX], rp[PATH_MAX];
	const char *slash;
	size_t l = strlen(path);
	struct stat st;

	if (l < 7 || strcmp(path + l - 7, ".preset") != 0 || stat(path, &st) != 0 ||
	    realpath(path, rp) == NULL)
		return 0;
	slash = strrchr(rp, '/');
	if (slash == NULL)
		return 0;
	snprintf(dir, sizeof dir, "%.*s", (int)(slash - rp), rp);
	for (const char *const *d = hb_preset_dirs(); d != NULL && *d != NULL; d++)
		if (realpath(*d, rdir) != NULL && strcmp(rdir, dir) == 0)
			return 1;
	return 0;
}

int
hb_outputs_probe(const char *path, struct hb_atomic_target *t, char *msg, size_t n)
{
	int st;
	size_t l;

	if (path[0] == '\0')
		return hb_status_set(msg, n, HB_EINVAL, "empty file name; accepted: %s",
		                     HB_OUTPUTS_ACCEPTED);
	if ((st = hb_atomic_probe(path, t, msg, n)) == HB_OK)
		return HB_OK;
	/* "PATH: reason", as the writer says it, then what is accepted */
	l = strlen(msg);
	if (strstr(msg, "expected") == NULL && l < n)
		snprintf(msg + l, n - l, "; accepted: %s", HB_OUTPUTS_ACCEPTED);
	return st;
}

int
hb_outputs_add(struct hb_outputs *o, const char *path, const char *what, char *msg, size_t n)
{
	struct hb_atomic_target t;
	int st;

	if (what == NULL)
		what = "an output";
	if (o->nout >= HB_OUTPUTS_MAX)
		return hb_status_set(msg, n, HB_EINVAL, "%s %s: too many outputs in one command",
		                     what, path);
	if ((st = hb_outputs_probe(path, &t, msg, n)) != HB_OK)
		return st;
	for (int k = 0; k < o->nin; k++)
		if (hb_outputs_same_file(path, o->in[k].path))
			return hb_status_set(msg, n, HB_EINVAL, "%s %s is %s; an output never "
			    "overwrites an input of its command; accepted: another file", what, path,
			    o->in[k].what);
	if (t.how != HB_ATOMIC_IN_PLACE && hb_outputs_is_shipped_preset(path))
		return hb_status_set(msg, n, HB_EINVAL, "%s %s is a shipped preset; an output "
		    "never overwrites it; accepted: a file outside the preset folders (or named "
		    "otherwise)", what, path);
	for (int k = 0; k < o->nout; k++) {
		/* Two devices written in place (/dev/null twice) are no conflict. */
		if (t.how == HB_ATOMIC_IN_PLACE && o->out[k].target.how == HB_ATOMIC_IN_PLACE)
			continue;
		if (hb_outputs_same_file(path, o->out[k].path) ||
		    hb_outputs_same_file(t.real, o->out[k].target.real))
			return hb_status_set(msg, n, HB_EINVAL, "%s %s and %s %s are the same file; "
			    "expected two different files", o->out[k].what, o->out[k].path, what,
			    path);
	}
	o->out[o->nout].path = path;
	o->out[o->nout].what = what;
	o->out[o->nout].target = t;
	o->nout++;
	return HB_OK;
}

size_t
hb_outputs_how(const struct hb_atomic_target *t, char *buf, size_t n)
{
	int r;

	if (t->how == HB_ATOMIC_IN_PLACE)
		r = snprintf(buf, n, " (written in place)");
	else if (t->via_link)
		r = snprintf(buf, n, " (through the link, to %s%s)", t->real,
		             t->how == HB_ATOMIC_REPLACE ? ", replacing it" : "");
	else if (t->how == HB_ATOMIC_REPLACE)
		r = snprintf(buf, n, " (replaced the existing file)");
	else
		r = snprintf(buf, n, "%s", "");
	return r < 0 ? 0 : (size_t)r;
}

/* 1 if s needs no quotes in a POSIX shell. */
static int
plain_word(const char *s)
{
	if (*s == '\0')
		return 0;
	for (; *s != '\0'; s++)
		if (strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
		           "_-+=./:,@%^", *s) == NULL)
			return 0;
	return 1;
}

size_t
hb_outputs_provenance(char *buf, size_t n, const char *version, const char *commit,
                      int argc, const char *const *argv)
{
	char *line = NULL;
	size_t len = 0, out;
	FILE *f = open_memstream(&line, &len);

	if (f == NULL) {
		if (n > 0)
			buf[0] = '\0';
		return 0;
	}
	fprintf(f, "; hybounce %s (commit %s):", version != NULL ? version : "?",
	        commit != NULL && commit[0] ? commit : "unknown");
	for (int i = 0; i < argc && argv != NULL && argv[i] != NULL; i++) {
		const char *a = argv[i];

		fputc(' ', f);
		if (plain_word(a)) {
			fputs(a, f);
			continue;
		}
		/* '...' with each ' as '\'' ; a newline inside quotes stays one
		 * argument for the shell but would end the comment: written \n
		 * through $'...' is not POSIX, so it is replaced by a space. */
		fputc('\'', f);
		for (; *a != '\0'; a++) {
			if (*a == '\'')
				fputs("'\\''", f);
			else if (*a == '\n' || *a == '\r')
				fputc(' ', f);
			else
				fputc(*a, f);
		}
		fputc('\'', f);
	}
	if (fclose(f) != 0 || line == NULL) {
		free(line);
		if (n > 0)
			buf[0] = '\0';
		return 0;
	}
	out = len;
	if (n > 0) {
		if (len < n) {
			memcpy(buf, line, len + 1);
		} else {
			memcpy(buf, line, n - 1);
			buf[n - 1] = '\0';
			if (n > 4)
				memcpy(buf + n - 4, "...", 4);
		}
	}
	free(line);
	return out;
}
