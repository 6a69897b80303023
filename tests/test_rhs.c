/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_rhs.c - the right-hand side specialised per law (src/core/sim_rhs.c)
 * against the general one (hbs_rhs, sim_flow.c): for every built-in law,
 * exponents Hertz's and others, both extensions, the layouts with and
 * without x, the reduced and the full system (with its ramp), each mode
 * sign, and states from a fixed pseudo-random sequence, the same doubles
 * bit for bit and the same status; a state that is not finite fails in
 * both.  Where the general one must stay (the centre of mass integrated),
 * it is the one installed.
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>

#include "sim_impl.h"
#include "testutil.h"

static unsigned long rng = 12345;

/* a double in [-2, 2), or now and then a value at a kink (0) */
static double
draw(void)
{
	rng = rng * 6364136223846793005UL + 1442695040888963407UL;
	if ((rng >> 60) == 0)
		return 0.0;
	return ((double)(rng >> 11) / 9007199254740992.0 - 0.5) * 4.0;
}

/* Compares the installed rhs of both phases of sc with the general one; returns how many were special. */
static int
compare(const struct hb_scene *sc, const char *what)
{
	char msg[256];
	struct hb_sim *s = hb_sim_new(sc, msg, sizeof msg);
	int q, special = 0;

	cr_assert_not_null(s, "%s: %s", what, msg);
	for (q = 0; q < 2; q++) {
		struct phase *p = &s->ph[q];
		int n = p->L.dim, k, i, sign;

		special += p->sys.function != hbs_rhs;
		for (k = 0; k < 200; k++) {
			double u[MAXDIM], a[MAXDIM], b[MAXDIM], t = 0.3 * fabs(draw());

			for (i = 0; i < n; i++) {
				int e = (int)(10.0 * draw()); /* scales are powers of 2 (hbs_scales) */

				u[i] = draw();
				s->scale[i] = ldexp(1.0, e);
				s->iscale[i] = ldexp(1.0, -e);
			}
			if (k == 199)
				u[p->L.iv] = NAN;
			for (sign = -1; sign <= 1; sign++) {
				int ra, rb;

				s->msign = q && s->I->law->psi_mode ? sign : 0; /* a mode only where the law has one */
				memset(a, 0, sizeof a);
				memset(b, 0, sizeof b);
				ra = p->sys.function(t, u, a, p);
				rb = hbs_rhs(t, u, b, p);
				cr_assert_eq(ra, rb, "%s, q = %d, state %d: status %d against %d", what, q, k, ra, rb);
				if (k == 199)
					cr_assert_neq(ra, GSL_SUCCESS, "%s: a state that is not finite passed", what);
				else
					cr_assert_eq(memcmp(a, b, sizeof a), 0, "%s, q = %d, state %d, sign %d: "
					             "du differs", what, q, k, sign);
			}
		}
	}
	s->msign = 0;
	hb_sim_free(s);
	return special;
}

static void
set(struct hb_scene *sc, const char *key, const char *val)
{
	char msg[256];

	cr_assert_eq(hb_scene_set(sc, key, val, msg, sizeof msg), 0, "%s = %s: %s", key, val, msg);
}

Test(rhs, specialised_gives_the_general_doubles)
{
	static const char *presets[] = { "steel-on-bitumen", "ptfe-pom", "permanent-contact-shccl" };
	static const char *laws[] = { NULL, "shccl", "bwshccl", "bwmcl", "hertz", "linear" };
	static const char *reduce[] = { "all", "flight,com" };
	static const char *ext[] = { "adhesive", "none" };
	int ip, il, ir, ie, pe;

	for (ip = 0; ip < 3; ip++)
		for (il = 0; il < 6; il++)
			for (ir = 0; ir < 2; ir++)
				for (ie = 0; ie < 2; ie++)
					for (pe = 0; pe < 2; pe++) {
						struct hb_scene sc;
						char what[256];

						scene_preset(presets[ip], &sc);
						if (laws[il])
							set(&sc, "scene.law", laws[il]);
						set(&sc, "run.reductions", reduce[ir]);
						set(&sc, "scene.extension", ext[ie]);
						if (pe && hb_law_param_index(sc.law, "p") >= 0)
							set(&sc, "law.p", "2.7");
						if (pe && hb_law_param_index(sc.law, "n") >= 0)
							set(&sc, "law.n", "1.7");
						snprintf(what, sizeof what, "%s, law %s, reductions %s, %s%s",
						         presets[ip], sc.law->name, reduce[ir], ext[ie],
						         pe ? ", p 2.7, n 1.7" : "");
						cr_assert_eq(compare(&sc, what), 2, "%s: not specialised", what);
					}
}

Test(rhs, general_where_the_centre_of_mass_is_integrated)
{
	struct hb_scene sc;

	scene_preset("ptfe-pom", &sc);
	set(&sc, "run.reductions", "none");
	cr_assert_eq(compare(&sc, "ptfe-pom, reductions none"), 0);
}
