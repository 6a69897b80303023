/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * input.c - reading an input once, whole and bounded (see input.h).
 */
#include <errno.h>
#include <stdio.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hybounce/input.h"
#include "hybounce/status.h"

/* "64 MiB", "512 KiB" or "N bytes" for a limit. */
static void
size_words(size_t v, char *buf, size_t n)
{
	if (v >= ((size_t)1 << 20) && v % ((size_t)1 << 20) == 0)
		snprintf(buf, n, "%zu MiB", v >> 20);
	else if (v >= 1024 && v % 1024 == 0)
		snprintf(buf, n, "%zu KiB", v >> 10);
	else
		snprintf(buf, n, "%zu bytes", v);
}

int
hb_input_read(const char *path, size_t limit, char **out, size_t *outlen, char *msg, size_t n)
{
	int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOCTTY);
	char *buf = NULL, lim[32];
	size_t len = 0, cap = 0;
	struct stat st;

	*out = NULL;
	if (outlen != NULL)
		*outlen = 0;
	if (fd < 0)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	if (fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
		close(fd);
		return hb_status_set(msg, n, HB_EIO, "%s: is a folder; expected a file", path);
	}
	for (;;) {
		ssize_t got;

		if (cap - len < 4096 && cap < limit + 2) {
			size_t nc = cap == 0 ? 65536 : 2 * cap;
			char *nb;

			if (nc > limit + 2)
				nc = limit + 2;     /* one byte past the limit tells, one NUL */
			if ((nb = realloc(buf, nc)) == NULL) {
				free(buf);
				close(fd);
				return hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", path);
			}
			buf = nb;
			cap = nc;
		}
		got = read(fd, buf + len, cap - len - 1);
		if (got < 0) {
			int e = errno;

			if (e == EINTR)
				continue;
			free(buf);
			close(fd);
			return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(e));
		}
		if (got == 0)
			break;
		len += (size_t)got;
		if (len > limit) {
			free(buf);
			close(fd);
			size_words(limit, lim, sizeof lim);
			return hb_status_set(msg, n, HB_EINVAL, "%s: larger than %s; accepted: a file "
			    "of at most %s (the limit of this input)", path, lim, lim);
		}
	}
	close(fd);
	if (buf == NULL && (buf = malloc(1)) == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", path);
	buf[len] = '\0';
	*out = buf;
	if (outlen != NULL)
		*outlen = len;
	return HB_OK;
}
