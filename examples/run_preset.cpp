/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * run_preset.cpp - run_preset.c from C++: the same output, the library's
 * handle held by a std::unique_ptr so that every path frees it.
 *
 *     c++ run_preset.cpp $(pkg-config --cflags --libs hybounce) -o run_preset_cpp
 *     ./run_preset_cpp steel-on-bitumen
 *
 * The public headers declare everything extern "C", so no wrapping is
 * needed here.
 */
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <hybounce/preset.h>
#include <hybounce/sim.h>
#include <hybounce/status.h>

namespace {

struct sim_deleter {
	void operator()(hb_sim *s) const { hb_sim_free(s); }
};
using sim_ptr = std::unique_ptr<hb_sim, sim_deleter>;

/* Loads a preset by name or path; throws with the library's message. */
hb_scene
load(const std::string &name, std::string &path)
{
	char buf[512], msg[1024];
	hb_scene sc;

	if (hb_preset_resolve(name.c_str(), buf, sizeof buf, msg, sizeof msg) != HB_OK ||
	    hb_preset_load(buf, &sc, msg, sizeof msg) != HB_OK)
		throw std::runtime_error(msg);
	path = buf;
	return sc;
}

} // namespace

int
main(int argc, char **argv)
{
	if (argc != 2) {
		std::fprintf(stderr, "usage: %s PRESET\n", argv[0]);
		return 2;
	}
	std::string path;
	hb_scene sc;
	try {
		sc = load(argv[1], path);
	} catch (const std::exception &e) {
		std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
		return 2;
	}
	char msg[1024];
	sim_ptr s(hb_sim_new(&sc, msg, sizeof msg));
	if (!s) {
		std::fprintf(stderr, "%s: %s\n", argv[0], msg);
		return 2;
	}
	int status = hb_sim_run(s.get());

	std::printf("# %s: %s\n", path.c_str(), sc.name);
	std::printf("# i t_e[s] t_s[s] v_i[m/s] e\n");
	size_t n = hb_sim_ncollisions(s.get());
	for (size_t i = 0; i < n; i++) {
		const hb_collision *c = hb_sim_collision(s.get(), i);
		std::printf("%ld %.17g %.17g %.17g %.17g\n", c->i, c->te, c->ts, c->vi, c->e);
	}
	std::printf("# %zu collisions, %s\n", n, hb_sim_end_str(s.get()));
	if (status != 0)
		std::fprintf(stderr, "%s: %s: %s\n", argv[0], hb_status_str(status), hb_sim_errmsg(s.get()));
	return status != 0 ? 1 : 0;
}
