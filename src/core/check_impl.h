/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * check_impl.h - what check.c and check_chain.c share (internal).
 */
#ifndef HB_CHECK_IMPL_H
#define HB_CHECK_IMPL_H

#include <stddef.h>

/* How the law named handles energy: passive (cannot give it back), elastic (stores and returns). */
void check_law_energy(const char *name, int *passive, int *elastic);

/* Appends one failure to msg, "; "-separated. */
void check_append_msg(char *msg, size_t n, const char *fmt_, ...)
	__attribute__((format(printf, 3, 4)));

#endif
