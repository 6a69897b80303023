/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_sample.h - an interface's state and the sample that holds it, one
 * field list for both directions: a sample filled from the state
 * (hbs_sample_put, sim_record.c) and the state restored from a sample
 * (hbs_sample_get, sim_seek.c).  A field named here has the same name
 * and size in struct iface (or struct hb_sim) and struct hb_arc_sample,
 * and is copied bit for bit.  Private to the engine.
 */
#ifndef HYBOUNCE_SIM_SAMPLE_H
#define HYBOUNCE_SIM_SAMPLE_H

#include "sim_impl.h"

/* the interface's, in flight and in contact */
#define HBS_SAMPLE_IFACE(X) X(q) X(x) X(v) X(W) X(JFc) X(JFe) X(xcmax) X(Fcmax) X(Ee) X(Wc)
/* the interface's contact's own, 0 in a flight's sample */
#define HBS_SAMPLE_CONTACT(X) X(xc) X(z)
/* the simulator's: the centre of mass of the pair */
#define HBS_SAMPLE_SIM(X) X(xm) X(vm)

#define HBS_SAMPLE_COPY(f)                                                                    \
	_Static_assert(sizeof dst->f == sizeof src->f, "sample field " #f);                     \
	memcpy(&dst->f, &src->f, sizeof dst->f);

/*
 * Sample a takes interface I's state and the simulator's centre of mass;
 * x_c and z only in contact (a's stay as they are, 0 from memset, in
 * flight).
 */
static inline void
hbs_sample_put(struct hb_arc_sample *a, const struct iface *I, const struct hb_sim *s)
{
	{
		struct hb_arc_sample *dst = a;
		const struct iface *src = I;

		HBS_SAMPLE_IFACE(HBS_SAMPLE_COPY)
		if (I->q) {
			HBS_SAMPLE_CONTACT(HBS_SAMPLE_COPY)
		}
	}
	{
		struct hb_arc_sample *dst = a;
		const struct hb_sim *src = s;

		HBS_SAMPLE_SIM(HBS_SAMPLE_COPY)
	}
}

/* Interface I and the simulator's centre of mass take sample a's state (its every field). */
static inline void
hbs_sample_get(struct iface *I, struct hb_sim *s, const struct hb_arc_sample *a)
{
	{
		struct iface *dst = I;
		const struct hb_arc_sample *src = a;

		HBS_SAMPLE_IFACE(HBS_SAMPLE_COPY)
		HBS_SAMPLE_CONTACT(HBS_SAMPLE_COPY)
	}
	{
		struct hb_sim *dst = s;
		const struct hb_arc_sample *src = a;

		HBS_SAMPLE_SIM(HBS_SAMPLE_COPY)
	}
}

#endif
