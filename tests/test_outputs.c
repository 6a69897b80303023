/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_outputs.c - the output policy (src/core/outputs.c): an output that is
 * an input, a shipped preset or another output of the command (by name, by
 * link, by canonical name) is refused, a device written in place is not;
 * the provenance line quotes its arguments for a shell; input.c reads a
 * file whole up to its limit and refuses one byte more; atomic.c tells its
 * temporary names, and which of them a dead process left.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <criterion/criterion.h>

#include "hybounce/atomic.h"
#include "hybounce/input.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "testutil.h"

static char dir[] = "/tmp/hb-outputs-XXXXXX";

static void
in_dir(char *out, size_t n, const char *name)
{
	snprintf(out, n, "%s/%s", dir, name);
}

static void
touch(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	cr_assert_not_null(f, "%s: %s", path, strerror(errno));
	fputs(text, f);
	fclose(f);
}

Test(outputs, inputs_shipped_presets_and_twice_are_refused)
{
	char data[256], other[256], link[256], dot[512], shipped[1024], msg[512];
	struct hb_outputs o;

	cr_assert_not_null(mkdtemp(dir));
	in_dir(data, sizeof data, "data.csv");
	in_dir(other, sizeof other, "out.preset");
	in_dir(link, sizeof link, "link.csv");
	touch(data, "t_e\n0\n");
	cr_assert_eq(symlink(data, link), 0);
	hb_outputs_init(&o);
	cr_assert_eq(hb_outputs_input(&o, data, "the data file"), HB_OK);
	/* the input itself, through a link */
	cr_assert_eq(hb_outputs_add(&o, data, "--out", msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "is the data file") != NULL, "%s", msg);
	cr_assert_eq(hb_outputs_add(&o, link, "--out", msg, sizeof msg), HB_EINVAL);
	/* a shipped preset */
	snprintf(shipped, sizeof shipped, "%s/steel-on-bitumen.preset", preset_dir());
	cr_assert_eq(hb_outputs_add(&o, shipped, "--out", msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "shipped preset") != NULL, "%s", msg);
	/* a new file, then the same new file by another name */
	cr_assert_eq(hb_outputs_add(&o, other, "--out", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(o.out[0].target.how, HB_ATOMIC_NEW);
	snprintf(dot, sizeof dot, "%s/./out.preset", dir);
	cr_assert_eq(hb_outputs_add(&o, dot, "--residuals", msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "are the same file") != NULL, "%s", msg);
	/* devices written in place: twice is no conflict, never "replaced" */
	cr_assert_eq(hb_outputs_add(&o, "/dev/null", "--a", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_outputs_add(&o, "/dev/null", "--b", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(o.out[1].target.how, HB_ATOMIC_IN_PLACE);
	hb_outputs_how(&o.out[1].target, msg, sizeof msg);
	cr_assert_str_eq(msg, " (written in place)");
	/* a folder */
	cr_assert_neq(hb_outputs_add(&o, dir, "--c", msg, sizeof msg), HB_OK);
	cr_assert(hb_outputs_same_file(data, link));
	cr_assert(!hb_outputs_same_file(data, other));
	unlink(link);
	unlink(data);
	rmdir(dir);
}

Test(outputs, provenance_quotes_for_a_shell)
{
	const char *argv[] = { "hybounce", "-b", "x y", "it's", "$(touch P)", "plain=1,2:3", "" };
	char buf[512], small[24];
	size_t n = hb_outputs_provenance(buf, sizeof buf, "0.1.0", "abc1234", 7, argv);

	cr_assert_str_eq(buf, "; hybounce 0.1.0 (commit abc1234): hybounce -b 'x y' 'it'\\''s' "
	                      "'$(touch P)' plain=1,2:3 ''");
	cr_assert_eq(n, strlen(buf));
	/* no commit known; truncation says so */
	hb_outputs_provenance(buf, sizeof buf, "0.1.0", NULL, 1, argv);
	cr_assert_str_eq(buf, "; hybounce 0.1.0 (commit unknown): hybounce");
	cr_assert_eq(hb_outputs_provenance(small, sizeof small, "0.1.0", "c", 7, argv), n - 6);
	cr_assert_eq(strlen(small), sizeof small - 1);
	cr_assert_str_eq(small + sizeof small - 4, "...");
}

Test(outputs, input_read_is_bounded)
{
	char path[256], msg[512], *buf = NULL;
	size_t len = 0;
	FILE *f;

	cr_assert_not_null(mkdtemp(dir));
	in_dir(path, sizeof path, "in.txt");
	f = fopen(path, "w");
	for (int i = 0; i < 100000; i++)
		fputc('a' + i % 26, f);
	fclose(f);
	cr_assert_eq(hb_input_read(path, 100000, &buf, &len, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(len, 100000);
	cr_assert_eq(buf[99999], 'a' + 99999 % 26);
	cr_assert_eq(buf[100000], '\0');
	free(buf);
	buf = NULL;
	cr_assert_eq(hb_input_read(path, 99999, &buf, &len, msg, sizeof msg), HB_EINVAL);
	cr_assert_null(buf);
	cr_assert(strstr(msg, "larger than 99999 bytes") != NULL, "%s", msg);
	cr_assert_eq(hb_input_read("/dev/zero", (size_t)1 << 20, &buf, &len, msg, sizeof msg),
	             HB_EINVAL);
	cr_assert(strstr(msg, "larger than 1 MiB") != NULL, "%s", msg);
	cr_assert_eq(hb_input_read(dir, 100, &buf, &len, msg, sizeof msg), HB_EIO);
	cr_assert(strstr(msg, "is a folder") != NULL, "%s", msg);
	unlink(path);
	cr_assert_eq(hb_input_read(path, 100, &buf, &len, msg, sizeof msg), HB_EIO);
	rmdir(dir);
}

Test(outputs, temporary_names_come_from_the_atomic_writer)
{
	long pid = 0;
	char name[64];

	cr_assert(hb_atomic_is_temp("sweep.preset.hbtmp-123-AbCdEf", "sweep.preset", &pid));
	cr_assert_eq(pid, 123);
	cr_assert(hb_atomic_is_temp("sweep.preset.hbtmp-123-AbCdEf.old", NULL, NULL));
	cr_assert(!hb_atomic_is_temp("sweep.preset.hbtmp-123-AbCdEf", "runs.csv", NULL));
	cr_assert(!hb_atomic_is_temp("sweep.preset.tmp", NULL, NULL));
	cr_assert(!hb_atomic_is_temp("x" HB_ATOMIC_TMP_TAG "abc-1", NULL, NULL));
	/* our own process is alive; pid 2^22 + 1 is beyond Linux's pid_max */
	snprintf(name, sizeof name, "a" HB_ATOMIC_TMP_TAG "%ld-x", (long)getpid());
	cr_assert(!hb_atomic_temp_stale(".", name));
	cr_assert(hb_atomic_temp_stale(".", "a" HB_ATOMIC_TMP_TAG "4194305-x"));
}
