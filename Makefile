# hylc -- homogenized yarn-level cloth.  One GNU Makefile; see README.md.
#   make            build libhylc, the programs (build/bin), unit tests and benchmarks
#   make test       install missing dependencies, build, run all tests (ends with "N passed, N failed")
#   make demo       install missing dependencies, build, run the main job on a built-in default
#   make bench      build and run the benchmarks (prints measured figures)
#   make install    PREFIX=/usr/local DESTDIR=: headers, libraries, programs, pkg-config files, docs
#   make uninstall  remove every installed file (from the manifest written by install)
#   make deps       install missing system packages (apt; as root or with sudo)
#   make format     clang-format the sources
#   V=1             show full command lines

.SUFFIXES:
.SECONDARY:
.DEFAULT_GOAL := all
SHELL := /bin/bash

BUILD   ?= build
OBJ     := $(BUILD)/obj
PKGS    := petsc hdf5-openmpi
NOCHECK_GOALS := deps test demo clean format help distclean bench-run hylcmat uninstall
PETSC_OK := $(shell pkg-config --exists $(PKGS) 2>/dev/null && echo yes)

ifeq ($(filter $(NOCHECK_GOALS),$(MAKECMDGOALS)),)
  ifneq ($(PETSC_OK),yes)
    $(error PETSc/HDF5 development files were not found by pkg-config ($(PKGS)). Install them with 'make deps' (runs config/install-deps.sh), or run 'make test' / 'make demo', which install them first)
  endif
endif

ifeq ($(PETSC_OK),yes)
  CC      := $(shell pkg-config --variable=ccompiler petsc)
  PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS))
  PKG_LIBS   := $(shell pkg-config --libs $(PKGS))
endif
OPT      ?= -O2 -g
CFLAGS   ?= $(OPT)
CFLAGS   += -Wall -Wextra -std=c11 -D_DEFAULT_SOURCE -fPIC -Iinclude $(PKG_CFLAGS) -MMD -MP
LDLIBS   := $(PKG_LIBS) -lmetis -lm

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
EX_SRC    := $(sort $(wildcard examples/*.c))
EXAMPLES  := $(EX_SRC:examples/%.c=$(BUILD)/ex/%)
ALL_OBJ   := $(LIB_OBJ) $(patsubst src/hylcmat/%.c,$(BUILD)/hylcmat/%.o,$(wildcard src/hylcmat/*.c)) $(APP_SRC:%.c=$(OBJ)/%.o) $(TEST_SRC:%.c=$(OBJ)/%.o) $(BENCH_SRC:%.c=$(OBJ)/%.o) $(EX_SRC:%.c=$(OBJ)/%.o)

.PHONY: all lib apps tests benches examples test demo bench deps format clean help hylcmat install uninstall
all: lib hylcmat apps tests benches examples
lib: $(LIB) $(SOLIB)
apps: $(APPS)
tests: $(TESTS)
benches: $(BENCHES)
examples: $(EXAMPLES)

# The build identity in every sampling run's identity (src/sampler/identity.c, docs/output-format.md):
# `git describe --always --dirty` of the checkout, "unknown" outside one. $(BUILD)/build-id changes only
# when it does, and identity.o is rebuilt then.
HYLC_BUILD_ID := $(shell git -C $(CURDIR) describe --always --dirty 2>/dev/null || echo unknown)
BUILD_ID_FILE := $(BUILD)/build-id
ifeq ($(filter clean help,$(MAKECMDGOALS)),)
  $(shell mkdir -p $(BUILD); [ "$$(cat $(BUILD_ID_FILE) 2>/dev/null)" = "$(HYLC_BUILD_ID)" ] || echo "$(HYLC_BUILD_ID)" > $(BUILD_ID_FILE))
endif
$(OBJ)/src/sampler/identity.o: CFLAGS += -DHYLC_BUILD_ID='"$(HYLC_BUILD_ID)"'
$(OBJ)/src/sampler/identity.o: $(BUILD_ID_FILE)

# libhylc's copy of hylcmat reads HDF5 tables too (the standalone libhylcmat: see below)
$(OBJ)/src/hylcmat/%.o: CFLAGS += -DHYLCMAT_WITH_HDF5

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
	$(Q)$(CC) -shared -Wl,-soname,libhylc.so.$(HYLC_SOVERSION) -o $@.$(HYLC_SOVERSION) $^ $(LDLIBS) && ln -sf libhylc.so.$(HYLC_SOVERSION) $@

# ---- hylcmat: the material model alone, C99, libc + libm (include/hylcmat.h, src/hylcmat/) ----------
# Built with the system C compiler and no PETSc/MPI/HDF5 flags. HYLCMAT_WITH_HDF5=1 adds the HDF5
# reader (HYLCMAT_HDF5_PKG: the pkg-config name of the HDF5 to use). libhylc has its own copy of these
# objects, built with HDF5 (one source).
HYLC_SOVERSION    := 1
HYLCMAT_SOVERSION := 1
HM_CC      ?= cc
HM_CFLAGS  ?= -O2 -g
HM_SRC     := $(sort $(wildcard src/hylcmat/*.c))
HM_OBJ     := $(HM_SRC:src/hylcmat/%.c=$(BUILD)/hylcmat/%.o)
HM_LIBS    := -lm
HYLCMAT_HDF5_PKG ?= hdf5-openmpi
ifeq ($(HYLCMAT_WITH_HDF5),1)
  HM_CFLAGS += -DHYLCMAT_WITH_HDF5 $(shell pkg-config --cflags $(HYLCMAT_HDF5_PKG))
  HM_LIBS   += $(shell pkg-config --libs $(HYLCMAT_HDF5_PKG))
endif
HM_LIB     := $(BUILD)/libhylcmat.a
HM_SOLIB   := $(BUILD)/libhylcmat.so
hylcmat: $(HM_LIB) $(HM_SOLIB)

$(BUILD)/hylcmat/%.o: src/hylcmat/%.c
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
	@PREFIX='$(PREFIX)' DESTDIR='$(DESTDIR)' LIBDIR='$(LIBDIR)' INCDIR='$(INCDIR)' BINDIR='$(BINDIR)' \
	  PCDIR='$(PCDIR)' DOCDIR='$(DOCDIR)' MANIFEST='$(MANIFEST)' BUILD='$(BUILD)' VERSION='$(HYLC_VERSION)' \
	  HYLC_SOVERSION='$(HYLC_SOVERSION)' HYLCMAT_SOVERSION='$(HYLCMAT_SOVERSION)' \
	  PC_REQUIRES='$(PKGS)' PC_LIBS_PRIVATE='-lmetis -lm' HM_LIBS='$(HM_LIBS)' \
	  bash tools/install.sh install

uninstall:
	@PREFIX='$(PREFIX)' DESTDIR='$(DESTDIR)' MANIFEST='$(MANIFEST)' bash tools/install.sh uninstall

define link_rule
$(BUILD)/$(1)/%: $(OBJ)/$(2)/%.o $(LIB)
	@mkdir -p $$(@D)
	@$$(if $$(Q),echo "  LD      $$@")
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$< $$(LIB) $$(LDLIBS)
endef
$(eval $(call link_rule,bin,src/apps))
$(eval $(call link_rule,tests,tests/unit))
$(eval $(call link_rule,bench,tests/bench))
$(eval $(call link_rule,ex,examples))

deps:
	@bash config/install-deps.sh

test:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory all
	@bash tests/run.sh

demo:
	@bash config/install-deps.sh
	@$(MAKE) --no-print-directory all
	@bash examples/demo.sh

bench: all
	@bash tests/bench/run.sh

format:
	clang-format -i $(wildcard include/*.h include/hylc/*.h include/hylc/private/*.h src/*/*.c src/hylcmat/*.h tests/*/*.c tests/*/*.h examples/*.c)

clean:
	rm -rf $(BUILD)

help:
	@sed -n '2,11p' Makefile

-include $(ALL_OBJ:.o=.d)
