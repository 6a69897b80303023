/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * report.c - the provenance line and the "wrote" lines of the command-line
 * front ends (report.h).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "hybounce/outputs.h"
#include "hybounce/version.h"
#include "report.h"

static char *provenance;

void
cli_provenance_init(int argc, char **argv)
{
	size_t len = hb_outputs_provenance(NULL, 0, hb_version(), hb_version_commit(), argc,
	                                   (const char *const *)argv);

	free(provenance);
	provenance = malloc(len + 1);
	if (provenance != NULL)
		hb_outputs_provenance(provenance, len + 1, hb_version(), hb_version_commit(), argc,
		                      (const char *const *)argv);
}

const char *
cli_provenance(void)
{
	return provenance != NULL ? provenance : "";
}

void
cli_print_wrote(const char *path, const struct hb_atomic_target *t)
{
	char how[4200];

	hb_outputs_how(t, how, sizeof how);
	fprintf(stderr, "wrote %s%s\n", path, how);
}

static int
refuse(const char *prog, const char *usage, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));

static int
refuse(const char *prog, const char *usage, const char *fmt, va_list ap)
{
	fprintf(stderr, "%s: ", prog);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	if (usage != NULL)
		fprintf(stderr, "Try '%s --help'.\n", usage);
	return 2;
}

int
cli_refuse(const char *prog, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = refuse(prog, NULL, fmt, ap);
	va_end(ap);
	return rc;
}

int
cli_refuse_usage(const char *prog, const char *usage, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = refuse(prog, usage, fmt, ap);
	va_end(ap);
	return rc;
}
