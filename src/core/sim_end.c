/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_end.c - how a run ends: a failure (the message names where the run
 * stood), the horizon T, the jump cap J.  Below every file of the run,
 * and calling none of them.
 */
#include "sim_impl.h"
#include "cnum.h"

int
hbs_fail(struct hb_sim *s, int status, const char *why)
{
	struct iface *I = s->I;
	s->end = HB_SIM_END_FAIL;
	cnum_snprintf(s->err, sizeof s->err,
	         "%s at (t = %.12g s, j = %ld): x = %.6g m, v = %.6g m/s, x_c = %.6g m, q_c = %d",
	         why, s->t, s->j, I->x, I->v, I->xc, I->q);
	snprintf(s->endmsg, sizeof s->endmsg, "failed: %s", s->err);
	return status;
}

int
hbs_fail_iface(struct hb_sim *s, const struct iface *I, int status, const char *why)
{
	s->end = HB_SIM_END_FAIL;
	cnum_snprintf(s->err, sizeof s->err,
	         "%s; interface %d there (j = %ld): x = %.6g m, v = %.6g m/s, x_c = %.6g m, q_c = %d",
	         why, s->k0 + (int)(I - s->ifc), s->j, I->x, I->v, I->xc, I->q);
	snprintf(s->endmsg, sizeof s->endmsg, "failed: %s", s->err);
	return status;
}

void
hbs_finish_T(struct hb_sim *s)
{
	s->end = HB_SIM_END_T;
	cnum_snprintf(s->endmsg, sizeof s->endmsg, "horizon T = %.9g s reached at j = %ld",
	         s->sc.run.T, s->j);
}

void
hbs_finish_J(struct hb_sim *s)
{
	s->end = HB_SIM_END_J;
	cnum_snprintf(s->endmsg, sizeof s->endmsg, "jump cap J = %ld reached at t = %.9g s",
	              s->sc.run.J, s->t);
}
