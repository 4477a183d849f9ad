# hylc -- homogenized yarn-level cloth.  One GNU Makefile; see README.md.
#   make            build libhylc, the programs (build/bin), unit tests and benchmarks
#   make test       install missing dependencies, build, run all tests (ends with "N passed, N failed")
#   make demo       install missing dependencies, build, run the main job on a built-in default
#   make bench      build and run the benchmarks (prints measured figures)
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
NOCHECK_GOALS := deps test demo clean format help distclean bench-run
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
CFLAGS   += -Wall -Wextra -std=c11 -D_DEFAULT_SOURCE -Iinclude $(PKG_CFLAGS) -MMD -MP
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
APP_SRC   := $(sort $(wildcard src/apps/*.c))
APPS      := $(APP_SRC:src/apps/%.c=$(BUILD)/bin/%)
TEST_SRC  := $(sort $(wildcard tests/unit/*.c))
TESTS     := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)
BENCH_SRC := $(sort $(wildcard tests/bench/*.c))
BENCHES   := $(BENCH_SRC:tests/bench/%.c=$(BUILD)/bench/%)
EX_SRC    := $(sort $(wildcard examples/*.c))
EXAMPLES  := $(EX_SRC:examples/%.c=$(BUILD)/ex/%)
ALL_OBJ   := $(LIB_OBJ) $(APP_SRC:%.c=$(OBJ)/%.o) $(TEST_SRC:%.c=$(OBJ)/%.o) $(BENCH_SRC:%.c=$(OBJ)/%.o) $(EX_SRC:%.c=$(OBJ)/%.o)

.PHONY: all lib apps tests benches examples test demo bench deps format clean help
all: lib apps tests benches examples
lib: $(LIB)
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

$(OBJ)/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  AR      $@")
	$(Q)rm -f $@ && ar rcs $@ $^

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
	clang-format -i $(wildcard include/hylc/*.h include/hylc/private/*.h src/*/*.c tests/*/*.c tests/*/*.h examples/*.c)

clean:
	rm -rf $(BUILD)

help:
	@sed -n '2,9p' Makefile

-include $(ALL_OBJ:.o=.d)
