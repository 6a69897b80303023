/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_stepper.c - the names of the steppers (scene.h:
 * hb_scene_stepper_name, hb_scene_stepper_find), which run.stepper reads
 * and prints.  Below the key table and the defaults, which both use them.
 */
#include <string.h>

#include "hybounce/scene.h"

static const char *const stepper_names[HB_STEPPER_COUNT] = {
	"rk8pd", "rkf45", "rkck", "msbdf", "rk4imp", "bsimp", "auto", "dop853", "vern98",
};

const char *
hb_scene_stepper_name(int stepper)
{
	if (stepper < 0 || stepper >= HB_STEPPER_COUNT)
		return "?";
	return stepper_names[stepper];
}

int
hb_scene_stepper_find(const char *name)
{
	if (name == NULL)
		return -1;
	for (int i = 0; i < HB_STEPPER_COUNT; i++)
		if (strcmp(stepper_names[i], name) == 0)
			return i;
	return -1;
}
