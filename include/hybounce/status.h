/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * status.h - status codes returned by every engine function.
 *
 * 0 is success.  Library code never prints and never exits: it returns one
 * of these codes and leaves a human-readable message in the handle (sim) or
 * in a caller-provided buffer (parsers, validators).
 */
#ifndef HB_STATUS_H
#define HB_STATUS_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>

enum hb_status {
	HB_OK = 0,
	HB_EINVAL,     /* bad input: malformed text, unknown key, out of range, wrong unit */
	HB_ENOMEM,     /* an allocation failed */
	HB_EIO,        /* a file could not be read or written */
	HB_ENUMERIC,   /* the integration failed: step underflow, non-finite state or force */
	HB_ECHATTER,   /* a run would jump without end at one instant */
	HB_EDONE,      /* the run has already ended (horizon, jump cap or failure) */
};

/* A short constant English description of a status code ("ok", "bad input", ...). */
const char *
hb_status_str(int status);

/*
 * Formats a message into buf (size n, always NUL-terminated when n > 0) and
 * returns status unchanged, so that code can write
 *     return hb_status_set(buf, n, HB_EINVAL, "%s:%d: ...", file, line);
 */
int
hb_status_set(char *buf, size_t n, int status, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

HB_END_DECLS

#endif
