/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_find.c - finding presets (see preset.h): the preset folders
 * ($HYBOUNCE_PRESETS, ./presets, the install folder), a name or path
 * resolved to a file, and the list of the presets with their titles.
 */
#include <dirent.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ini.h>

#include "hybounce/preset.h"
#include "hybounce/status.h"

#include "preset_ini.h"

#ifndef HYBOUNCE_DATADIR
#define HYBOUNCE_DATADIR "/usr/local/share/hybounce"
#endif

/*
 * The folders near the running executable (Linux /proc/self/exe):
 * BIN/../presets (build/hybounce in the source tree) and
 * BIN/../share/hybounce/presets (PREFIX/bin/hybounce installed anywhere),
 * those that exist, written into out[0..1].  Returns how many.
 */
static int
exe_dirs(char out[2][1024])
{
	static const char *const rel[] = { "/../presets", "/../share/hybounce/presets" };
	char exe[1024], *slash;
	ssize_t l = readlink("/proc/self/exe", exe, sizeof exe - 1);
	struct stat st;
	int k = 0;

	if (l <= 0)
		return 0;
	exe[l] = '\0';
	slash = strrchr(exe, '/');
	if (slash == NULL)
		return 0;
	*slash = '\0';
	for (size_t i = 0; i < sizeof rel / sizeof rel[0]; i++) {
		if ((size_t)snprintf(out[k], sizeof out[k], "%s%s", exe, rel[i]) >= sizeof out[k])
			continue;
		if (stat(out[k], &st) == 0 && S_ISDIR(st.st_mode))
			k++;
	}
	return k;
}

/*
 * Any number of folders: the entries of $HYBOUNCE_PRESETS are split into a
 * buffer that grows.  The buffer is per thread, so that threads may look
 * presets up at once, and is freed when its thread ends (a pthread key's
 * destructor); it is built again only when HYBOUNCE_PRESETS changes, so a
 * list returned earlier stays valid while the environment does not change.
 */
struct dirs_cache {
	char *store;       /* the entries, split in place */
	char *seen;        /* the HYBOUNCE_PRESETS they came from; NULL: unset */
	const char **dirs; /* NULL-terminated */
};

/* Set once (pthread_once), then only read: the key of every thread's cache. */
static struct {
	pthread_key_t key;
	int ok;
} dirs_tls;
static pthread_once_t dirs_once = PTHREAD_ONCE_INIT;

static void
dirs_cache_free(void *p)
{
	struct dirs_cache *c = p;

	free(c->store);
	free(c->seen);
	free(c->dirs);
	free(c);
}

static void
dirs_key_make(void)
{
	dirs_tls.ok = pthread_key_create(&dirs_tls.key, dirs_cache_free) == 0;
}

const char *const *
hb_preset_dirs(void)
{
	static _Thread_local char datadir[sizeof HYBOUNCE_DATADIR + 16], near[2][1024];
	static _Thread_local const char *fallback[3];
	static const char here[] = "presets";
	const char *env = getenv("HYBOUNCE_PRESETS");
	struct dirs_cache *c = NULL;
	size_t k = 0, count = 5; /* ./presets, the install folder, two beside the program */
	int nnear;

	snprintf(datadir, sizeof datadir, "%s/presets", HYBOUNCE_DATADIR);
	fallback[0] = here;
	fallback[1] = datadir;
	fallback[2] = NULL;
	pthread_once(&dirs_once, dirs_key_make);
	if (!dirs_tls.ok)
		return fallback;
	c = pthread_getspecific(dirs_tls.key);
	if (c == NULL) {
		c = calloc(1, sizeof *c);
		if (c == NULL || pthread_setspecific(dirs_tls.key, c) != 0) {
			free(c);
			return fallback; /* out of memory: the built-in folders only */
		}
	}
	if (c->dirs != NULL &&
	    (env == NULL ? c->seen == NULL : c->seen != NULL && strcmp(env, c->seen) == 0))
		return c->dirs;
	free(c->store);
	free(c->seen);
	free(c->dirs);
	c->store = c->seen = NULL;
	c->dirs = NULL;
	if (env != NULL) {
		for (const char *p = env; *p != '\0'; p++)
			count += *p == ':';
		c->store = strdup(env);
		c->seen = strdup(env);
	}
	c->dirs = malloc((count + 1) * sizeof *c->dirs);
	if (c->dirs == NULL || (env != NULL && (c->store == NULL || c->seen == NULL))) {
		free(c->dirs);
		c->dirs = NULL;
		return fallback; /* out of memory: the built-in folders only */
	}
	for (char *p = c->store; p != NULL && *p != '\0';) {
		char *q = strchr(p, ':');

		if (q != NULL)
			*q = '\0';
		if (*p != '\0') /* an empty entry ("a::b") names no folder */
			c->dirs[k++] = p;
		p = q != NULL ? q + 1 : NULL;
	}
	c->dirs[k++] = here;
	c->dirs[k++] = datadir;
	nnear = exe_dirs(near);
	for (int i = 0; i < nnear; i++)
		c->dirs[k++] = near[i];
	c->dirs[k] = NULL;
	return c->dirs;
}

static int
is_file(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* A path given as the preset itself may also be a pipe: -b <(sed ... x.preset). */
static int
is_file_or_pipe(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && (S_ISREG(st.st_mode) || S_ISFIFO(st.st_mode));
}

/*
 * Why an existing path is not a preset file, in its own words: "is a
 * directory", "is a symbolic link loop", "is a socket" ... (ENOENT only
 * when nothing is there).
 */
static int
not_a_preset(const char *name, char *msg, size_t mn)
{
	struct stat st, lst;
	const char *what = NULL;

	if (lstat(name, &lst) != 0)
		return hb_status_set(msg, mn, HB_EINVAL, "%s: %s", name, strerror(errno));
	if (stat(name, &st) != 0) {
		if (errno == ELOOP)
			return hb_status_set(msg, mn, HB_EINVAL, "%s: a loop of symbolic links (%s); "
			    "expected a preset file", name, strerror(ELOOP));
		if (S_ISLNK(lst.st_mode))
			return hb_status_set(msg, mn, HB_EINVAL, "%s: a symbolic link to nothing (%s); "
			    "expected a preset file", name, strerror(errno));
		return hb_status_set(msg, mn, HB_EINVAL, "%s: %s", name, strerror(errno));
	}
	if (S_ISDIR(st.st_mode))
		what = "a directory";
	else if (S_ISCHR(st.st_mode))
		what = "a character device";
	else if (S_ISBLK(st.st_mode))
		what = "a block device";
	else if (S_ISSOCK(st.st_mode))
		what = "a socket";
	else
		what = "not a regular file";
	return hb_status_set(msg, mn, HB_EINVAL, "%s: is %s; expected a preset file (or a pipe, "
	    "e.g. <(...)) or a preset name", name, what);
}

int
hb_preset_resolve(const char *name, char *out, size_t n, char *msg, size_t mn)
{
	const char *const *dirs;
	char path[1024], where[1024] = "";
	struct stat lst;

	if (name == NULL || name[0] == '\0')
		return hb_status_set(msg, mn, HB_EINVAL, "no preset name given; expected a preset name "
		    "(hybounce --list-presets) or the path of a preset file");
	if (is_file_or_pipe(name)) {
		if (strlen(name) >= n)
			return hb_status_set(msg, mn, HB_EINVAL, "%s: path too long", name);
		snprintf(out, n, "%s", name);
		return HB_OK;
	}
	if (strchr(name, '/') == NULL) {
		dirs = hb_preset_dirs();
		for (int i = 0; dirs[i] != NULL; i++) {
			for (int ext = 0; ext < 2; ext++) {
				snprintf(path, sizeof path, "%s/%s%s", dirs[i], name,
				    ext ? ".preset" : "");
				if (is_file(path)) {
					if (strlen(path) >= n)
						return hb_status_set(msg, mn, HB_EINVAL, "%s: path too long",
						    path);
					snprintf(out, n, "%s", path);
					return HB_OK;
				}
			}
			size_t l = strlen(where);
			snprintf(where + l, sizeof where - l, "%s%s", i ? ", " : "", dirs[i]);
		}
		if (lstat(name, &lst) == 0) /* something is there: say what */
			return not_a_preset(name, msg, mn);
		return hb_status_set(msg, mn, HB_EINVAL,
		    "no preset '%s': not a file, and neither %s nor %s.preset is in %s", name, name,
		    name, where);
	}
	return not_a_preset(name, msg, mn);
}

struct title_ctx {
	char title[96];
	char description[256];
};

static int
title_handler(void *user, const char *section, const char *name, const char *value)
{
	struct title_ctx *t = user;

	if (strcmp(section, "scene") != 0)
		return 1;
	if (strcmp(name, "name") == 0)
		snprintf(t->title, sizeof t->title, "%s", value);
	else if (strcmp(name, "description") == 0)
		snprintf(t->description, sizeof t->description, "%s", value);
	return 1;
}

static int
info_cmp(const void *a, const void *b)
{
	return strcmp(((const struct hb_preset_info *)a)->name, ((const struct hb_preset_info *)b)->name);
}

int
hb_preset_list(struct hb_preset_info **out)
{
	const char *const *dirs = hb_preset_dirs();
	struct hb_preset_info *v = NULL;
	int cnt = 0, cap = 0;

	*out = NULL;
	for (int i = 0; dirs[i] != NULL; i++) {
		DIR *d = opendir(dirs[i]);
		struct dirent *de;
		if (d == NULL)
			continue;
		while ((de = readdir(d)) != NULL) {
			size_t l = strlen(de->d_name);
			struct hb_preset_info pi;
			struct title_ctx t = { "", "" };
			int dup = 0;
			if (l <= 7 || strcmp(de->d_name + l - 7, ".preset") != 0 || l - 7 >= sizeof pi.name)
				continue;
			memset(&pi, 0, sizeof pi);
			memcpy(pi.name, de->d_name, l - 7);
			for (int k = 0; k < cnt; k++)
				if (strcmp(v[k].name, pi.name) == 0)
					dup = 1;
			if (dup)
				continue;
			if ((size_t)snprintf(pi.path, sizeof pi.path, "%s/%s", dirs[i], de->d_name) >=
			    sizeof pi.path || !is_file(pi.path))
				continue;
			struct preset_ini_saved sv;

			preset_ini_begin(&sv);
			ini_parse(pi.path, title_handler, &t);
			preset_ini_end(&sv);
			snprintf(pi.title, sizeof pi.title, "%s", t.title);
			snprintf(pi.description, sizeof pi.description, "%s", t.description);
			if (cnt == cap) {
				int nc = cap ? 2 * cap : 16;
				struct hb_preset_info *nv = realloc(v, (size_t)nc * sizeof *nv);
				if (nv == NULL) {
					closedir(d);
					free(v);
					return -1;
				}
				v = nv;
				cap = nc;
			}
			v[cnt++] = pi;
		}
		closedir(d);
	}
	if (cnt > 1)
		qsort(v, (size_t)cnt, sizeof *v, info_cmp);
	if (cnt == 0) {
		free(v);
		v = malloc(sizeof *v); /* a valid pointer to free even when empty */
		if (v == NULL)
			return -1;
	}
	*out = v;
	return cnt;
}
