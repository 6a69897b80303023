/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * report.c - the provenance line and the "wrote" lines of the command-line
 * front ends (report.h).
 */
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
