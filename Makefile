# hybounce - plain Makefile (GNU make).
#
#   make            build build/hybounce
#   make run        install missing packages, build, open the explorer on the default preset
#   make check      install missing packages, build, run every test
#   make check-asan the unit tests under AddressSanitizer + UBSan
#   make bench      the work-precision benchmark (report in build/bench/)
#   make install / uninstall   honour PREFIX, DESTDIR, MANPREFIX
#   make SAN=address,undefined   any target with sanitizers
#   make debug      -O0 -g3

VERSION   := 0.1.0
PREFIX    ?= /usr/local
MANPREFIX ?= $(PREFIX)/share/man
DATADIR   ?= $(PREFIX)/share/hybounce
CC        ?= gcc
PKG_CONFIG ?= pkg-config

# Debian packages the build and the tests use (apt-get names).
APT_PACKAGES := libgsl-dev libncurses-dev libinih-dev libcriterion-dev pkg-config tmux mandoc \
                clang libclang-rt-14-dev strace parallel slurm-wlm munge \
                libaubio-dev aubio-tools sox

BUILD     ?= build
OPT       ?= -O2
WARN      := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
             -Wwrite-strings -Wformat=2 -Wundef
ifdef WERROR
WARN      += -Werror
endif
ifdef SAN
SANFLAGS  := -fsanitize=$(SAN) -fno-omit-frame-pointer -fno-sanitize-recover=undefined
endif

CURSES_PC := $(shell $(PKG_CONFIG) --exists ncursesw 2>/dev/null && echo ncursesw || echo ncurses)
CORE_CFLAGS := $(shell $(PKG_CONFIG) --cflags gsl inih 2>/dev/null)
CORE_LIBS   := $(shell $(PKG_CONFIG) --libs gsl inih 2>/dev/null) -lm
# ncursesw's pkg-config adds -D_XOPEN_SOURCE=600, which would redefine ours (700).
TUI_CFLAGS  := $(filter-out -D_XOPEN_SOURCE=%,$(shell $(PKG_CONFIG) --cflags $(CURSES_PC) 2>/dev/null))
TUI_LIBS    := $(shell $(PKG_CONFIG) --libs $(CURSES_PC) 2>/dev/null)
TEST_CFLAGS := $(shell $(PKG_CONFIG) --cflags criterion 2>/dev/null)
TEST_LIBS   := $(shell $(PKG_CONFIG) --libs criterion 2>/dev/null)

CPPFLAGS  += -Iinclude -Iinclude/hybounce -Isrc/core -DHYBOUNCE_VERSION='"$(VERSION)"' \
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
CORE_LIB  := $(BUILD)/libhybounce.a
TUI_LIB   := $(BUILD)/libhybounce-tui.a
BIN       := $(BUILD)/hybounce
UNIT      := $(BUILD)/unit-tests
BENCHBIN  := $(BUILD)/hybounce-bench

.PHONY: all run check check-asan unit deps bench install uninstall clean debug lint-man

all: $(BIN)

$(BUILD)/src/core/%.o: src/core/%.c
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CORE_CFLAGS) $(CFLAGS) -c $< -o $@
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

$(CORE_LIB): $(CORE_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^
$(TUI_LIB): $(TUI_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BIN): $(CLI_OBJ) $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(CLI_OBJ) $(TUI_LIB) $(CORE_LIB) $(TUI_LIBS) $(CORE_LIBS)

$(UNIT): $(TEST_OBJ) $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(TEST_OBJ) $(TUI_LIB) $(CORE_LIB) $(TEST_LIBS) $(TUI_LIBS) $(CORE_LIBS)

$(BENCHBIN): $(BENCH_OBJ) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(BENCH_OBJ) $(CORE_LIB) $(CORE_LIBS)

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

run: deps
	@$(MAKE) --no-print-directory all
	./$(BIN)

unit: $(UNIT)

# Every test: the Criterion unit tests, then the command-line and explorer
# tests (tmux); ends with "N passed, N failed".
check: deps
	@$(MAKE) --no-print-directory all unit
	@sh tests/run.sh $(BIN) $(UNIT)

check-asan: deps
	@$(MAKE) --no-print-directory BUILD=build-asan SAN=address,undefined OPT=-O1 all unit
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    sh tests/run.sh build-asan/hybounce build-asan/unit-tests

debug:
	@$(MAKE) --no-print-directory BUILD=build-debug OPT=-O0 CFLAGS='-g3' all

bench: deps
	@$(MAKE) --no-print-directory $(BENCHBIN)
	@mkdir -p $(BUILD)/bench
	./$(BENCHBIN) --out $(BUILD)/bench

lint-man:
	mandoc -Tlint -W warning man/hybounce.1

install: $(BIN)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(MANPREFIX)/man1 $(DESTDIR)$(DATADIR)/presets
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/hybounce
	install -m 644 man/hybounce.1 $(DESTDIR)$(MANPREFIX)/man1/hybounce.1
	install -m 644 presets/*.preset $(DESTDIR)$(DATADIR)/presets/

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/hybounce $(DESTDIR)$(MANPREFIX)/man1/hybounce.1
	rm -f $(DESTDIR)$(DATADIR)/presets/*.preset
	-rmdir $(DESTDIR)$(DATADIR)/presets $(DESTDIR)$(DATADIR)

clean:
	rm -rf build build-asan build-debug

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# The explorer's key list in the man page and the README, generated from the
# key table (src/tui/keys.c) between the KEYS-BEGIN and KEYS-END markers;
# tests/test_tui_keys.c fails when they differ.
GENKEYS := $(BUILD)/gen-keys
$(GENKEYS): $(BUILD)/tests/gen_keys.o $(TUI_LIB) $(CORE_LIB)
	$(CC) $(LDFLAGS) -o $@ $(BUILD)/tests/gen_keys.o $(TUI_LIB) $(CORE_LIB) $(TUI_LIBS) $(CORE_LIBS)
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

# The README's explorer screen and batch example, from real runs
# (tests/tui/readme.inc); tests/tui/readme.sh fails when they are stale.
.PHONY: readme-examples
readme-examples: $(BIN)
	. tests/tui/readme.inc && readme_screen $(abspath $(BIN)) | readme_splice README.md SCREEN \
	    && readme_batch $(abspath $(BIN)) | readme_splice README.md BATCH
docs: readme-examples
