/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_output.c - what `hybounce fit` writes: the fitted preset (with the
 * provenance line), the residuals CSV and the JSON report, as one atomic
 * set under the output policy, and the "wrote" lines.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/fit.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "fit_cmd.h"
#include "report.h"
#include "signals.h"

#define PROG "hybounce"

/* "hybounce fit: WHAT WHY; nothing written" on stderr; returns 2. */
static int
bad(const char *what, const char *why)
{
	return cli_refuse(PROG " fit", "%s %s; nothing written", what, why);
}

/* The residuals CSV: a row per data point. */
static void
fill_residuals(FILE *f, const void *ctx)
{
	const struct hb_fit_result *r = ctx;

	fprintf(f, "point,row,observable,measured,simulated,sd,resid,start,trial,index\n");
	for (size_t k = 0; k < r->npoints; k++) {
		const struct hb_fit_point *p = &r->point[k];

		fprintf(f, "%zu,%zu,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%zu,%zu\n", k, p->row,
		    hb_fit_obs_name(p->obs), p->measured, p->simulated, p->sd, p->resid, p->start,
		    p->trial, p->index);
	}
}

/*
 * The fitted scene as a preset (then the provenance line) and the residuals
 * as CSV, as one atomic set (atomic.h): should either fail, neither is
 * written nor changed.
 */
int
fit_write_outputs(const char *out, const struct hb_scene *sc, const char *resid_path,
                  const struct hb_fit_result *r, const struct hb_outputs *pol, int k_out,
                  int k_resid, const char *report_path, void (*fill)(FILE *, const void *),
                  const void *rc, int k_report)
{
	struct hb_atomic_set set;
	size_t len = hb_preset_format(sc, NULL, 0);
	const char *prov = cli_provenance();
	char *buf = malloc(len + 1), m[4400];
	FILE *f;
	int st;

	if (buf == NULL)
	{
		fprintf(stderr, PROG " fit: --out %s: out of memory; nothing written\n", out);
		return 2;
	}
	hb_preset_format(sc, buf, len + 1);
	hb_atomic_begin(&set);
	if ((f = hb_atomic_add(&set, out, m, sizeof m)) == NULL)
		goto fail;
	fwrite(buf, 1, len, f);
	if (prov[0] != '\0')
		fprintf(f, "%s\n", prov);
	if (resid_path != NULL) {
		if ((f = hb_atomic_add(&set, resid_path, m, sizeof m)) == NULL)
			goto fail;
		fill_residuals(f, r);
	}
	if (report_path != NULL) {
		if ((f = hb_atomic_add(&set, report_path, m, sizeof m)) == NULL)
			goto fail;
		fill(f, rc);
	}
	free(buf);
	buf = NULL;
	if ((st = hb_atomic_commit(&set, m, sizeof m)) != HB_OK)
		goto failed;
	cli_print_wrote(out, &pol->out[k_out].target);
	if (resid_path != NULL)
		cli_print_wrote(resid_path, &pol->out[k_resid].target);
	if (report_path != NULL)
		cli_print_wrote(report_path, &pol->out[k_report].target);
	return 0;
fail:
	hb_atomic_abort(&set);
failed:
	free(buf);
	{
		/* "PATH: reason" from the writer: the option that named PATH first */
		size_t rl = resid_path != NULL ? strlen(resid_path) : 0;
		size_t pl = report_path != NULL ? strlen(report_path) : 0;
		int is_resid = resid_path != NULL && strncmp(m, resid_path, rl) == 0 &&
		               m[rl] == ':' && strcmp(resid_path, out) != 0;
		int is_report = !is_resid && report_path != NULL && strncmp(m, report_path, pl) == 0
		                && m[pl] == ':' && strcmp(report_path, out) != 0;

		return bad(is_resid ? "--residuals" : is_report
		           ? "--report" : "--out", m);
	}
}

