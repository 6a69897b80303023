/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * gendoc.c - writes the generated parts of the man page and the README
 * from the engine's tables, so that they cannot drift:
 *
 *     hybounce-gendoc [--check] FILE...
 *
 * In each FILE, the lines between a line holding "GENERATED-BEGIN NAME"
 * and the next line holding "GENERATED-END NAME" are replaced by the text
 * of generator NAME:
 *     preset-keys                 the keys of a preset (scene_keys_mdoc)
 *     collision-columns-mdoc      the columns of --collisions (mdoc list)
 *     collision-columns-markdown  the same as a Markdown table
 *     run-observables-mdoc        the run observables, runs.csv's columns
 *                                 (observables.h; mdoc list items)
 *     run-observables-markdown    the same as a Markdown table
 * With --check nothing is written: the exit status is 1, with the file and
 * block named on stderr, when a block differs from its generator's text.
 * `make docs` runs it on man/hybounce.1 and README.md; tests/cli/docs.sh
 * runs it with --check.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "docs.h"

static const struct {
	const char *name;
	size_t (*gen)(char *, size_t);
} gens[] = {
	{ "preset-keys", scene_keys_mdoc },
	{ "collision-columns-mdoc", collision_columns_mdoc },
	{ "collision-columns-markdown", collision_columns_markdown },
	{ "run-observables-mdoc", run_observables_mdoc },
	{ "run-observables-markdown", run_observables_markdown },
};

static char *
slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *buf = NULL;
	long n;

	if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 ||
	    fseek(f, 0, SEEK_SET) != 0 || (buf = malloc((size_t)n + 1)) == NULL ||
	    fread(buf, 1, (size_t)n, f) != (size_t)n) {
		perror(path);
		if (f != NULL)
			fclose(f);
		free(buf);
		return NULL;
	}
	fclose(f);
	buf[n] = '\0';
	*len = (size_t)n;
	return buf;
}

/* The generated text of block name (malloc'd), or NULL if unknown. */
static char *
generate(const char *name, size_t nlen)
{
	for (size_t i = 0; i < sizeof gens / sizeof gens[0]; i++) {
		if (strlen(gens[i].name) != nlen || strncmp(gens[i].name, name, nlen) != 0)
			continue;
		size_t n = gens[i].gen(NULL, 0);
		char *buf = malloc(n + 1);
		if (buf != NULL)
			gens[i].gen(buf, n + 1);
		return buf;
	}
	return NULL;
}

/* Processes one file; returns 0, 1 (out of date under --check) or 2 (error). */
static int
process(const char *path, int check)
{
	size_t len, olen = 0, ocap;
	char *in = slurp(path, &len), *out, *p;
	int stale = 0, blocks = 0;

	if (in == NULL)
		return 2;
	ocap = 2 * len + 65536;
	out = malloc(ocap);
	if (out == NULL)
		return 2;
	p = in;
	while (*p != '\0') {
		char *eol = strchr(p, '\n'), *b = strstr(p, "GENERATED-BEGIN ");
		size_t ll = eol != NULL ? (size_t)(eol - p) + 1 : strlen(p);

		if (b == NULL || b >= p + ll) {
			memcpy(out + olen, p, ll);
			olen += ll;
			p += ll;
			continue;
		}
		/* the begin line, then the block up to the end line */
		const char *name = b + strlen("GENERATED-BEGIN ");
		size_t nlen = strcspn(name, " \t\n");
		char endmark[128], *end, *gen;
		snprintf(endmark, sizeof endmark, "GENERATED-END %.*s", (int)nlen, name);
		memcpy(out + olen, p, ll);
		olen += ll;
		p += ll;
		end = strstr(p, endmark);
		gen = generate(name, nlen);
		if (end == NULL || gen == NULL) {
			fprintf(stderr, "%s: block %.*s: %s\n", path, (int)nlen, name,
			    gen == NULL ? "no such generator" : "no GENERATED-END line");
			free(gen);
			free(in);
			free(out);
			return 2;
		}
		while (end > p && end[-1] != '\n')
			end--; /* the start of the end line */
		if ((size_t)(end - p) != strlen(gen) || strncmp(p, gen, strlen(gen)) != 0) {
			stale = 1;
			fprintf(stderr, "%s: block %.*s is %s\n", path, (int)nlen, name,
			    check ? "out of date (run make docs)" : "rewritten");
		}
		memcpy(out + olen, gen, strlen(gen));
		olen += strlen(gen);
		free(gen);
		p = end;
		blocks++;
	}
	if (blocks == 0)
		fprintf(stderr, "%s: no GENERATED-BEGIN block\n", path);
	if (!check && stale) {
		FILE *f = fopen(path, "wb");
		if (f == NULL || fwrite(out, 1, olen, f) != olen || fclose(f) != 0) {
			perror(path);
			free(in);
			free(out);
			return 2;
		}
	}
	free(in);
	free(out);
	return blocks == 0 ? 2 : check && stale ? 1 : 0;
}

int
main(int argc, char **argv)
{
	int check = 0, worst = 0, i = 1;

	if (argc > 1 && strcmp(argv[1], "--check") == 0) {
		check = 1;
		i++;
	}
	if (i >= argc) {
		fprintf(stderr, "usage: hybounce-gendoc [--check] FILE...\n");
		return 2;
	}
	for (; i < argc; i++) {
		int r = process(argv[i], check);
		if (r > worst)
			worst = r;
	}
	return worst;
}
