/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_plot_summary.c - the explorer's min/max pyramid (src/tui/plot_summary.c)
 * gives the extremes a scan of the samples gives, for any range, as the
 * arc grows, and after the arc changed under it.
 */
#include <math.h>
#include <stdlib.h>

#include <criterion/criterion.h>

#include "plot_summary.h"
#include "testutil.h"

static void
check_ranges(const struct plot_sum *p, const struct hb_sim *s, unsigned seed)
{
	const struct hb_arc *arc = hb_sim_arc(s);
	size_t n = hb_arc_len(arc);

	srand(seed);
	for (int trial = 0; trial < 400; trial++) {
		size_t a = (size_t)rand() % n, b = (size_t)rand() % (n + 1);

		if (trial % 4 == 0)
			b = a + (size_t)rand() % 40;   /* short ranges: the edges alone */
		if (b > n)
			b = n;
		if (a > b) {
			size_t t = a;
			a = b;
			b = t;
		}
		for (int q = 0; q < PSUM_NQ; q++) {
			double lo = INFINITY, hi = -INFINITY, blo = INFINITY, bhi = -INFINITY;

			psum_range(p, a, b, q, &lo, &hi);
			for (size_t i = a; i < b; i++) {
				double v = psum_value(hb_arc_at(arc, i), q);

				blo = fmin(blo, v);
				bhi = fmax(bhi, v);
			}
			cr_assert(lo == blo && hi == bhi, "q %d, samples [%zu, %zu) of %zu: %g..%g, scan %g..%g",
			          q, a, b, n, lo, hi, blo, bhi);
		}
	}
}

Test(plot_summary, extremes_of_any_range_as_a_scan_gives_them)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct plot_sums *ps = psum_new();
	const struct plot_sum *p;
	char msg[256];

	cr_assert_not_null(ps);
	scene_preset("steel-on-bitumen", &sc);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(s, "%s", msg);
	/* as the arc grows, frame by frame */
	for (int frame = 0; frame < 40 && hb_sim_end(s) == HB_SIM_RUNNING; frame++) {
		cr_assert_eq(hb_sim_advance(s, 25, 0), 0);
		p = psum_of(ps, s);
		cr_assert_not_null(p);
		check_ranges(p, s, (unsigned)frame);
	}
	cr_assert_eq(hb_sim_run(s), 0);
	p = psum_of(ps, s);
	check_ranges(p, s, 99);
	/* the arc changed under it: a restart, then a shorter run */
	cr_assert_eq(hb_sim_restart(s), 0);
	cr_assert_eq(hb_sim_advance(s, 300, 0), 0);
	p = psum_of(ps, s);
	check_ranges(p, s, 7);
	hb_sim_free(s);
	psum_free(ps);
}
