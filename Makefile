# hylc -- homogenized yarn-level cloth.  One GNU Makefile; see README.md.
#   make            build libhylc, the programs (build/bin), unit tests and benchmarks
#   make test       install missing dependencies, build, run all tests (ends with "N passed, N failed")
#   make demo       install missing dependencies, build, run the main job on a built-in default
#   make bench      build and run the benchmarks (prints measured figures)
#   make fabric-sheet  build, run hylc-cloth's virtual tests on the paper's tables (and FABRIC_TABLES="NAME=PATH ...")
#   make fidelity   build, make the default table of every paper and generated pattern and write
#                   docs/fabric-fidelity.md: each table against its own yarn tile (hours; resumable)
#                   and write docs/fabric-sheet.md (tools/fabric_sheet.py, about 40 min on 2 cores)
#   make install    PREFIX=/usr/local DESTDIR=: headers, libraries, programs, pkg-config files, docs
#   make uninstall  remove every installed file (from the manifest written by install)
#   make deps       install missing system packages (apt; as root or with sudo)
#   make format     clang-format the sources; `make check-format` fails on any unformatted source
#   make fuzz       build the libFuzzer harnesses (clang) and run each FUZZ_SECONDS (default 60) s
#   ASAN=1          build into build-asan with -fsanitize=address,undefined; `make test ASAN=1` runs the
#                   tests there (docs/testing.md); `make test-asan` runs the unit tests only
#   COVERAGE=1      build into build-cov with gcov instrumentation; `make coverage` runs the tests there
#                   (COVERAGE_TESTS: arguments of tests/run.sh, e.g. --unit) and prints line coverage per stage
#   V=1             show full command lines

.SUFFIXES:
.SECONDARY:
.DEFAULT_GOAL := all
SHELL := /bin/bash

ifeq ($(ASAN),1)
  BUILD ?= build-asan
  SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
else ifeq ($(COVERAGE),1)
  BUILD ?= build-cov
  SAN_FLAGS := --coverage
  SAN_LIBS  := -lgcov
  OPT ?= -O0 -g
else
  BUILD ?= build
  SAN_FLAGS :=
endif
OBJ     := $(BUILD)/obj
# nettle: SHA-256 of the run identities (src/sys/sha256.c); yaml-0.1: libyaml, the check of YAML options
# files (src/sys/yamlcheck.c). Every program loads both through PETSc and HDF5 already.
PKGS    := petsc hdf5-openmpi nettle yaml-0.1
NOCHECK_GOALS := deps test test-asan coverage check-format demo clean format help distclean bench-run fuzz fuzz-build fuzz-deps hylcmat uninstall
PETSC_OK := $(shell pkg-config --exists $(PKGS) 2>/dev/null && echo yes)

ifeq ($(filter $(NOCHECK_GOALS),$(MAKECMDGOALS)),)
  ifneq ($(PETSC_OK),yes)
    $(error PETSc/HDF5/nettle/libyaml development files were not found by pkg-config ($(PKGS)). Install them with 'make deps' (runs config/install-deps.sh), or run 'make test' / 'make demo', which install them first)
  endif
endif

ifeq ($(PETSC_OK),yes)
  CC      := $(shell pkg-config --variable=ccompiler petsc)
  PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS))
  PKG_LIBS   := $(shell pkg-config --libs $(PKGS))
endif
OPT      ?= -O2 -g
CFLAGS   ?= $(OPT)
CFLAGS   += -Wall -Wextra -std=c11 -D_DEFAULT_SOURCE -fPIC -Iinclude $(PKG_CFLAGS) -MMD -MP $(SAN_FLAGS)
LDFLAGS  += $(SAN_FLAGS)
LDLIBS   := $(PKG_LIBS) -lmetis -llapack -lm $(SAN_LIBS)

ifeq ($(V),1)
  Q :=
else
  Q := @
endif

LIB_SRC   := $(sort $(wildcard src/*/*.c))
LIB_SRC   := $(filter-out src/apps/%,$(LIB_SRC))
LIB_OBJ   := $(LIB_SRC:%.c=$(OBJ)/%.o)
LIB       := $(BUILD)/libhylc.a
SOLIB     := $(BUILD)/libhylc.so
APP_SRC   := $(sort $(wildcard src/apps/*.c))
APPS      := $(APP_SRC:src/apps/%.c=$(BUILD)/bin/%)
TEST_SRC  := $(sort $(wildcard tests/unit/*.c))
TESTS     := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)
BENCH_SRC := $(sort $(wildcard tests/bench/*.c))
BENCHES   := $(BENCH_SRC:tests/bench/%.c=$(BUILD)/bench/%)
REPLAY_SRC := $(sort $(wildcard tests/fuzz/fuzz_*.c))
REPLAYS   := $(REPLAY_SRC:tests/fuzz/%.c=$(BUILD)/fuzz/%)
EX_SRC    := $(sort $(wildcard examples/*.c))
EXAMPLES  := $(EX_SRC:examples/%.c=$(BUILD)/ex/%)
SUPPORT_SRC := $(sort $(wildcard tests/support/*.c))
SUPPORT_LIB := $(BUILD)/libhylc-testsupport.a
ALL_OBJ   := $(LIB_OBJ) $(SUPPORT_SRC:%.c=$(OBJ)/%.o) $(patsubst src/%.c,$(BUILD)/hylcmat/%.o,$(wildcard src/hylcmat/*.c) src/sys/json.c src/sys/strain.c src/sys/h5util.c) $(APP_SRC:%.c=$(OBJ)/%.o) $(TEST_SRC:%.c=$(OBJ)/%.o) $(REPLAY_SRC:%.c=$(OBJ)/%.o) $(OBJ)/tests/fuzz/replay.o $(BENCH_SRC:%.c=$(OBJ)/%.o) $(EX_SRC:%.c=$(OBJ)/%.o)

.PHONY: all lib apps tests benches examples test test-asan coverage check-format demo bench fabric-sheet fidelity deps format clean help fuzz fuzz-build fuzz-deps hylcmat install uninstall
all: lib hylcmat apps tests benches examples
lib: $(LIB) $(SOLIB)
apps: $(APPS)
tests: $(TESTS) $(REPLAYS)
benches: $(BENCHES)
examples: $(EXAMPLES)

# The build identity in every sampling run's identity (src/samples/identity.c, docs/output-format.md):
# `git describe --always --dirty` of the checkout, "unknown" outside one. $(BUILD)/build-id changes only
# when it does, and identity.o is rebuilt then.
HYLC_BUILD_ID := $(shell git -C $(CURDIR) describe --always --dirty 2>/dev/null || echo unknown)
BUILD_ID_FILE := $(BUILD)/build-id
ifeq ($(filter clean help,$(MAKECMDGOALS)),)
  $(shell mkdir -p $(BUILD); [ "$$(cat $(BUILD_ID_FILE) 2>/dev/null)" = "$(HYLC_BUILD_ID)" ] || echo "$(HYLC_BUILD_ID)" > $(BUILD_ID_FILE))
endif
$(OBJ)/src/samples/identity.o: CFLAGS += -DHYLC_BUILD_ID='"$(HYLC_BUILD_ID)"'
$(OBJ)/src/samples/identity.o: $(BUILD_ID_FILE)
# and in -version of every program (src/sys/version.c)
$(OBJ)/src/sys/version.o: CFLAGS += -DHYLC_BUILD_ID='"$(HYLC_BUILD_ID)"'
$(OBJ)/src/sys/version.o: $(BUILD_ID_FILE)

# the Cholesky kernels and solves: GCC's -O2 vectorizes only loops it needs no run-time alias check for;
# the dynamic cost model lets it version the solves' loops (about 2x on them, results bitwise unchanged:
# docs/performance.md). Only where the compiler knows the flag.
VECT_FLAGS := $(shell $(CC) -fvect-cost-model=dynamic -E -x c /dev/null >/dev/null 2>&1 && echo -fvect-cost-model=dynamic)
$(OBJ)/src/linalg/chol.o: CFLAGS += $(VECT_FLAGS)

# libhylc's copy of hylcmat reads HDF5 tables too (the standalone libhylcmat: see below)
$(OBJ)/src/hylcmat/%.o: CFLAGS += -DHYLCMAT_WITH_HDF5

# the material evaluator and the shell element at -O3 in both copies (GCC vectorizes and unrolls their
# small fixed loops: 40 % fewer instructions for the element Hessian; the same results, x86-64 has no
# FMA contraction without -mfma: docs/performance.md). Not in the COVERAGE=1 build.
HM_FAST := src/hylcmat/eval.c src/hylcmat/shell.c src/hylcmat/psd.c src/hylcmat/mesh.c
ifneq ($(COVERAGE),1)
$(HM_FAST:src/%.c=$(OBJ)/src/%.o): CFLAGS += -O3
$(HM_FAST:src/%.c=$(BUILD)/hylcmat/%.o): HM_CFLAGS += -O3
endif

$(OBJ)/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@ && ar rcs $@ $^

$(SOLIB): $(LIB_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(LDFLAGS) -shared -Wl,-soname,libhylc.so.$(HYLC_SOVERSION) -o $@.$(HYLC_SOVERSION) $^ $(LDLIBS) && ln -sf libhylc.so.$(HYLC_SOVERSION) $@

# ---- hylcmat: the material model alone, C99, libc + libm (include/hylcmat.h, src/hylcmat/) ----------
# Built with the system C compiler and no PETSc/MPI/HDF5 flags. HYLCMAT_WITH_HDF5=1 adds the HDF5
# reader (HYLCMAT_HDF5_PKG: the pkg-config name of the HDF5 to use). libhylc has its own copy of these
# objects, built with HDF5 (one source).
HYLC_SOVERSION    := 1
HYLCMAT_SOVERSION := 1
HM_CC      ?= cc
HM_CFLAGS  ?= -O2 -g
# PETSc-free sources of src/sys shared with libhylc: the JSON reader, and the HDF5 helpers with HDF5
HM_SRC     := $(sort $(wildcard src/hylcmat/*.c)) src/sys/json.c src/sys/strain.c $(if $(filter 1,$(HYLCMAT_WITH_HDF5)),src/sys/h5util.c)
HM_OBJ     := $(HM_SRC:src/%.c=$(BUILD)/hylcmat/%.o)
HM_LIBS    := -lm
HYLCMAT_HDF5_PKG ?= hdf5-openmpi
ifeq ($(HYLCMAT_WITH_HDF5),1)
  HM_CFLAGS += -DHYLCMAT_WITH_HDF5 $(shell pkg-config --cflags $(HYLCMAT_HDF5_PKG))
  HM_LIBS   += $(shell pkg-config --libs $(HYLCMAT_HDF5_PKG))
endif
HM_LIB     := $(BUILD)/libhylcmat.a
HM_SOLIB   := $(BUILD)/libhylcmat.so
hylcmat: $(HM_LIB) $(HM_SOLIB)

$(BUILD)/hylcmat/%.o: src/%.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (hylcmat)")
	$(Q)$(HM_CC) $(HM_CFLAGS) -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -pedantic -fPIC -fvisibility=default -Iinclude -MMD -MP -c $< -o $@

$(HM_LIB): $(HM_OBJ)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@ && ar rcs $@ $^

$(HM_SOLIB): $(HM_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(HM_CC) -shared -Wl,-soname,libhylcmat.so.$(HYLCMAT_SOVERSION) -o $@.$(HYLCMAT_SOVERSION) $^ $(HM_LIBS) && ln -sf libhylcmat.so.$(HYLCMAT_SOVERSION) $@

# ---- install / uninstall ------------------------------------------------------------------------------
# Every installed file is listed in $(DESTDIR)$(PREFIX)/share/hylc/install-manifest.txt; uninstall removes
# the files of that list, the list itself, and the directories install created once they are empty.
PREFIX     ?= /usr/local
DESTDIR    ?=
LIBDIR     ?= $(PREFIX)/lib
INCDIR     ?= $(PREFIX)/include
BINDIR     ?= $(PREFIX)/bin
DATADIR    ?= $(PREFIX)/share
PCDIR      ?= $(LIBDIR)/pkgconfig
DOCDIR     ?= $(DATADIR)/doc/hylc
MANIFEST   := $(DATADIR)/hylc/install-manifest.txt
HYLC_VERSION := $(shell sed -n 's/^\#define HYLC_VERSION_STRING "\(.*\)"/\1/p' include/hylc/sys.h)

install: lib hylcmat apps
	@PREFIX='$(PREFIX)' DESTDIR='$(DESTDIR)' DATADIR='$(DATADIR)' LIBDIR='$(LIBDIR)' INCDIR='$(INCDIR)' BINDIR='$(BINDIR)' \
	  PCDIR='$(PCDIR)' DOCDIR='$(DOCDIR)' MANIFEST='$(MANIFEST)' BUILD='$(BUILD)' VERSION='$(HYLC_VERSION)' \
	  HYLC_SOVERSION='$(HYLC_SOVERSION)' HYLCMAT_SOVERSION='$(HYLCMAT_SOVERSION)' \
	  PC_REQUIRES='$(PKGS)' PC_LIBS_PRIVATE='-lmetis -llapack -lm' HM_LIBS='$(HM_LIBS)' \
	  bash tools/install.sh install

uninstall:
	@PREFIX='$(PREFIX)' DESTDIR='$(DESTDIR)' MANIFEST='$(MANIFEST)' bash tools/install.sh uninstall

# tests/support: reference code for the tests and benchmarks only (HylcTile), not in libhylc
$(SUPPORT_LIB): $(SUPPORT_SRC:%.c=$(OBJ)/%.o)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@ && ar rcs $@ $^
$(OBJ)/tests/%.o: CFLAGS += -Itests/support

# link_rule,dir,srcdir[,extra archives]
define link_rule
$(BUILD)/$(1)/%: $(OBJ)/$(2)/%.o $(3) $(LIB)
	@mkdir -p $$(@D)
	@$$(if $$(Q),echo "  LD      $$@")
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$< $(3) $$(LIB) $$(LDLIBS)
endef
$(eval $(call link_rule,bin,src/apps))
$(eval $(call link_rule,tests,tests/unit,$(SUPPORT_LIB)))
$(eval $(call link_rule,bench,tests/bench,$(SUPPORT_LIB)))
$(eval $(call link_rule,ex,examples))
# the fuzz harnesses with a plain main (tests/fuzz/replay.c) for tests/regression/fuzz_regressions.sh
$(BUILD)/fuzz/%: $(OBJ)/tests/fuzz/%.o $(OBJ)/tests/fuzz/replay.o $(LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(LDFLAGS) -o $@ $< $(OBJ)/tests/fuzz/replay.o $(LIB) $(LDLIBS)

deps:
	@bash config/install-deps.sh

test:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory all
	@BUILD=$(BUILD) HYLC_ASAN=$(if $(filter 1,$(ASAN)),1,0) bash tests/run.sh

# the unit tests (tests/unit) under ASan + UBSan, in build-asan
test-asan:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory ASAN=1 BUILD=build-asan lib tests
	@BUILD=build-asan HYLC_ASAN=1 bash tests/run.sh --unit

demo:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory all
	@bash examples/demo.sh

bench: all
	@bash tests/bench/run.sh

# the fabric sheet (docs/fabric-sheet.md) of hylc-cloth's virtual tests on the paper's tables and FABRIC_TABLES
fabric-sheet: apps
	@HYLC_FABRIC_TABLES="$(FABRIC_TABLES)" python3 tools/fabric_sheet.py

fidelity: apps
	@bash tools/fidelity_all.sh

# the tests in the COVERAGE=1 build (build-cov), then line coverage per stage (tools/coverage.sh)
coverage:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory COVERAGE=1 BUILD=build-cov all
	@find build-cov -name '*.gcda' -delete
	@st=0; BUILD=build-cov COVERAGE=1 bash tests/run.sh $(COVERAGE_TESTS) || st=$$?; BUILD=build-cov bash tools/coverage.sh; exit $$st

FORMAT_SRC := $(wildcard include/*.h include/hylc/*.h include/hylc/private/*.h src/*/*.c src/hylcmat/*.h tests/*/*.c tests/*/*.h examples/*.c)
format:
	clang-format -i $(FORMAT_SRC)

check-format:
	@command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (apt-get install clang-format)"; exit 1; }
	@clang-format --dry-run -Werror $(FORMAT_SRC) && echo "check-format: $(words $(FORMAT_SRC)) files formatted"

clean:
	rm -rf $(BUILD)

# ---- libFuzzer harnesses (tests/fuzz, docs/testing.md): clang, -fsanitize=fuzzer,address,undefined ----
FUZZ_BUILD   ?= build-fuzz
FUZZ_CC      ?= clang-14
FUZZ_SECONDS ?= 60
FUZZ_NAMES   := $(patsubst tests/fuzz/%.c,%,$(sort $(wildcard tests/fuzz/fuzz_*.c)))
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_CFLAGS  := -g -O1 -Wall -Wextra -std=c11 -D_DEFAULT_SOURCE -Iinclude $(PKG_CFLAGS) -MMD -MP $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_OBJ     := $(LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_BINS    := $(FUZZ_NAMES:%=$(FUZZ_BUILD)/%)

$(FUZZ_BUILD)/obj/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  FUZZCC  $<")
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_BUILD)/libhylc.a: $(FUZZ_OBJ)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@ && ar rcs $@ $^

$(FUZZ_BUILD)/fuzz_%: $(FUZZ_BUILD)/obj/tests/fuzz/fuzz_%.o $(FUZZ_BUILD)/libhylc.a
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(FUZZ_CC) $(FUZZ_SAN) -fsanitize=fuzzer -o $@ $< $(FUZZ_BUILD)/libhylc.a $(LDLIBS)

fuzz-deps:
	@HYLC_DEPS_EXTRA="clang-14 libclang-rt-14-dev" bash config/install-deps.sh

fuzz-build: fuzz-deps
	@$(MAKE) --no-print-directory $(FUZZ_BINS)

# runs every harness FUZZ_SECONDS seconds on its corpus (build-fuzz/corpus/<harness>, seeded by
# tests/fuzz/seeds.sh); a crash, leak or timeout stops it with the input in build-fuzz/findings
fuzz: fuzz-build
	@FUZZ_BUILD=$(FUZZ_BUILD) FUZZ_SECONDS=$(FUZZ_SECONDS) bash tests/fuzz/run.sh $(FUZZ_NAMES)

help:
	@sed -n '2,15p' Makefile

-include $(ALL_OBJ:.o=.d)
-include $(wildcard $(FUZZ_BUILD)/obj/*/*/*.d $(FUZZ_BUILD)/obj/tests/fuzz/*.d)
