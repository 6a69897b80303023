/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * status.c - status codes and message formatting (see status.h).
 */
#include <stdarg.h>
#include <stdio.h>

#include "hybounce/status.h"
#include "cnum.h"

const char *
hb_status_str(int status)
{
	switch (status) {
	case HB_OK: return "ok";
	case HB_EINVAL: return "bad input";
	case HB_ENOMEM: return "out of memory";
	case HB_EIO: return "input/output error";
	case HB_ENUMERIC: return "numerical failure";
	case HB_ECHATTER: return "jumps without end at one instant";
	case HB_EDONE: return "the run has ended";
	default: return "unknown status";
	}
}

int
hb_status_set(char *buf, size_t n, int status, const char *fmt, ...)
{
	va_list ap;

	if (buf == NULL || n == 0)
		return status;
	va_start(ap, fmt);
	cnum_vsnprintf(buf, n, fmt, ap);
	va_end(ap);
	return status;
}
