/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_laws.c - `hybounce fit --laws shccl,bwshccl,bwmcl`: which law fits
 * the material.  Each law is fitted to the same data (the preset with
 * scene.law set to it, its own free keys), reported as a single fit is,
 * and the laws are ranked by AIC; the best law's fitted preset, residuals
 * and the report of every law are written, and the exit status is the
 * best law's verdict.
 *
 * Free keys: --free LAW:KEY,... for that law; --free KEY without a prefix
 * for every law that has no LAW: keys; else the law's default set (below).
 * Starts likewise: --set LAW:KEY=VALUE changes that law's scene only.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "fit_cmd.h"
#include "plot_cmd.h"
#include "report.h"
#include "signals.h"

#define PROG "hybounce"
enum { MAX_LAWS = 8 };

/* The free keys of a law when --free names none for it. */
static const struct {
	const char *law, *keys;
} law_defaults[] = {
	{ "shccl",   "law.c" },
	{ "bwshccl", "law.c,law.alpha" },
	{ "bwmcl",   "law.c,law.alpha" },
};

struct law_fit {
	const char *name;
	const char *keys[HB_FIT_MAX_FREE];
	int nkeys;
	int fitted;                 /* 1: a result; 0: why says why not */
	char why[1024];
	struct hb_fit_result r;
	struct hb_fit_stats st;
	struct fit_verdict v;
	struct fit_report_ctx rc;
	struct hb_scene sc;         /* the preset with this law */
};

struct laws_json {
	const struct fit_laws_args *a;
	struct law_fit *lf;
	int n;
	const int *rank;            /* indices of the fitted laws, best first */
	int nrank;
	int status;
};

int
fit_laws_prefix(const char *s, const char **rest)
{
	const char *q;

	for (q = s; (*q >= 'a' && *q <= 'z') || (*q >= 'A' && *q <= 'Z') || (*q >= '0' && *q <= '9')
	     || *q == '_' || *q == '-'; q++)
		;
	if (q == s || *q != ':')
		return 0;
	if (rest != NULL)
		*rest = q + 1;
	return 1;
}

/* 1 when s is "LAW:..." for this law. */
static int
for_law(const char *s, const char *law)
{
	size_t l = strlen(law);

	return fit_laws_prefix(s, NULL) && strncmp(s, law, l) == 0 && s[l] == ':';
}

/* A refusal (report.h): "hybounce fit: ..." */
#define bad(...) cli_refuse(PROG " fit", __VA_ARGS__)

/* "shccl: law.c; bwshccl: law.c,law.alpha; ..." */
static void
defaults_str(char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (size_t i = 0; i < sizeof law_defaults / sizeof law_defaults[0]; i++) {
		snprintf(buf + len, n - len, "%s%s: %s", i ? "; " : "", law_defaults[i].law,
		         law_defaults[i].keys);
		len = strlen(buf);
	}
}

/* The keys of law lf from --free (or its defaults, split into kbuf). */
static int
keys_of(const struct fit_laws_args *a, struct law_fit *lf, char *kbuf, size_t kn)
{
	const char *rest;
	char dflt[256];

	lf->nkeys = 0;
	for (int i = 0; i < a->nkeys; i++)
		if (for_law(a->keys[i], lf->name) && fit_laws_prefix(a->keys[i], &rest)
		    && lf->nkeys < HB_FIT_MAX_FREE)
			lf->keys[lf->nkeys++] = rest;
	for (int i = 0; lf->nkeys == 0 && i < a->nkeys; i++)
		if (!fit_laws_prefix(a->keys[i], NULL))
			for (int j = 0; j < a->nkeys; j++)
				if (!fit_laws_prefix(a->keys[j], NULL))
					lf->keys[lf->nkeys++] = a->keys[j];
	for (size_t i = 0; lf->nkeys == 0 && i < sizeof law_defaults / sizeof law_defaults[0];
	     i++) {
		if (strcmp(law_defaults[i].law, lf->name) != 0)
			continue;
		snprintf(kbuf, kn, "%s", law_defaults[i].keys);
		for (char *save = NULL, *k = strtok_r(kbuf, ",", &save); k != NULL;
		     k = strtok_r(NULL, ",", &save))
			lf->keys[lf->nkeys++] = k;
	}
	if (lf->nkeys > 0) {
		char msg[1024];
		double v;

		/* every key is one of this law's scene: refused now, not after the others' fits */
		for (int i = 0; i < lf->nkeys; i++)
			if (hb_fit_key_get(&lf->sc, lf->keys[i], &v, msg, sizeof msg) != HB_OK)
				return bad("--laws %s: --free %s", lf->name, msg);
		return 0;
	}
	defaults_str(dflt, sizeof dflt);
	return bad("--laws %s: no free keys; accepted: --free %s:KEY[,%s:KEY...], or a law "
	           "with a default set (%s)", lf->name, lf->name, lf->name, dflt);
}

/* Opens the preset with the law (and its --set); 0, or 2 for bad input. */
static int
open_law(const struct fit_laws_args *a, struct law_fit *lf)
{
	const char **sets = calloc((size_t)a->nsets + 2, sizeof *sets);
	char lawset[64], path[1024], msg[4096];
	const char *rest;
	int n = 0, st;

	if (sets == NULL)
		return bad("out of memory");
	snprintf(lawset, sizeof lawset, "scene.law=%s", lf->name);
	sets[n++] = lawset;
	for (int i = 0; i < a->nsets; i++)
		if (!fit_laws_prefix(a->sets[i], NULL))
			sets[n++] = a->sets[i];
	for (int i = 0; i < a->nsets; i++)
		if (for_law(a->sets[i], lf->name) && fit_laws_prefix(a->sets[i], &rest))
			sets[n++] = rest;
	msg[0] = '\0';
	st = hb_preset_open_named(a->preset, sets, n, &lf->sc, path, sizeof path, msg, sizeof msg);
	free(sets);
	if (st != HB_OK)
		return bad("--laws %s: %s", lf->name, msg);
	return 0;
}

/* Fits one law: lf->fitted, or lf->why. */
static void
fit_one(const struct fit_laws_args *a, struct law_fit *lf)
{
	struct hb_fit_options fo = *a->fo;
	struct hb_fit *fit;
	char msg[4096];

	fo.keys = lf->keys;
	fo.nkeys = lf->nkeys;
	fo.progress = NULL;
	msg[0] = '\0';
	if ((fit = hb_fit_new(&lf->sc, a->d, &fo, msg, sizeof msg)) == NULL) {
		snprintf(lf->why, sizeof lf->why, "%.*s", (int)sizeof lf->why - 1, msg);
		return;
	}
	while (cli_signal == 0 && !hb_fit_iterate(fit))
		;
	if (hb_fit_result_get(fit, &lf->r, msg, sizeof msg) != HB_OK) {
		snprintf(lf->why, sizeof lf->why, "%.*s", (int)sizeof lf->why - 1, msg);
		hb_fit_free(fit);
		return;
	}
	hb_fit_free(fit);
	if (cli_signal != 0)
		snprintf(lf->r.why, sizeof lf->r.why, "interrupted by %s (the best point so far)",
		         cli_signal_name(cli_signal));
	hb_fit_stats(&lf->r, 0.05, &lf->st);
	fit_verdict(&lf->r, &lf->st, a->max_rse, &lf->v);
	lf->fitted = 1;
}

static void
laws_json(FILE *f, const void *ctx)
{
	const struct laws_json *j = ctx;

	fprintf(f, "{\n  \"hybounce\": \"%s\",\n  \"ranked_by\": \"AIC\",\n  \"best\": ",
	    HYBOUNCE_VERSION);
	if (j->nrank > 0)
		fprintf(f, "\"%s\"", j->lf[j->rank[0]].name);
	else
		fprintf(f, "null");
	fprintf(f, ",\n  \"exit_status\": %d,\n  \"laws\": [\n", j->status);
	for (int i = 0; i < j->nrank; i++) {
		fit_report_json_object(f, &j->lf[j->rank[i]].rc);
		fprintf(f, "%s\n", i + 1 < j->nrank ? "," : "");
	}
	fprintf(f, "  ],\n  \"not_fitted\": [");
	for (int i = 0, k = 0; i < j->n; i++) {
		if (j->lf[i].fitted)
			continue;
		fprintf(f, "%s{\"law\": \"%s\", \"reason\": \"", k++ ? ", " : "", j->lf[i].name);
		for (const char *s = j->lf[i].why; *s != '\0'; s++)
			if (*s == '"' || *s == '\\')
				fprintf(f, "\\%c", *s);
			else if ((unsigned char)*s < 0x20)
				fprintf(f, "\\u%04x", (unsigned char)*s);
			else
				fputc(*s, f);
		fprintf(f, "\"}");
	}
	fprintf(f, "]\n}\n");
}

int
fit_laws(const struct fit_laws_args *a)
{
	struct law_fit *lf = calloc(MAX_LAWS, sizeof *lf);
	char *list = strdup(a->laws), kbuf[MAX_LAWS][256];
	int n = 0, status = 2, rank[MAX_LAWS], nrank = 0, sig;
	double wsum = 0;

	if (lf == NULL || list == NULL) {
		status = bad("out of memory");
		goto out;
	}
	for (char *save = NULL, *l = strtok_r(list, ", \t", &save); l != NULL;
	     l = strtok_r(NULL, ", \t", &save)) {
		if (n == MAX_LAWS) {
			status = bad("--laws %s: more than %d laws; accepted: at most %d", a->laws,
			             MAX_LAWS, MAX_LAWS);
			goto out;
		}
		for (int i = 0; i < n; i++)
			if (strcmp(lf[i].name, l) == 0) {
				status = bad("--laws %s: %s given twice; accepted: each law once",
				             a->laws, l);
				goto out;
			}
		lf[n++].name = l;
	}
	if (n == 0) {
		status = bad("--laws '%s': no law given; accepted: law names separated by commas, "
		             "e.g. --laws shccl,bwshccl,bwmcl (hybounce --list-laws)", a->laws);
		goto out;
	}
	/* every LAW: prefix names a law of the list */
	for (int pass = 0; pass < 2; pass++) {
		const char *const *v = pass ? a->sets : a->keys;
		int nv = pass ? a->nsets : a->nkeys;

		for (int i = 0; i < nv; i++) {
			int known = 0;

			if (!fit_laws_prefix(v[i], NULL))
				continue;
			for (int k = 0; k < n; k++)
				known |= for_law(v[i], lf[k].name);
			if (!known) {
				status = bad("%s %s: the law before ':' is not one of --laws %s; accepted: "
				             "LAW:%s with LAW one of them", pass ? "--set" : "--free", v[i],
				             a->laws, pass ? "KEY=VALUE" : "KEY");
				goto out;
			}
		}
	}
	for (int i = 0; i < n; i++)
		if (open_law(a, &lf[i]) != 0 || keys_of(a, &lf[i], kbuf[i], sizeof kbuf[i]) != 0)
			goto out;
	cli_signals_watch();
	for (int i = 0; i < n && cli_signal == 0; i++) {
		printf("\nlaw         %s: free ", lf[i].name);
		for (int k = 0; k < lf[i].nkeys; k++)
			printf("%s%s", k ? ", " : "", lf[i].keys[k]);
		printf("\n");
		fflush(stdout);
		if (!a->quiet)
			fprintf(stderr, PROG " fit: fitting %s (%d of %d)\n", lf[i].name, i + 1, n);
		fit_one(a, &lf[i]);
		if (lf[i].fitted) {
			fit_report_print(&lf[i].r, a->d, &lf[i].st, 1);
			for (int k = 0; k < lf[i].v.n; k++)
				printf("not credible: %s\n", lf[i].v.reason[k]);
		} else {
			printf("not fitted: %s\n", lf[i].why);
		}
	}
	sig = cli_signal;
	/* rank by AIC (insertion; a NaN AIC last) */
	for (int i = 0; i < n; i++) {
		int k;

		if (!lf[i].fitted)
			continue;
		for (k = nrank; k > 0 && (isnan(lf[rank[k - 1]].st.aic)
		                          || lf[rank[k - 1]].st.aic > lf[i].st.aic); k--)
			rank[k] = rank[k - 1];
		rank[k] = i;
		nrank++;
	}
	for (int i = 0; i < nrank; i++)
		if (isfinite(lf[rank[i]].st.aic))
			wsum += exp(-(lf[rank[i]].st.aic - lf[rank[0]].st.aic) / 2);
	printf("\nranked by AIC (lower is better; the same data and weights for every law;\n"
	       "weight: Akaike weight, exp(-dAIC/2) normalised over these laws)\n");
	printf("  %-4s %-8s %2s %12s %10s %12s %10s %7s %12s  %s\n", "rank", "law", "P", "cost",
	    "chi2/dof", "AIC", "dAIC", "weight", "BIC", "credible");
	for (int i = 0; i < nrank; i++) {
		const struct law_fit *l = &lf[rank[i]];
		double daic = l->st.aic - lf[rank[0]].st.aic;

		printf("  %-4d %-8s %2d %12.6g %10.4g %12.6g %10.4g %7.3g %12.6g  %s\n", i + 1,
		    l->name, l->st.p, l->r.cost, l->st.chi2_red, l->st.aic, daic,
		    isfinite(daic) && wsum > 0 ? exp(-daic / 2) / wsum : NAN, l->st.bic,
		    l->v.status == 0 ? "yes" : "no");
	}
	for (int i = 0; i < nrank; i++) {
		const struct law_fit *l = &lf[rank[i]];

		printf("  %d %-8s", i + 1, l->name);
		for (int k = 0; k < l->r.np; k++)
			printf("%s %s = %.6g +- %.3g", k ? "," : "", l->r.key[k], l->r.value[k],
			       l->r.se[k]);
		printf("\n");
	}
	for (int i = 0; i < n; i++)
		if (!lf[i].fitted && lf[i].why[0] != '\0')
			printf("  - %-8s not fitted: %s\n", lf[i].name, lf[i].why);
	fflush(stdout);
	if (nrank == 0) {
		fprintf(stderr, PROG " fit: no law could be fitted; nothing written\n");
		status = sig != 0 ? cli_signal_status(sig) : 1;
		goto out;
	}
	{
		struct law_fit *b = &lf[rank[0]];
		struct laws_json j;
		char desc[sizeof b->r.fitted.description];
		size_t len;

		for (int i = 0; i < nrank; i++) {
			struct law_fit *l = &lf[rank[i]];

			l->rc = (struct fit_report_ctx){ .preset = a->preset, .data = a->data,
			    .law = l->name, .d = a->d, .r = &l->r, .st = &l->st, .v = &l->v,
			    .status = sig != 0 ? cli_signal_status(sig) : l->v.status, .sig = sig };
		}
		status = sig != 0 ? cli_signal_status(sig) : b->v.status;
		j = (struct laws_json){ .a = a, .lf = lf, .n = n, .rank = rank, .nrank = nrank,
		                        .status = status };
		snprintf(desc, sizeof desc, "Fitted to %.80s, %s ranked first by AIC of %d laws:",
		         a->data, b->name, n);
		for (int k = 0; k < b->r.np; k++) {
			len = strlen(desc);
			snprintf(desc + len, sizeof desc - len, " %s = %.9g", b->r.key[k], b->r.value[k]);
		}
		len = strlen(desc);
		snprintf(desc + len, sizeof desc - len, " (%.60s).", sig != 0
		         ? "interrupted: the best point so far" : hb_fit_reason_str(b->r.reason));
		memcpy(b->r.fitted.description, desc, sizeof desc);
		printf("\nbest        %s\n", b->name);
		fflush(stdout);
		if (fit_write_outputs(a->out, &b->r.fitted, a->resid_path, &b->r, a->pol, a->k_out,
		                      a->k_resid, a->report_path, laws_json, &j, a->k_report) != 0) {
			status = 2;
			goto out;
		}
		char pm[4200];

		if (a->plot != NULL && plot_write_fit(a->plot, a->pol, &b->r, a->d, pm, sizeof pm)
		    != 0) {
			fprintf(stderr, PROG " fit: %s\n", pm);
			status = 2;
			goto out;
		}
		if (sig != 0)
			fprintf(stderr, PROG " fit: interrupted by %s: the laws fitted so far are "
			        "reported, the best written\n", cli_signal_name(sig));
		else
			for (int k = 0; k < b->v.n; k++)
				fprintf(stderr, PROG " fit: not credible (the best law, %s): %s\n", b->name,
				        b->v.reason[k]);
	}
out:
	for (int i = 0; lf != NULL && i < n; i++)
		hb_fit_result_free(&lf[i].r);
	free(lf);
	free(list);
	return status;
}
