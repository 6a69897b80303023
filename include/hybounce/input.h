/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * input.h - how the program reads an input file: once, whole, into memory,
 * with a size limit, so that a pipe, a FIFO or /dev/stdin works as well
 * as a file (nothing is opened twice or rewound), and /dev/zero or a huge
 * file is refused with a message naming the limit instead of eating the
 * memory.
 */
#ifndef HB_INPUT_H
#define HB_INPUT_H

#include <stddef.h>

#include "export.h"
HB_BEGIN_DECLS

/* Limits of the front ends: a preset, a data file (CSV of measurements). */
#define HB_INPUT_PRESET_MAX ((size_t)64 << 20)   /* 64 MiB */
#define HB_INPUT_DATA_MAX   ((size_t)64 << 20)   /* 64 MiB */

/*
 * Reads path whole into *buf (malloc'd, NUL-terminated after *len bytes;
 * the caller frees).  Returns HB_OK; HB_EIO with "PATH: reason" (a folder
 * included); HB_EINVAL with "PATH: larger than LIMIT; accepted: ..." when
 * more than limit bytes come (reading stops there); HB_ENOMEM.
 */
int
hb_input_read(const char *path, size_t limit, char **buf, size_t *len, char *msg, size_t n);

HB_END_DECLS

#endif
