# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce - plain Makefile (GNU make).
#
#   make            build build/hybounce
#   make run        install missing packages, build, open the explorer on the default preset
#   make check      install missing packages, build, run every test and the fuzz smoke
#   make lint-cycles   no cycle of calls among the source files (also part of make check)
#   make fuzz       the libFuzzer campaign, FUZZ_TIME seconds per harness (tests/fuzz)
#   make check-asan the unit tests under AddressSanitizer + UBSan
#   make bench      the work-precision benchmark (report in build/bench/)
#   make bench-steppers  every stepper's true error against tests/reference (into tests/bench/REPORT.md)
#   make bench-studies   per study: instructions per rhs, rhs, time beside SciPy, true error, error bar
#   make golden     rewrite tests/golden/*.csv (the collision tables the tests compare with)
#   make reference  rewrite tests/reference/*.csv, the binary128 reference of the paper studies
#   make python     the Python package in build/python/hybounce (over build/'s libhybounce.so)
#   make bench-python  a 1,000-point sweep from Python side by side with hybounce sweep
#   make bench-figures a figure of each paper study against its batch run; PNG sizes
#   make bench-tui  the explorer's frame cost at 25k and 250k samples
#   make install / uninstall   honour PREFIX, DESTDIR, MANPREFIX, LIBDIR, INCLUDEDIR, PYTHONDIR
#                   (the binary, man page, presets, and libhybounce: shared, static,
#                   headers under include/hybounce/, pkg-config file hybounce.pc;
#                   the Python package hybounce)
#   make SAN=address,undefined   any target with sanitizers
#   make debug      -O0 -g3

# The release number (MAJOR.MINOR.PATCH) is the VERSION file's; the
# public header version.h, generated in $(BUILD)/include/hybounce/, adds the
# commit (tools/version.sh).
VERSION   := $(strip $(file <VERSION))
PREFIX    ?= /usr/local
MANPREFIX ?= $(PREFIX)/share/man
DATADIR   ?= $(PREFIX)/share/hybounce
LIBDIR    ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
# libhybounce.so.SOVERSION: raise it when the ABI changes incompatibly.
SOVERSION := 3
CC        ?= gcc
PKG_CONFIG ?= pkg-config

# Debian packages the build and the tests use (apt-get names).
APT_PACKAGES := libgsl-dev libncurses-dev libinih-dev libcriterion-dev pkg-config tmux mandoc \
                clang libclang-rt-14-dev strace parallel slurm-wlm munge \
                libaubio-dev aubio-tools sox libsox-fmt-mp3 locales python3-pandas \
                python3-cffi python3-numpy python3-pytest \
                libcairo2-dev libpng-dev poppler-utils valgrind libhdf5-dev python3-h5py
# Locales the tests run under (decimal commas, a Turkish case fold): `make
# deps` generates those `locale -a` lacks with localedef (about 2 MB each,
# where locales-all would take 220 MB).
TEST_LOCALES := de_DE fr_FR tr_TR

BUILD     ?= build
OPT       ?= -O2
WARN      := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
             -Wwrite-strings -Wformat=2 -Wundef
ifdef WERROR
WARN      += -Werror
endif
ifdef SAN
# float-cast-overflow: gcc's (and clang's) "undefined" leaves it out
SANFLAGS  := -fsanitize=$(SAN) -fsanitize=float-cast-overflow -fno-omit-frame-pointer \
             -fno-sanitize-recover=undefined,float-cast-overflow
endif

CURSES_PC := $(shell $(PKG_CONFIG) --exists ncursesw 2>/dev/null && echo ncursesw || echo ncurses)
CORE_CFLAGS := $(shell $(PKG_CONFIG) --cflags gsl inih 2>/dev/null)
# the engine never reads errno after a math function: sqrt and the like inline
CORE_CFLAGS += -fno-math-errno
CORE_LIBS   := $(shell $(PKG_CONFIG) --libs gsl inih 2>/dev/null) -lm
CORE_LIBS   += -pthread
# ncursesw's pkg-config adds -D_XOPEN_SOURCE=600, which would redefine ours (700).
TUI_CFLAGS  := $(filter-out -D_XOPEN_SOURCE=%,$(shell $(PKG_CONFIG) --cflags $(CURSES_PC) 2>/dev/null))
TUI_LIBS    := $(shell $(PKG_CONFIG) --libs $(CURSES_PC) 2>/dev/null)
TEST_CFLAGS := $(shell $(PKG_CONFIG) --cflags criterion 2>/dev/null)
TEST_LIBS   := $(shell $(PKG_CONFIG) --libs criterion 2>/dev/null)
# aubio (onset detection for `hybounce fit` on recordings): its header for
# onset.o and onset_aubio.o; the library itself is opened with dlopen when
# a recording is first read (src/core/onset_aubio.h says why), under the
# soname of the libaubio pkg-config finds.
AUBIO_CFLAGS := $(shell $(PKG_CONFIG) --cflags aubio 2>/dev/null)
AUBIO_SONAME := $(shell objdump -p "$$($(PKG_CONFIG) --variable=libdir aubio 2>/dev/null)/libaubio.so" \
                  2>/dev/null | sed -n 's/^ *SONAME *//p')
AUBIO_LIBS   := -ldl
# cairo (the figures of `hybounce plot`): its headers for plot_cairo.o (as
# system headers: -isystem), the library opened with dlopen when a figure
# is first drawn (src/cli/plot_cairo.c says why), under the soname of the
# libcairo pkg-config finds.
# libpng likewise (a PNG is written with it: plot_cairo.c says why).
CAIRO_CFLAGS := $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags cairo libpng 2>/dev/null))
CAIRO_SONAME := $(shell objdump -p "$$($(PKG_CONFIG) --variable=libdir cairo 2>/dev/null)/libcairo.so" \
                  2>/dev/null | sed -n 's/^ *SONAME *//p')
PNG_SONAME   := $(shell objdump -p "$$($(PKG_CONFIG) --variable=libdir libpng 2>/dev/null)/libpng.so" \
                  2>/dev/null | sed -n 's/^ *SONAME *//p')
# libhdf5 (hybounce sweep --format hdf5): its headers for sweep_hdf5.o and
# sweep_hdf5_load.o (as system headers), the serial library opened with
# dlopen when a sweep first asks for it (src/cli/sweep_hdf5_load.c says
# why), under the soname of the hdf5-serial pkg-config finds.
HDF5_PC     := $(shell $(PKG_CONFIG) --exists hdf5-serial 2>/dev/null && echo hdf5-serial || echo hdf5)
HDF5_CFLAGS := $(patsubst -I%,-isystem %,$(shell $(PKG_CONFIG) --cflags $(HDF5_PC) 2>/dev/null))
HDF5_LIBDIR := $(patsubst -L%,%,$(firstword $(shell $(PKG_CONFIG) --libs-only-L $(HDF5_PC) 2>/dev/null)))
HDF5_SONAME := $(shell objdump -p "$(or $(HDF5_LIBDIR),$$($(PKG_CONFIG) --variable=libdir $(HDF5_PC) \
                  2>/dev/null))/libhdf5.so" 2>/dev/null | sed -n 's/^ *SONAME *//p')
# The hybounce executable links GSL, inih and ncursesw from their static
# archives (shipped by the same -dev packages): resolving libgsl's dynamic
# relocations took 0.8M of the 1.3M instructions of a batch run that does
# nothing (callgrind), more than reading the preset and printing.  The
# library, the tests and the tools link them dynamically.
# `make STATIC_DEPS=no` links the executable dynamically too.
STATIC_DEPS ?= yes
ifeq ($(STATIC_DEPS),yes)
BIN_LIBS := -Wl,-Bstatic $(filter-out -lm -ldl -lpthread,$(shell $(PKG_CONFIG) --static \
              --libs-only-l $(CURSES_PC) gsl inih 2>/dev/null)) -Wl,-Bdynamic -lm -pthread
else
BIN_LIBS := $(TUI_LIBS) $(CORE_LIBS)
endif

CPPFLAGS  += -Iinclude -Iinclude/hybounce -I$(BUILD)/include -Isrc/core -DHYBOUNCE_VERSION='"$(VERSION)"' \
             -DHYBOUNCE_DATADIR='"$(DATADIR)"' -D_POSIX_C_SOURCE=200809L -D_XOPEN_SOURCE=700
CFLAGS    ?= $(OPT) -g
CFLAGS    += -std=c17 $(WARN) $(SANFLAGS) -MMD -MP
LDFLAGS   += $(SANFLAGS)

CORE_SRC  := $(sort $(wildcard src/core/*.c))
TUI_SRC   := $(sort $(wildcard src/tui/*.c))
CLI_SRC   := $(sort $(wildcard src/cli/*.c))
TEST_SRC  := $(sort $(wildcard tests/test_*.c))
BENCH_SRC := $(sort $(wildcard tests/bench/*.c))

CORE_OBJ  := $(CORE_SRC:%.c=$(BUILD)/%.o)
TUI_OBJ   := $(TUI_SRC:%.c=$(BUILD)/%.o)
CLI_OBJ   := $(CLI_SRC:%.c=$(BUILD)/%.o)
TEST_OBJ  := $(TEST_SRC:%.c=$(BUILD)/%.o)
BENCH_OBJ := $(BENCH_SRC:%.c=$(BUILD)/%.o)
# The engine for the programs built here (the hybounce binary, the tests,
# the bench, the tools), which may call its internal functions; the
# installed static library is STATIC_LIB (below).
CORE_LIB  := $(BUILD)/libhybounce-internal.a
TUI_LIB   := $(BUILD)/libhybounce-tui.a
BIN       := $(BUILD)/hybounce
UNIT      := $(BUILD)/unit-tests
BENCHBIN  := $(BUILD)/hybounce-bench
# The binary128 reference of the paper's studies (tests/reference/).
REFBIN    := $(BUILD)/hybounce-ref
REF_STUDIES := steel-on-bitumen ptfe-pom permanent-contact-shccl permanent-contact-bwshccl \
               permanent-contact-bwmcl

# libhybounce.so: the core objects are position-independent and hidden
# unless a public header declares them (HB_BEGIN_DECLS, include/hybounce/export.h).
LIB_CFLAGS := -fPIC -fvisibility=hidden
SHLIB_SO   := libhybounce.so.$(SOVERSION)
SHLIB      := $(BUILD)/libhybounce.so.$(VERSION)
PCFILE     := $(BUILD)/hybounce.pc
VERSION_H  := $(BUILD)/include/hybounce/version.h
PUBLIC_H   := $(sort $(wildcard include/hybounce/*.h)) $(VERSION_H)
# libhybounce.a, as installed: the core objects linked into one relocatable
# object (ld -r) whose hidden symbols objcopy --localize-hidden makes local,
# so that only the public hb_ names are global: a host program that links
# it statically may define any of the engine's internal names (atomic_add,
# textbuf_init, ...) without a clash, and the engine's own calls still
# reach the engine's functions (tests/cli/host.sh).
STATIC_LIB := $(BUILD)/libhybounce.a
STATIC_OBJ := $(BUILD)/libhybounce.o
# Paths under PREFIX are written relative to ${prefix} in hybounce.pc.
pc_rel      = $(patsubst $(PREFIX)/%,$${prefix}/%,$(1))
.PHONY: fuzz fuzzers fuzz-smoke

.PHONY: python bench-python
.PHONY: all run check check-asan unit deps bench install uninstall clean debug lint-man lib FORCE golden bench-docs figures

all: $(BIN) lib python $(REFBIN)

lib: $(STATIC_LIB) $(SHLIB) $(PCFILE)

$(BUILD)/src/core/%.o: src/core/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CORE_CFLAGS) $(CFLAGS) $(LIB_CFLAGS) -c $< -o $@
$(BUILD)/src/tui/%.o: src/tui/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Isrc/tui $(TUI_CFLAGS) $(CFLAGS) -c $< -o $@
$(BUILD)/src/cli/%.o: src/cli/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Isrc/tui $(CFLAGS) -c $< -o $@
$(BUILD)/tests/bench/%.o: tests/bench/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CORE_CFLAGS) $(CFLAGS) -c $< -o $@
$(BUILD)/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) -Isrc/tui $(CORE_CFLAGS) $(TEST_CFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/src/core/onset.o: CORE_CFLAGS += $(AUBIO_CFLAGS)
$(BUILD)/src/core/onset_aubio.o: CORE_CFLAGS += $(AUBIO_CFLAGS) \
    $(if $(AUBIO_SONAME),-DAUBIO_SONAME='"$(AUBIO_SONAME)"')
$(BUILD)/src/cli/sweep_hdf5.o: CPPFLAGS += $(HDF5_CFLAGS)
$(BUILD)/src/cli/sweep_hdf5_load.o: CPPFLAGS += $(HDF5_CFLAGS) \
    $(if $(HDF5_SONAME),-DHDF5_SONAME='"$(HDF5_SONAME)"')
$(BUILD)/src/cli/plot_cairo.o: CPPFLAGS += $(CAIRO_CFLAGS) \
    $(if $(CAIRO_SONAME),-DCAIRO_SONAME='"$(CAIRO_SONAME)"') \
    $(if $(PNG_SONAME),-DPNG_SONAME='"$(PNG_SONAME)"')

$(CORE_LIB): $(CORE_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^
$(STATIC_OBJ): $(CORE_OBJ)
	$(LD) -r -o $@.tmp $^ && objcopy --localize-hidden $@.tmp $@ && rm -f $@.tmp
$(STATIC_LIB): $(STATIC_OBJ)
	rm -f $@ && ar rcs $@ $^
# version.h: rewritten only when it changes (a new commit, a change to the
# working tree's state, a new VERSION), so that an unchanged tree rebuilds
# nothing; version.o and main.o, which include it, are rebuilt when it does.
$(VERSION_H): FORCE
	@mkdir -p $(@D)
	@sh tools/version.sh include/hybounce/version.h.in VERSION >$@.new && \
	    { cmp -s $@.new $@ && rm -f $@.new || mv $@.new $@; }
$(BUILD)/src/core/version.o $(BUILD)/src/cli/main.o $(BUILD)/src/cli/signals.o: $(VERSION_H)
# The objects are rebuilt when what is compiled into them changes: the
# library flags, or the preset folder of PREFIX (make PREFIX=/opt/x install
# after a plain make installs a program that looks in /opt/x).
BUILD_CONFIG := $(LIB_CFLAGS) $(VERSION) $(PREFIX) $(DATADIR) $(LIBDIR) $(INCLUDEDIR)
$(BUILD)/build-config: FORCE
	@mkdir -p $(@D)
	@echo '$(BUILD_CONFIG)' | cmp -s - $@ || echo '$(BUILD_CONFIG)' >$@
$(CORE_OBJ) $(TUI_OBJ) $(CLI_OBJ): $(BUILD)/build-config
FORCE:
# -Bsymbolic-functions: the library's calls to its own public functions bind
# inside it when it is linked, so that a host (or another library) that
# defines a function of the same name (hb_atomic_add, ...) does not redirect
# the engine's own calls to it; the internal functions are hidden, bound
# inside already.  Chosen over protected visibility on the public
# declarations, which makes the linker refuse (or copy-relocate) a host's
# reference to a public object and is treated unevenly by compilers; what
# it costs: a host's &hb_f and the library's own may differ, and the API
# compares no function pointers with public functions.
$(SHLIB): $(CORE_OBJ)
	$(CC) -shared $(LDFLAGS) -Wl,-soname,$(SHLIB_SO) -Wl,--no-undefined -Wl,-Bsymbolic-functions \
	    -o $@ $^ $(CORE_LIBS) $(AUBIO_LIBS)
$(PCFILE): hybounce.pc.in $(BUILD)/build-config
	@mkdir -p $(@D)
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(call pc_rel,$(LIBDIR))|' \
	    -e 's|@INCLUDEDIR@|$(call pc_rel,$(INCLUDEDIR))|' -e 's|@VERSION@|$(VERSION)|' $< >$@
$(TUI_LIB): $(TUI_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BIN): $(CLI_OBJ) $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(CLI_OBJ) $(TUI_LIB) $(CORE_LIB) $(BIN_LIBS) $(AUBIO_LIBS)

# The figure model of hybounce plot (no plotting library) is unit-tested too;
# its renderer comes along, as the explorer saves figures through it (src/tui/figure.c).
UNIT_CLI_OBJ := $(BUILD)/src/cli/plot_model.o $(BUILD)/src/cli/plot_map.o $(BUILD)/src/cli/plot_draw.o $(BUILD)/src/cli/plot_cairo.o
$(UNIT): $(TEST_OBJ) $(UNIT_CLI_OBJ) $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(TEST_OBJ) $(UNIT_CLI_OBJ) $(TUI_LIB) $(CORE_LIB) $(TEST_LIBS) $(TUI_LIBS) $(CORE_LIBS) $(AUBIO_LIBS)

$(BENCHBIN): $(BENCH_OBJ) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(BENCH_OBJ) $(CORE_LIB) $(CORE_LIBS)

# Written from the paper alone: no engine code, binary128 (libquadmath, part of gcc).
$(REFBIN): tests/reference/ref.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $< -lquadmath

# Rewrites the cached reference tables (tests/reference/STUDY.csv, tolerance
# 1e-28) and shows their own error: each must agree with a run at 1e-24 to
# 1e-20 (tests/reference/agree.py); about 15 s.
.PHONY: reference
reference: $(REFBIN)
	@set -e; for s in $(REF_STUDIES); do \
	    ./$(REFBIN) $$s --tol 1e-28 >tests/reference/$$s.csv; \
	    ./$(REFBIN) $$s --tol 1e-24 >$(BUILD)/ref-$$s-1e-24.csv; \
	    echo "$$s: the reference at 1e-24 against 1e-28 (largest error per column):"; \
	    $(PYTHON) tests/reference/agree.py --limit 1e-20 tests/reference/$$s.csv \
	        $(BUILD)/ref-$$s-1e-24.csv | tr '\n' ' '; echo; \
	done

# The Python package (python/hybounce: cffi's ABI mode over libhybounce.so).
# Its declarations (_cdef.py) are generated from the public headers by
# python/gen_cdef.py, with where to find the library: the build tree's
# libhybounce.so for $(BUILD)/python (PYTHONPATH=$(BUILD)/python), the
# soname then LIBDIR for the installed package; and the soname of the
# libgsl the library links (the package turns GSL's error handler off).
# Installed in PYTHONDIR: Debian's python3 finds /usr/lib/python3/dist-packages
# and /usr/local/lib/python3.X/dist-packages.
PYTHON    ?= /usr/bin/python3
PY_VER     = $(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])')
PYTHONDIR ?= $(if $(filter /usr,$(PREFIX)),/usr/lib/python3/dist-packages,$(PREFIX)/lib/python$(PY_VER)/dist-packages)
PY_SRC    := $(sort $(wildcard python/hybounce/*.py))
PY_PKG    := $(BUILD)/python/hybounce
GSL_NEEDED = $$(objdump -p $(SHLIB) | sed -n 's/^ *NEEDED *\(libgsl\.so[.0-9]*\)$$/\1/p')
python: $(PY_PKG)/_cdef.py
$(PY_PKG)/_cdef.py: python/gen_cdef.py $(PY_SRC) $(PUBLIC_H) $(SHLIB)
	@rm -rf $(PY_PKG) && mkdir -p $(PY_PKG) && cp $(PY_SRC) $(PY_PKG)/
	$(PYTHON) python/gen_cdef.py $@ --lib $(abspath $(SHLIB)) --gsl "$(GSL_NEEDED)" \
	    --soversion $(SOVERSION) -- $(PUBLIC_H)

# A 1,000-point sweep from Python and the same sweep from hybounce sweep,
# alternated in one run (report in build/bench/python.txt).
bench-python: deps
	@$(MAKE) --no-print-directory all
	@mkdir -p $(BUILD)/bench
	@PYTHONPATH=$(BUILD)/python $(PYTHON) tests/bench/python_sweep.py $(BIN) | tee $(BUILD)/bench/python.txt

# The figure targets (tests/bench/figures.sh): a figure of each paper study
# against its batch run, whole processes side by side (hyperfine), and the
# size of a 1600x1200 PNG.
.PHONY: bench-figures
bench-figures: $(BIN)
	@mkdir -p $(BUILD)/bench
	@HYBOUNCE_PRESETS=$(CURDIR)/presets sh tests/bench/figures.sh $(BIN) | tee $(BUILD)/bench/figures.md

# The generated parts of the man page and the README (tools/gendoc.c):
# `make docs` rewrites them; tests/cli/docs.sh fails when they are stale.
GENDOC    := $(BUILD)/hybounce-gendoc
.PHONY: docs
all: $(GENDOC)
$(BUILD)/tools/%.o: tools/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CORE_CFLAGS) $(CFLAGS) -c $< -o $@
$(GENDOC): $(BUILD)/tools/gendoc.o $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(BUILD)/tools/gendoc.o $(CORE_LIB) $(CORE_LIBS)
docs: $(GENDOC)
	./$(GENDOC) man/hybounce.1 README.md

# Installs the Debian packages that are missing (as root, or through sudo).
deps:
	@missing=""; for p in $(APT_PACKAGES); do \
	    dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	    echo "hybounce: installing missing Debian packages:$$missing"; \
	    if [ "$$(id -u)" = 0 ]; then SUDO=; elif command -v sudo >/dev/null; then SUDO=sudo; \
	    else echo "hybounce: run as root: apt-get install$$missing" >&2; exit 1; fi; \
	    $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	    $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null \
	    || { echo "hybounce: apt-get install$$missing failed" >&2; exit 1; }; \
	fi
	@for l in $(TEST_LOCALES); do \
	    locale -a 2>/dev/null | grep -qix "$$l.utf-\?8" && continue; \
	    echo "hybounce: generating the locale $$l.UTF-8 (the tests run under it)"; \
	    if [ "$$(id -u)" = 0 ]; then SUDO=; elif command -v sudo >/dev/null; then SUDO=sudo; \
	    else echo "hybounce: run as root: localedef -i $$l -f UTF-8 $$l.UTF-8" >&2; exit 1; fi; \
	    $$SUDO localedef -i $$l -f UTF-8 $$l.UTF-8; \
	    locale -a 2>/dev/null | grep -qix "$$l.utf-\?8" \
	    || { echo "hybounce: localedef -i $$l -f UTF-8 $$l.UTF-8 failed" >&2; exit 1; }; \
	done

run: deps
	@$(MAKE) --no-print-directory all
	./$(BIN)

unit: $(UNIT)

# Every test: the Criterion unit tests, then the command-line and explorer
# tests (tmux); ends with "N passed, N failed".
check: deps
	@$(MAKE) --no-print-directory all unit fuzzers
	@HYBOUNCE_FUZZ_SMOKE="$(FUZZ_RUNS) $(FUZZ_BINS)" sh tests/run.sh $(BIN) $(UNIT)

check-asan: deps
	@$(MAKE) --no-print-directory BUILD=build-asan SAN=address,undefined OPT=-O1 all unit
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	    sh tests/run.sh build-asan/hybounce build-asan/unit-tests

# libFuzzer harnesses (tests/fuzz/fuzz_*.c), built with clang against the
# engine's sources with ASan + UBSan (float-cast-overflow included), always
# in build/fuzz.  `make fuzz` is the long campaign: FUZZ_TIME seconds per
# harness (default 60), corpus grown in build/fuzz/corpus/NAME from the seeds
# in tests/fuzz/corpus and presets/, findings (crash-*, leak-*, timeout-*) left in
# build/fuzz/findings/.  `make fuzz-smoke` (also the last step of make check's tests/run.sh, counted in its summary)
# runs each harness FUZZ_RUNS times (default 100000; fuzz_run, a simulation per input, a fifth of that), from its seeds.
FUZZ_CC    ?= clang
FUZZ_TIME  ?= 60
FUZZ_RUNS  ?= 100000
FUZZ_DIR   := build/fuzz
FUZZ_SAN   := -fsanitize=address,undefined,float-cast-overflow \
              -fno-sanitize-recover=undefined,float-cast-overflow -fno-omit-frame-pointer
FUZZ_FLAGS := -g -O1 -std=c17 -Wall -Wextra -MMD -MP $(FUZZ_SAN)
FUZZ_SRC   := $(sort $(wildcard tests/fuzz/fuzz_*.c))
FUZZ_BINS  := $(FUZZ_SRC:tests/fuzz/%.c=$(FUZZ_DIR)/%)
FUZZ_OBJ   := $(CORE_SRC:%.c=$(FUZZ_DIR)/obj/%.o)
# kept: not intermediate files that make would delete after linking
.SECONDARY: $(FUZZ_OBJ)
$(FUZZ_DIR)/obj/src/core/version.o: $(VERSION_H)

$(FUZZ_DIR)/obj/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CPPFLAGS) $(CORE_CFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_DIR)/%: tests/fuzz/%.c tests/fuzz/fuzz.h $(FUZZ_OBJ)
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CPPFLAGS) $(CORE_CFLAGS) $(FUZZ_FLAGS) -fsanitize=fuzzer -o $@ $< \
	    $(FUZZ_OBJ) $(CORE_LIBS) $(AUBIO_LIBS)

fuzzers: $(FUZZ_BINS)

fuzz: deps
	@$(MAKE) --no-print-directory fuzzers
	@sh tests/fuzz/run.sh campaign $(FUZZ_TIME) $(FUZZ_BINS)

fuzz-smoke: deps
	@$(MAKE) --no-print-directory fuzzers
	@sh tests/fuzz/run.sh smoke $(FUZZ_RUNS) $(FUZZ_BINS)

debug:
	@$(MAKE) --no-print-directory BUILD=build-debug OPT=-O0 CFLAGS='-g3' all

bench: deps
	@$(MAKE) --no-print-directory $(BENCHBIN)
	@mkdir -p $(BUILD)/bench
	./$(BENCHBIN) --out $(BUILD)/bench
	@sh tests/bench/study-table.sh $(BUILD)/bench/work-precision.csv >$(BUILD)/bench/study-table.md
	@echo "per-study table (docs/speed-and-accuracy.md): $(BUILD)/bench/study-table.md"
	@sh tests/bench/studies.sh $(BIN) $(BUILD)/bench/studies.md

# Per paper study: instructions per rhs (callgrind), rhs, rejected steps,
# engine CPU time beside SciPy DOP853's, the true error against
# tests/reference and the largest --error bar (build/bench/studies.md; a
# minute; make bench runs it too, make bench-docs puts it in the README).
.PHONY: bench-studies
bench-studies: $(BIN)
	@mkdir -p $(BUILD)/bench
	@sh tests/bench/studies.sh $(BIN) $(BUILD)/bench/studies.md

# Every offered stepper's true error against the binary128 reference
# (tests/reference/) at rtol 1e-6 ... 1e-12, and its ratio to rk8pd's:
# the table goes into tests/bench/REPORT.md (STEPPERS markers); a minute or two.
.PHONY: bench-steppers
bench-steppers: $(BIN)
	@mkdir -p $(BUILD)/bench
	@sh tests/bench/steppers.sh $(BIN) $(BUILD)/bench/steppers.md
	@. tests/tui/readme.inc && { echo; cat $(BUILD)/bench/steppers.md; echo; } | \
	    readme_splice tests/bench/REPORT.md STEPPERS && echo "tests/bench/REPORT.md (STEPPERS) written"

# A chain's work in counts (tests/bench/chains.sh, callgrind): a 5-ball touching
# cradle, the stacked-drop preset, a 100-bead chain over its wave's crossing, the cost of a step at
# N = 10, 100, 1000; the table goes into tests/bench/REPORT.md (CHAINS markers).
.PHONY: bench-chains
bench-chains: $(BIN)
	@mkdir -p $(BUILD)/bench
	@sh tests/bench/chains.sh $(BIN) $(BUILD)/bench/chains.md
	@. tests/tui/readme.inc && { echo; cat $(BUILD)/bench/chains.md; echo; } | \
	    readme_splice tests/bench/REPORT.md CHAINS && echo "tests/bench/REPORT.md (CHAINS) written"

# After make bench: the per-study table into docs/speed-and-accuracy.md, and tests/bench/REPORT.md.
bench-docs:
	@sh tests/bench/report.sh $(BUILD)/bench

# Rewrites the golden collision tables (tests/golden/*.csv) from this engine:
# only after a change meant to move the numbers; review the diff (tests/test_golden.c).
golden: $(UNIT)
	@mkdir -p tests/golden
	HYBOUNCE_GOLDEN_WRITE=1 ./$(UNIT) --filter 'golden/paper_presets_reproduce_their_collision_tables'

lint-man:
	mandoc -Tlint -W warning man/hybounce.1

# Calls among the files of the engine, the explorer and the command line
# point one way: no file calls, through others, back into itself
# (tests/cli/calls.sh, part of make check; tests/cli/calls.allow lists the
# files still in a cycle).
.PHONY: lint-cycles
lint-cycles: $(BIN)
	@HYBOUNCE_BIN=$(BIN) sh tests/cli/calls.sh

install: $(BIN) lib
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(MANPREFIX)/man1 $(DESTDIR)$(DATADIR)/presets
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/hybounce
	install -m 644 man/hybounce.1 $(DESTDIR)$(MANPREFIX)/man1/hybounce.1
	install -m 644 presets/*.preset $(DESTDIR)$(DATADIR)/presets/
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCLUDEDIR)/hybounce $(DESTDIR)$(PKGCONFIGDIR)
	install -m 755 $(SHLIB) $(DESTDIR)$(LIBDIR)/
	ln -sf libhybounce.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SHLIB_SO)
	ln -sf $(SHLIB_SO) $(DESTDIR)$(LIBDIR)/libhybounce.so
	install -m 644 $(STATIC_LIB) $(DESTDIR)$(LIBDIR)/libhybounce.a
	install -m 644 $(PUBLIC_H) $(DESTDIR)$(INCLUDEDIR)/hybounce/
	install -m 644 $(PCFILE) $(DESTDIR)$(PKGCONFIGDIR)/hybounce.pc
	install -d $(DESTDIR)$(PYTHONDIR)/hybounce
	install -m 644 $(PY_SRC) $(DESTDIR)$(PYTHONDIR)/hybounce/
	$(PYTHON) python/gen_cdef.py $(DESTDIR)$(PYTHONDIR)/hybounce/_cdef.py --lib $(SHLIB_SO) \
	    --lib $(LIBDIR)/$(SHLIB_SO) --gsl "$(GSL_NEEDED)" --soversion $(SOVERSION) -- $(PUBLIC_H)
	@if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" = 0 ] && command -v ldconfig >/dev/null; then ldconfig; fi

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/hybounce $(DESTDIR)$(MANPREFIX)/man1/hybounce.1
	rm -f $(DESTDIR)$(DATADIR)/presets/*.preset
	-rmdir $(DESTDIR)$(DATADIR)/presets $(DESTDIR)$(DATADIR)
	rm -f $(DESTDIR)$(LIBDIR)/libhybounce.so.$(VERSION) $(DESTDIR)$(LIBDIR)/$(SHLIB_SO) \
	      $(DESTDIR)$(LIBDIR)/libhybounce.so $(DESTDIR)$(LIBDIR)/libhybounce.a \
	      $(DESTDIR)$(PKGCONFIGDIR)/hybounce.pc
	rm -f $(addprefix $(DESTDIR)$(INCLUDEDIR)/hybounce/,$(notdir $(PUBLIC_H)))
	-rmdir $(DESTDIR)$(INCLUDEDIR)/hybounce
	rm -f $(addprefix $(DESTDIR)$(PYTHONDIR)/hybounce/,$(notdir $(PY_SRC)) _cdef.py)
	rm -rf $(DESTDIR)$(PYTHONDIR)/hybounce/__pycache__
	-rmdir $(DESTDIR)$(PYTHONDIR)/hybounce

clean:
	rm -rf build build-asan build-debug

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# The sweep's threads under ThreadSanitizer (build-tsan/): the engine's
# writable statics and the same point on many threads at once
# (tests/cli/sweep_reentrant.sh, which make check runs on the plain build);
# then 16 threads loading and running every shipped preset at once
# (tests/host/preset_threads.c, linked with the installable libhybounce.a).
.PHONY: check-tsan
PRESET_THREADS := $(BUILD)/preset-threads
$(PRESET_THREADS): tests/host/preset_threads.c $(STATIC_LIB)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ $< $(STATIC_LIB) $(CORE_LIBS) $(AUBIO_LIBS)
check-tsan: deps
	@$(MAKE) --no-print-directory BUILD=build-tsan SAN=thread OPT=-O1 all build-tsan/preset-threads
	@TSAN_OPTIONS=halt_on_error=1:exitcode=66 HYBOUNCE_BIN=$(CURDIR)/build-tsan/hybounce \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets sh tests/cli/sweep_reentrant.sh | tee build-tsan/tsan.log; \
	TSAN_OPTIONS=halt_on_error=1:exitcode=66 HYBOUNCE_PRESETS=$(CURDIR)/presets \
	    build-tsan/preset-threads 16 >build-tsan/preset-threads.log 2>&1; rc=$$?; \
	    cat build-tsan/preset-threads.log | tee -a build-tsan/tsan.log; \
	    [ $$rc -eq 0 ] || echo "not ok - preset-threads 16 exits $$rc (build-tsan/preset-threads.log)" | \
	    tee -a build-tsan/tsan.log; \
	    ! grep -q '^not ok' build-tsan/tsan.log

# The sweep's speed targets: efficiency at 1, 2, 4 ... jobs up to the online
# processors beside as many independent processes, overhead per point in
# instructions (valgrind's callgrind), memory per point of a 100,000-point
# sweep (report in build/bench/sweep.txt; a few minutes).
.PHONY: bench-sweep
bench-sweep: deps
	@$(MAKE) --no-print-directory all
	@sh tests/bench/sweep.sh $(BIN) $(BUILD)/bench

# The explorer's frame against the arc's length (study 1 at run.T = 66 s and
# 730 s, about 25k and 250k samples): instructions a frame drawn
# (callgrind), playback's share of a core, computing while drawing against
# --batch (tests/bench/tui_frame.sh; report in build/bench/tui.txt; a few
# minutes; needs valgrind and tmux).
.PHONY: bench-tui
bench-tui: deps
	@$(MAKE) --no-print-directory all
	@mkdir -p $(BUILD)/bench
	@sh tests/bench/tui_frame.sh $(CURDIR)/$(BIN) | tee $(BUILD)/bench/tui.txt

# The engine side by side with the paper's own method (SciPy DOP853, rtol
# 1e-11, atol 1e-14: tests/bench/scipy_ref.py) on the five paper studies,
# report in build/bench/scipy.md (a few minutes).  Not part of make check:
# it needs Debian's python3-scipy (make deps-scipy installs it).
.PHONY: bench-scipy deps-scipy
bench-scipy: deps
	@$(MAKE) --no-print-directory all
	@sh tests/bench/scipy.sh $(BIN) $(BUILD)/bench

deps-scipy:
	@$(MAKE) --no-print-directory deps APT_PACKAGES='python3-scipy python3-numpy hyperfine'

# The explorer's key lists in the man page and the README, one per mode,
# generated from the modes' key tables (src/tui/modes.c lists the modes)
# between the KEYS-BEGIN and KEYS-END markers; tests/test_tui_keys.c fails
# when they differ.  The modes bring the explorer along (and its figures).
GENKEYS := $(BUILD)/gen-keys
$(GENKEYS): $(BUILD)/tests/gen_keys.o $(UNIT_CLI_OBJ) $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(BUILD)/tests/gen_keys.o $(UNIT_CLI_OBJ) $(TUI_LIB) $(CORE_LIB) $(TUI_LIBS) $(CORE_LIBS) $(AUBIO_LIBS)
.PHONY: keys-doc
keys-doc: $(GENKEYS)
	$(GENKEYS) man > $(BUILD)/keys.man
	$(GENKEYS) md > $(BUILD)/keys.md
	awk -v f=$(BUILD)/keys.man '/^\.\\" KEYS-END/ { while ((getline l < f) > 0) print l; skip = 0 } \
	    skip { next } /^\.\\" KEYS-BEGIN/ { print; skip = 1; next } { print }' man/hybounce.1 > $(BUILD)/hybounce.1.new
	mv $(BUILD)/hybounce.1.new man/hybounce.1
	awk -v f=$(BUILD)/keys.md '/^<!-- KEYS-END -->/ { while ((getline l < f) > 0) print l; skip = 0 } \
	    skip { next } /^<!-- KEYS-BEGIN -->/ { print; skip = 1; next } { print }' README.md > $(BUILD)/README.md.new
	mv $(BUILD)/README.md.new README.md
docs: keys-doc

# The README's explorer screens (the plots, the space-time view) and batch example, from real runs
# (tests/tui/readme.inc); tests/tui/readme.sh fails when they are stale.
.PHONY: readme-examples
readme-examples: $(BIN)
	. tests/tui/readme.inc && readme_screen $(abspath $(BIN)) | readme_splice README.md SCREEN \
	    && readme_batch $(abspath $(BIN)) | readme_splice README.md BATCH \
	    && readme_spacetime $(abspath $(BIN)) | readme_splice README.md SPACETIME
docs: readme-examples

# The README's figures (docs/figures/*.png), drawn by hybounce plot from the
# paper's three studies: the state against t and the observables per
# collision of each, the hysteresis loops of the first; 150 dpi at a
# journal column's width.  Then the --plot of sweep (e against law.c; a
# heat map over law.c and law.alpha) and fit (examples/fit/bounces.csv),
# at their default 300 dpi; two runs of the first study compared.
FIGURES := docs/figures
figures: $(BIN)
	@mkdir -p $(FIGURES)
	@for p in steel-on-bitumen ptfe-pom permanent-contact-bwmcl; do \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) plot $$p --dpi 150 --out $(FIGURES)/$$p-state.png && \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) plot $$p --kind observables --dpi 150 \
	        --out $(FIGURES)/$$p-observables.png || exit 1; \
	done
	@HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) plot steel-on-bitumen --kind loop --collisions 0,1,2,4 \
	    --dpi 150 --out $(FIGURES)/steel-on-bitumen-loop.png
	@rm -rf $(BUILD)/figures && mkdir -p $(BUILD)/figures && \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) sweep steel-on-bitumen --vary law.c=1e3:1e5:17:log \
	        --out $(BUILD)/figures/c -q --plot $(FIGURES)/sweep-law-c.png && \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) sweep steel-on-bitumen --vary law.c=1e3:1e5:13:log \
	        --vary law.alpha=0.1:0.7:13 --set run.T=0.1 --out $(BUILD)/figures/c-alpha -q \
	        --plot $(FIGURES)/sweep-law-c-alpha.png && \
	    HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) fit steel-on-bitumen --data examples/fit/bounces.csv \
	        --free law.c,law.alpha -q --out $(BUILD)/figures/fit.preset \
	        --plot $(FIGURES)/fit-bounces.png >/dev/null
	@HYBOUNCE_PRESETS=$(CURDIR)/presets ./$(BIN) plot steel-on-bitumen --variant law.c=2000 \
	    --variant law.c=20000 --set run.T=0.3 --dpi 150 --out $(FIGURES)/compare-law-c.png

# The pgfplots source of hybounce plot compiled with pdflatex
# (tests/tex/check.sh): not part of make check, TeX Live being heavy;
# make deps-tex installs texlive-pictures (pgfplots) and texlive-latex-base.
.PHONY: check-tex deps-tex
check-tex: $(BIN)
	@HYBOUNCE_BIN=$(CURDIR)/$(BIN) HYBOUNCE_PRESETS=$(CURDIR)/presets sh tests/tex/check.sh

deps-tex:
	@$(MAKE) --no-print-directory deps APT_PACKAGES='texlive-pictures texlive-latex-base'
