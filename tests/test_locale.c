/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_locale.c - the library reads and writes numbers in the C numeric
 * locale whatever the host set: a host that calls setlocale(LC_ALL,
 * "de_DE.UTF-8") (process-wide) or uselocale() on one of its threads, in a
 * decimal-comma locale (de_DE, fr_FR) or the Turkish one (where 'I' and
 * 'i' are not one letter under the locale's case fold), gets from units,
 * scene_set/scene_get, messages, presets, the CSV writers (trace,
 * collisions, a sweep curve) and the fit data reader exactly the bytes
 * and values it gets under C, and its locale is left as it set it.
 * The locales come from `make deps`: a missing one fails, never skips.
 */
#define _GNU_SOURCE     /* open_memstream, fmemopen */
#include <locale.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <criterion/criterion.h>

#include "hybounce/csv.h"
#include "hybounce/fit.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "hybounce/units.h"
#include "testutil.h"

static const char *const locales[] = { "de_DE.UTF-8", "fr_FR.UTF-8", "tr_TR.UTF-8" };
#define NLOCALES (sizeof locales / sizeof locales[0])

/* Everything the library writes or reads back in one pass, as text. */
struct capture {
	char *text;   /* malloc'd, sections separated by "== NAME" lines */
	size_t len;
};

static void
put(FILE *f, const char *section, const char *s)
{
	fprintf(f, "== %s\n%s\n", section, s);
}

/* A double the library read, as its bits in hexadecimal (no locale in it). */
static void
put_num(FILE *f, const char *section, double v)
{
	char b[32];
	unsigned long long u;

	memcpy(&u, &v, sizeof u);
	snprintf(b, sizeof b, "%016llx", u);
	put(f, section, b);
}

static char *
mem_stream_text(FILE *m, char **buf)
{
	fclose(m);
	return *buf;
}

static void
capture_all(struct capture *cap)
{
	char buf[4096], msg[512] = "", path[1024];
	FILE *f = open_memstream(&cap->text, &cap->len);
	struct hb_scene sc, back;
	struct hb_scene_keyinfo ki;
	struct hb_scene_error err;
	double v;

	cr_assert_not_null(f);

	/* units: every formatter, and the parser */
	put(f, "format", hb_units_format(0.3e-3, hb_unit_length, 6, buf, sizeof buf));
	put(f, "format N", hb_units_format(4.4e3, hb_unit_force, 4, buf, sizeof buf));
	put(f, "format none", hb_units_format(0.35, hb_unit_none, 6, buf, sizeof buf));
	put(f, "format exact", hb_units_format_exact(0.1, hb_unit_time, buf, sizeof buf));
	hb_units_axis(2.5e-5, "m", buf, sizeof buf);
	put(f, "axis", buf);
	cr_assert_eq(hb_units_parse("0.3 mm", hb_unit_length, &v, msg, sizeof msg), HB_OK, "%s", msg);
	put_num(f, "parse 0.3 mm", v);
	cr_assert_eq(hb_units_parse("1.5e1 ms", hb_unit_time, &v, msg, sizeof msg), HB_OK, "%s", msg);
	put_num(f, "parse 1.5e1 ms", v);
	cr_assert_eq(hb_units_parse("2.5 g/cm^3", hb_unit_density, &v, msg, sizeof msg), HB_OK,
	             "%s", msg);
	put_num(f, "parse g/cm^3", v);
	/* a decimal comma stays refused, as under C */
	cr_assert_neq(hb_units_parse("0,3", hb_unit_none, &v, msg, sizeof msg), HB_OK,
	              "'0,3' accepted as %g", v);
	put(f, "refused 0,3", msg);

	/* a scene: --set with decimals and units, a choice in capitals */
	snprintf(path, sizeof path, "%s/steel-on-bitumen.preset", preset_dir());
	cr_assert_eq(hb_preset_load(path, &sc, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "law.c", "4.4 kN s/m", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "body1.nu", "0.3", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "initial.x0", "12.5 mm", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "scene.extension", "ADHESIVE", msg, sizeof msg), HB_OK,
	             "a choice in capitals (ASCII fold): %s", msg);
	back = sc;
	cr_assert_eq(hb_scene_set(&back, "scene.law", "LINEAR", msg, sizeof msg), HB_OK,
	             "a law in capitals (ASCII fold): %s", msg);
	cr_assert_eq(hb_scene_get(&sc, "law.c", &ki, &err), HB_OK);
	put(f, "get value", ki.value);
	put(f, "get edit", ki.edit);
	put(f, "get range", ki.range);
	put_num(f, "get number", ki.number);
	cr_assert_eq(hb_scene_get(&sc, "body1.nu", &ki, &err), HB_OK);
	put(f, "get nu", ki.edit);
	/* a message with numbers in it */
	cr_assert_neq(hb_scene_set(&sc, "body1.nu", "0.75", msg, sizeof msg), HB_OK);
	put(f, "nu out of range", msg);

	/* the preset: formatted, and read back to the same scene */
	cr_assert(hb_preset_format(&sc, buf, sizeof buf) < sizeof buf);
	put(f, "preset", buf);
	cr_assert_eq(hb_preset_load_string(buf, "formatted", &back, msg, sizeof msg), HB_OK,
	             "the formatted preset reads back: %s", msg);
	cr_assert_eq(hb_scene_get(&back, "body1.nu", &ki, &err), HB_OK);
	cr_assert_eq(ki.number, 0.3, "nu read back as %.17g", ki.number);
	cr_assert_eq(hb_scene_get(&back, "law.c", &ki, &err), HB_OK);
	cr_assert_eq(ki.number, 4400.0, "law.c read back as %.17g", ki.number);

	/* the CSV writers: trace and collisions of a run */
	{
		struct hb_sim *s = hb_sim_new(&sc, msg, sizeof msg);
		char *t = NULL;
		size_t tn = 0;
		FILE *m;

		cr_assert_not_null(s, "%s", msg);
		cr_assert_eq(hb_sim_run(s), HB_OK, "%s", hb_sim_errmsg(s));
		put(f, "end", hb_sim_end_str(s));
		m = open_memstream(&t, &tn);
		cr_assert_eq(hb_csv_stream_arc(m, s, msg, sizeof msg), HB_OK, "%s", msg);
		put(f, "trace", mem_stream_text(m, &t));
		free(t);
		t = NULL;
		m = open_memstream(&t, &tn);
		cr_assert_eq(hb_csv_stream_collisions(m, s, msg, sizeof msg), HB_OK, "%s", msg);
		put(f, "collisions", mem_stream_text(m, &t));
		free(t);
		hb_sim_free(s);
	}

	/* a sweep curve's CSV (threads of the library's own) */
	{
		struct hb_sweep_curve *c;
		char csv[64];
		long np, k;
		int fd;

		snprintf(path, sizeof path, "%s/hertz-elastic.preset", preset_dir());
		cr_assert_eq(hb_preset_load(path, &sc, msg, sizeof msg), HB_OK, "%s", msg);
		c = hb_sweep_curve_start(&sc, "initial.v0", "-0.5 m/s:-1.5 m/s:3", HB_CURVE_E, 0, 2,
		                         msg, sizeof msg);
		cr_assert_not_null(c, "%s", msg);
		np = hb_sweep_curve_npoints(c);
		cr_assert_eq(np, 3);
		do {
			double x[3], y[3];
			int st[3];

			k = hb_sweep_curve_poll(c, x, y, st, 3);
			if (k < np)
				usleep(1000);
		} while (k < np);
		snprintf(csv, sizeof csv, "/tmp/hb-locale-XXXXXX");
		fd = mkstemp(csv);
		cr_assert(fd >= 0);
		close(fd);
		cr_assert_eq(hb_sweep_curve_write_csv(c, csv, msg, sizeof msg), HB_OK, "%s", msg);
		hb_sweep_curve_free(c);
		{
			char *t = slurp(csv);

			put(f, "curve", t);
			free(t);
		}
		unlink(csv);
	}

	/* fit data: decimals read as under C */
	{
		static const char data[] = "t_e,sd_t_e\n0.5,0.001\n1.25,0.0015\n1.875,2.5e-3\n";
		struct hb_fit_data d;
		FILE *m = fmemopen((void *)data, sizeof data - 1, "r");

		cr_assert_not_null(m);
		cr_assert_eq(hb_fit_data_read(m, "data.csv", &d, msg, sizeof msg), HB_OK, "%s", msg);
		fclose(m);
		cr_assert_eq(d.n, 3);
		cr_assert_eq(d.col[HB_FIT_OBS_TE][1], 1.25, "t_e read as %.17g", d.col[HB_FIT_OBS_TE][1]);
		cr_assert_eq(d.sd[HB_FIT_OBS_TE][2], 2.5e-3);
		for (size_t i = 0; i < d.n; i++)
			put_num(f, "fit t_e", d.col[HB_FIT_OBS_TE][i]);
		hb_fit_data_free(&d);
	}
	fclose(f);
}

/* The C reference, made in this process before any locale is set. */
static struct capture reference(void)
{
	struct capture c;

	cr_assert_str_eq(setlocale(LC_ALL, NULL), "C");
	capture_all(&c);
	cr_assert(strstr(c.text, "0.3") != NULL);
	return c;
}

static void
same_as(const struct capture *ref, const struct capture *got, const char *where)
{
	if (ref->len == got->len && memcmp(ref->text, got->text, ref->len) == 0)
		return;
	/* name the first section that differs */
	{
		size_t i = 0;
		size_t sec = 0;

		while (i < ref->len && i < got->len && ref->text[i] == got->text[i]) {
			if (ref->text[i] == '=' && (i == 0 || ref->text[i - 1] == '\n'))
				sec = i;
			i++;
		}
		cr_assert_fail("%s: the library's output differs from C's at byte %zu, in\n%.200s\n"
		               "got\n%.200s", where, i, ref->text + sec, got->text + sec);
	}
}

/* The locale really gives a decimal comma (else the test would prove nothing). */
static void
check_comma(const char *loc)
{
	char b[16];

	snprintf(b, sizeof b, "%.1f", 0.5);
	cr_assert_str_eq(b, "0,5", "%s does not give a decimal comma (\"%s\")", loc, b);
}

Test(locale, setlocale_process_wide)
{
	struct capture ref = reference();

	for (size_t i = 0; i < NLOCALES; i++) {
		struct capture got;

		cr_assert_not_null(setlocale(LC_ALL, locales[i]),
		                   "locale %s is not installed: run make deps", locales[i]);
		check_comma(locales[i]);
		capture_all(&got);
		same_as(&ref, &got, locales[i]);
		/* the host's locale is left as it set it */
		cr_assert_str_eq(setlocale(LC_NUMERIC, NULL), locales[i]);
		check_comma(locales[i]);
		free(got.text);
		setlocale(LC_ALL, "C");
	}
	free(ref.text);
}

Test(locale, lc_numeric_alone)
{
	struct capture ref = reference();

	for (size_t i = 0; i < NLOCALES; i++) {
		struct capture got;

		cr_assert_not_null(setlocale(LC_NUMERIC, locales[i]),
		                   "locale %s is not installed: run make deps", locales[i]);
		check_comma(locales[i]);
		capture_all(&got);
		same_as(&ref, &got, locales[i]);
		free(got.text);
		setlocale(LC_NUMERIC, "C");
	}
	free(ref.text);
}

struct host_thread {
	const char *loc;
	struct capture got;
	int ok_before, ok_after;
	char err[256];
};

static void *
host_thread_main(void *p)
{
	struct host_thread *h = p;
	locale_t l = newlocale(LC_ALL_MASK, h->loc, (locale_t)0);
	char b[16];

	if (l == (locale_t)0) {
		snprintf(h->err, sizeof h->err, "locale %s is not installed: run make deps", h->loc);
		return NULL;
	}
	uselocale(l);
	snprintf(b, sizeof b, "%.1f", 0.5);
	h->ok_before = strcmp(b, "0,5") == 0;
	capture_all(&h->got);
	/* the thread's own locale is still in force afterwards */
	snprintf(b, sizeof b, "%.1f", 0.5);
	h->ok_after = strcmp(b, "0,5") == 0 && uselocale((locale_t)0) == l;
	uselocale(LC_GLOBAL_LOCALE);
	freelocale(l);
	return NULL;
}

Test(locale, uselocale_in_host_threads)
{
	struct capture ref = reference();
	struct host_thread h[NLOCALES];
	pthread_t t[NLOCALES];

	memset(h, 0, sizeof h);
	for (size_t i = 0; i < NLOCALES; i++) {
		h[i].loc = locales[i];
		cr_assert_eq(pthread_create(&t[i], NULL, host_thread_main, &h[i]), 0);
	}
	for (size_t i = 0; i < NLOCALES; i++)
		cr_assert_eq(pthread_join(t[i], NULL), 0);
	for (size_t i = 0; i < NLOCALES; i++) {
		cr_assert_eq(h[i].err[0], '\0', "%s", h[i].err);
		cr_assert(h[i].ok_before, "%s: the thread's locale gives no decimal comma", h[i].loc);
		cr_assert(h[i].ok_after, "%s: the library changed the thread's locale", h[i].loc);
		same_as(&ref, &h[i].got, h[i].loc);
		free(h[i].got.text);
	}
	/* the process's locale was never touched */
	cr_assert_str_eq(setlocale(LC_ALL, NULL), "C");
	free(ref.text);
}
