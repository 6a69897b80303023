/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_axis.c - a sweep's axes: "KEY=FROM:TO:N[:log]" or "KEY=V1,V2,..."
 * (hb_sweep_vary, or the "; sweep: --vary" lines of a spec file) into the
 * canonical values of an axis (see sweep.c for what canonical means), and
 * whether a point's scene can be made by storing its values (fast_ready).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "cnum.h"
#include "scene_keys.h"
#include "sweep_impl.h"

/* See sweep_impl.h. */
const char *
sweep_axis_text(const struct axis *a, long i, char *buf, size_t n)
{
	if (a->val != NULL)
		return a->val[i];
	if (n < CNUM_G17_MAX)
		cnum_snprintf(buf, n, "%.17g", sweep_axis_num(a, i));
	else
		cnum_g17(buf, sweep_axis_num(a, i));
	return buf;
}

/* See sweep_impl.h. */
void
sweep_axis_free(struct axis *a)
{
	for (long i = 0; a->val != NULL && i < a->n; i++)
		free(a->val[i]);
	free(a->val);
	free(a->num);
	memset(a, 0, sizeof *a);
}

/*
 * The value of key in sc as text that hb_scene_set() reads back to the same
 * value: a number in SI as %.17g, or the word of a choice.  Returns 0, or
 * -1 for a key that has no such value (unknown, free text, derived).
 */
static int
key_value(const struct hb_scene *sc, const char *key, char *buf, size_t n)
{
	const char *word = NULL;
	double v = NAN;

	/* hb_scene_get's value without its display texts (which cost ~100k
	 * instructions a number: hb_units_format_exact tries up to 12 widths). */
	switch (scene_key_value(sc, key, &v, &word)) {
	case HB_SCENE_KEY_NUMBER:
	case HB_SCENE_KEY_WHOLE:
		if (isnan(v))
			return -1;
		cnum_snprintf(buf, n, "%.17g", v);
		return 0;
	case HB_SCENE_KEY_CHOICE:
		if (strlen(word) >= n)
			return -1;
		snprintf(buf, n, "%s", word);
		return 0;
	default:
		return -1;
	}
}

/* The scene on which axis k's values are checked: base + earlier axes' first values. */
void
sweep_check_scene(const struct hb_sweep *sw, int k, struct hb_scene *sc)
{
	char m[256], t[64];

	*sc = sw->base;
	for (int i = 0; i < k; i++)
		(void)hb_scene_set(sc, sw->ax[i].key, sweep_axis_text(&sw->ax[i], 0, t, sizeof t), m,
		                   sizeof m);
}

/* Applies text to key on a copy of sc and reads the canonical value back. */
static int
canonical(const struct hb_scene *sc, const char *key, const char *text, char *out, size_t on,
          char *msg, size_t n)
{
	struct hb_scene t = *sc;
	char m[512];

	m[0] = '\0';
	if (hb_scene_set(&t, key, text, m, sizeof m) != HB_OK)
		return hb_status_set(msg, n, HB_EINVAL, "--vary %s: value '%s': %s", key, text,
		                  m[0] ? m : "rejected");
	if (key_value(&t, key, out, on) != 0)
		return hb_status_set(msg, n, HB_EINVAL, "--vary %s: this key cannot be varied "
		                  "(it is not a typed value of the scene)", key);
	return HB_OK;
}

static char *
trimmed(const char *a, const char *b)
{
	char *s;

	while (a < b && (*a == ' ' || *a == '\t'))
		a++;
	while (b > a && (b[-1] == ' ' || b[-1] == '\t'))
		b--;
	s = malloc((size_t)(b - a) + 1);
	if (s != NULL) {
		memcpy(s, a, (size_t)(b - a));
		s[b - a] = '\0';
	}
	return s;
}

static int
parse_count(const char *t, long *out)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(t, &end, 10);
	if (end == t || *end != '\0' || errno != 0 || v < 1 || v > SWEEP_MAX_POINTS)
		return -1;
	*out = v;
	return 0;
}

#define RANGE_HELP "expected KEY=FROM:TO:N, KEY=FROM:TO:N:log or KEY=V1,V2,... " \
	"(e.g. --vary law.c=1e8:1e10:50:log, --vary initial.x0='10 um,40 um')"

/* Value i of FROM:TO:N (lg: log): the ends themselves, the others from
 * the formula; not inlined, so that every caller gets the same double. */
__attribute__((noinline)) double
sweep_ramp_value(double from, double to, long n, int lg, long i)
{
	double f = n > 1 ? (double)i / (double)(n - 1) : 0;

	if (i == 0)
		return from;
	if (i == n - 1)
		return to;
	if (lg)
		return copysign(exp(log(fabs(from)) + (log(fabs(to)) - log(fabs(from))) * f), from);
	return from + (to - from) * f;
}

/*
 * A range FROM:TO:N[:log] into a->val; others: the points of the other
 * axes, so that a sweep over the limit is refused before a value is made.
 */
int
sweep_parse_range(struct axis *a, const struct hb_scene *sc, const struct hb_sweep *sw,
            double others, char *msg, size_t n)
{
	char *part[5] = { 0 }, num[64];
	const char *p = a->spec, *c;
	int np = 0, rc = HB_OK, lg = 0, plain = 0;
	double from, to;
	char *end;

	while (np < 5) {
		c = strchr(p, ':');
		part[np++] = trimmed(p, c ? c : p + strlen(p));
		if (part[np - 1] == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		if (c == NULL)
			break;
		p = c + 1;
	}
	if (np < 3 || np > 4 || (np == 4 && strcmp(part[3], "log") != 0 &&
	    strcmp(part[3], "lin") != 0)) {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: " RANGE_HELP, a->key, a->spec);
		goto out;
	}
	lg = np == 4 && strcmp(part[3], "log") == 0;
	if (parse_count(part[2], &a->n) != 0) {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: N '%s' is not a count; "
		                "accepted: an integer from 1 to %ld", a->key, a->spec, part[2],
		                SWEEP_MAX_POINTS);
		goto out;
	}
	if (a->n > sw->max_points) {
		/* Refused before a value is made: 10^9 would take minutes and gigabytes. */
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: %ld points, more than the "
		                "limit of %ld points; accepted: at most %ld points%s%s", a->key,
		                a->spec, a->n, sw->max_points, sw->max_points,
		                sw->more[0] ? "; " : "", sw->more);
		goto out;
	}
	if ((double)a->n * others > (double)sw->max_points) {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s: the sweep would have %.0f "
		                   "points, more than the limit of %ld points; accepted: at most "
		                   "%ld points in all%s%s", a->key, (double)a->n * others,
		                   sw->max_points, sw->max_points, sw->more[0] ? "; " : "", sw->more);
		goto out;
	}
	if ((rc = canonical(sc, a->key, part[0], num, sizeof num, msg, n)) != HB_OK)
		goto out;
	from = cnum_strtod(num, &end);
	if (*end != '\0') {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: a range needs a numeric key; "
		                "accepted for %s: a list V1,V2,...", a->key, a->spec, a->key);
		goto out;
	}
	if ((rc = canonical(sc, a->key, part[1], num, sizeof num, msg, n)) != HB_OK)
		goto out;
	to = cnum_strtod(num, &end);
	if (!isfinite(from) || !isfinite(to)) {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: the ends of a range must be "
		                "finite", a->key, a->spec);
		goto out;
	}
	if (lg && (from == 0 || to == 0 || (from < 0) != (to < 0))) {
		rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: a log range needs FROM and TO "
		                "of the same sign, not 0; accepted: FROM and TO both > 0 or both "
		                "< 0", a->key, a->spec);
		goto out;
	}
	{
		const struct scene_keydef *kd;
		struct hb_scene_error e;
		int li = -1, ro = 0;

		plain = scene_key_resolve(sc, a->key, &kd, &li, &ro, &e) == HB_OK && !ro &&
		        (kd != NULL ? kd->store == ST_DOUBLE : li >= 0);
	}
	/*
	 * A double of the scene or a law parameter between two values accepted:
	 * %.17g of v sets v itself, in the range (an interval) of its ends.  (The
	 * test sweep::point_scene_equals_the_set_values sets the printed values.)
	 * When every value between the ends is such a v, none is kept: each is
	 * computed again when asked for (sweep_axis_num), the same double.
	 */
	a->ramp.from = from;
	a->ramp.to = to;
	a->ramp.lg = lg;
	a->ramp.on = plain;
	for (long i = 1; plain && i < a->n - 1; i++) {
		double v = sweep_ramp_value(from, to, a->n, lg, i);

		a->ramp.on = v >= fmin(from, to) && v <= fmax(from, to);
		if (!a->ramp.on)
			break;
	}
	if (a->ramp.on)
		goto out;
	a->num = malloc((size_t)a->n * sizeof *a->num);
	if (a->num == NULL) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	for (long i = 0; i < a->n; i++) {
		double v = sweep_ramp_value(from, to, a->n, lg, i);
		char t[64];

		if (i > 0 && i < a->n - 1 && plain && v >= fmin(from, to) && v <= fmax(from, to)) {
			a->num[i] = v;
			continue;
		}
		cnum_snprintf(t, sizeof t, "%.17g", v);
		if ((rc = canonical(sc, a->key, t, num, sizeof num, msg, n)) != HB_OK)
			goto out;
		/* %.17g reads back to the same double, which %.17g writes as num again */
		a->num[i] = cnum_strtod(num, NULL);
	}
out:
	for (int i = 0; i < 5; i++)
		free(part[i]);
	return rc;
}

/* A list V1,V2,... into a->val. */
static int
parse_list(struct axis *a, const struct hb_scene *sc, char *msg, size_t n)
{
	const char *p = a->spec, *c;
	long cnt = 1;
	char num[256];

	for (c = p; *c; c++)
		cnt += *c == ',';
	a->val = calloc((size_t)cnt, sizeof *a->val);
	if (a->val == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	for (a->n = 0; a->n < cnt; a->n++) {
		char *t;
		int rc;

		c = strchr(p, ',');
		t = trimmed(p, c ? c : p + strlen(p));
		if (t == NULL)
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		if (t[0] == '\0') {
			free(t);
			return hb_status_set(msg, n, HB_EINVAL, "--vary %s=%s: empty value in the "
			                  "list; " RANGE_HELP, a->key, a->spec);
		}
		rc = canonical(sc, a->key, t, num, sizeof num, msg, n);
		free(t);
		if (rc != HB_OK)
			return rc;
		if ((a->val[a->n] = strdup(num)) == NULL)
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		p = c ? c + 1 : p;
	}
	return HB_OK;
}

/*
 * Whether a point's scene can be made by storing its values into
 * sw->fast_base and deriving once: every axis a range of a double of the
 * scene or of a law parameter (no law among the axes).  hb_scene_set_number
 * does the same per axis (it derives, checks the range, stores, sets the
 * body's flags, derives again), at about 7,000 instructions each: the
 * stored doubles and the flags are the same (the values were checked when
 * the axis was made), and so is the derived scene.
 */
static void
fast_ready(struct hb_sweep *sw)
{
	struct hb_scene sc = sw->base;

	sw->fast = 0;
	for (int k = 0; k < sw->naxes; k++) {
		struct axis *a = &sw->ax[k];
		const struct scene_keydef *kd;
		struct hb_scene_error e;
		int li = -1, ro = 0;

		if (a->val != NULL || scene_key_resolve(&sc, a->key, &kd, &li, &ro, &e) != HB_OK ||
		    ro || (kd != NULL && kd->store != ST_DOUBLE) || (kd == NULL && li < 0))
			return;
		a->off = kd != NULL ? kd->off : 0;
		a->par = kd != NULL ? -1 : li;
		if (hb_scene_set_number(&sc, a->key, sweep_axis_num(a, 0), &e) != HB_OK)
			return;
	}
	sw->fast_base = sc;
	sw->fast = 1;
}

int
hb_sweep_vary(struct hb_sweep *sw, const char *arg, char *msg, size_t n)
{
	const char *eq = strchr(arg, '=');
	struct axis a;
	struct hb_scene sc;
	char *key;
	int k, rc;
	double others;

	memset(&a, 0, sizeof a);
	if (sw->rf.on)
		return hb_status_set(msg, n, HB_EINVAL, "--vary '%s': the sweep is refined already "
		                     "(--refine %s); expected every --vary before --refine", arg,
		                     sw->rf.spec);
	if (eq == NULL)
		return hb_status_set(msg, n, HB_EINVAL, "--vary '%s': " RANGE_HELP, arg);
	key = trimmed(arg, eq);
	if (key == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	if (key[0] == '\0' || strlen(key) >= sizeof a.key) {
		free(key);
		return hb_status_set(msg, n, HB_EINVAL, "--vary '%s': " RANGE_HELP, arg);
	}
	strcpy(a.key, key);
	free(key);
	/* blanks around the spec go, as around a --set value */
	if ((key = trimmed(eq + 1, eq + 1 + strlen(eq + 1))) == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	if (strlen(key) >= sizeof a.spec) {
		free(key);
		return hb_status_set(msg, n, HB_EINVAL, "--vary %s: value too long; accepted: up "
		                     "to %zu characters", a.key, sizeof a.spec - 1);
	}
	strcpy(a.spec, key);
	free(key);
	for (k = 0; k < sw->naxes; k++)
		if (strcmp(sw->ax[k].key, a.key) == 0)
			break;
	if (k == sw->naxes && sw->naxes == SWEEP_MAX_AXES)
		return hb_status_set(msg, n, HB_EINVAL, "--vary %s: too many axes; accepted: at "
		                  "most %d", a.key, SWEEP_MAX_AXES);
	sweep_check_scene(sw, k, &sc);
	others = 1;
	for (int i = 0; i < sw->naxes; i++)
		if (i != k)
			others *= (double)sw->ax[i].n;
	if (strchr(a.spec, ':') != NULL)
		rc = sweep_parse_range(&a, &sc, sw, others, msg, n);
	else
		rc = parse_list(&a, &sc, msg, n);
	if (rc != HB_OK) {
		sweep_axis_free(&a);
		return rc;
	}
	{
		double prod = (double)a.n * others;   /* no overflow: a double for the message */

		if (prod > (double)sw->max_points) {
			rc = hb_status_set(msg, n, HB_EINVAL, "--vary %s: the sweep would have %.0f "
			                   "points, more than the limit of %ld points; accepted: at most "
			                   "%ld points in all%s%s", a.key, prod, sw->max_points,
			                   sw->max_points, sw->more[0] ? "; " : "", sw->more);
			sweep_axis_free(&a);
			return rc;
		}
	}
	if (k < sw->naxes)
		sweep_axis_free(&sw->ax[k]);
	else
		sw->naxes++;
	sw->ax[k] = a;
	fast_ready(sw);
	return HB_OK;
}

/* See sweep_impl.h. */
int
sweep_tagged_lines(struct hb_sweep *sw, const char *text, const char *name, const char *tag,
                   int (*take)(struct hb_sweep *, const char *, char *, size_t), char *msg, size_t n)
{
	const char *p = text;
	size_t tl = strlen(tag);
	int line = 0;

	while (*p) {
		const char *end = strchr(p, '\n');
		size_t len = end ? (size_t)(end - p) : strlen(p);

		line++;
		if (len > tl && strncmp(p, tag, tl) == 0) {
			char arg[512], m[512];

			snprintf(arg, sizeof arg, "%.*s", (int)(len - tl), p + tl);
			m[0] = '\0';
			if (take(sw, arg, m, sizeof m) != HB_OK)
				return hb_status_set(msg, n, HB_EINVAL, "%s:%d: %s", name, line, m);
		}
		p = end ? end + 1 : p + len;
	}
	return HB_OK;
}

int
hb_sweep_vary_from_preset(struct hb_sweep *sw, const char *text, const char *name,
                       char *msg, size_t n)
{
	return sweep_tagged_lines(sw, text, name, "; sweep: --vary ", hb_sweep_vary, msg, n);
}

