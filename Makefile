# fxrt: fixed-point ray tracer. Quiet unless V=1; all output under build/.
#   make          host tool build/fxrt
#   make test     every test; ends with "N passed, N failed"
#   make demo     render the seed scenes (see README)
#   make deps     install missing Debian packages

BUILD   ?= build
CC      ?= gcc
ifeq ($(origin CC),default)
CC      := gcc
endif
V       ?= 0
Q       := $(if $(filter 1,$(V)),,@)

WARN    := -std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wmissing-prototypes -Werror
HOSTCFLAGS ?= -O2 -g
CFLAGS_H := $(WARN) $(HOSTCFLAGS) -D_POSIX_C_SOURCE=200809L -MMD -MP -Icore
# The test programs' own sources (tests/*.c: the checks, not the code under
# test, which they link as the host build's objects) at TEST_OPT, -O0:
# gcc -O2 took longer to compile them than their runs saved (test_geom.c in
# q16: 4.5 s to compile at -O2 and 0.8 s to run, 0.6 s and 1.6 s at -O0).
# A test whose run is mostly its own arithmetic sets TEST_OPT back (below).
TEST_OPT ?= -O0
CFLAGS_T = $(filter-out -O%,$(CFLAGS_H)) $(TEST_OPT)
LDLIBS_H := -lpng -lm

NUMBERS := q16 float double
num_id   = $(if $(filter q16,$1),1,$(if $(filter float,$1),2,3))

include core/core.mk
.SECONDARY:
.SECONDEXPANSION:
include host/multi.mk
HOST_SRC := main scene image errf compare engine_select args obj xform meshstore meshbuild
# The scene loader and what it needs (OBJ meshes, node transforms, messages).
SCENE_LIB = $(BUILD)/host/scene.o $(BUILD)/host/obj.o $(BUILD)/host/xform.o $(BUILD)/host/errf.o \
            $(BUILD)/host/meshstore.o $(BUILD)/host/meshbuild.o

# --- host tool -----------------------------------------------------------
# (host/multi.mk: the three number types' objects, each joined into one.)
HOST_OBJ := $(HOST_SRC:%=$(BUILD)/host/%.o) $(BUILD)/host/fx.o $(call multi_objs,$(BUILD),fxrt,$(NUMBERS))

SCENEC_OBJ := $(BUILD)/host/scenec.o $(SCENE_LIB) $(BUILD)/host/args.o $(BUILD)/host/engine_select.o \
              $(BUILD)/host/meshemit.o \
              $(BUILD)/host/fx.o $(call multi_objs,$(BUILD),scenec,$(NUMBERS))

all: $(BUILD)/fxrt $(BUILD)/fxrt-scenec

$(BUILD)/fxrt-scenec: $(SCENEC_OBJ)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $(filter %.o,$^) $(LDLIBS_H)

$(BUILD)/fxrt: $(HOST_OBJ)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $(filter %.o,$^) $(LDLIBS_H)

$(BUILD)/host/%.o: host/%.c
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CFLAGS_H) -c $< -o $@

# The Q16.16 library, the same in every number type (core/core.mk
# CORE_FX), joined into one object (ld -r) that programs and tests link.
$(BUILD)/host/fx.o: $(CORE_FX:%=$(BUILD)/host/fx/%.o)
	@echo "  LD -r   $@"
	$(Q)ld -r -o $@ $(filter %.o,$^)
$(BUILD)/host/fx/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CFLAGS_H) -c $< -o $@

define number_rules
$(BUILD)/host/$(1)/%.o: core/%.c
	@mkdir -p $$(@D)
	@echo "  CC $(1)  $$<"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@
$(BUILD)/host/engine-$(1).o: host/engine.c
	@mkdir -p $$(@D)
	@echo "  CC $(1)  $$<"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@
$(BUILD)/host/scenec_emit-$(1).o $(BUILD)/host/scenec_world-$(1).o: $(BUILD)/host/scenec_%-$(1).o: host/scenec_%.c
	@mkdir -p $$(@D)
	@echo "  CC $(1)  $$<"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@
endef
$(foreach n,$(NUMBERS),$(eval $(call number_rules,$(n))))

# --- tests ---------------------------------------------------------------
UNIT_TESTS := test_fx test_image test_compare test_scene test_obj test_node
TEST_BIN   := $(UNIT_TESTS:%=$(BUILD)/tests/%)
test_fx_DEPS      := $(BUILD)/host/fx.o
test_image_DEPS   := $(BUILD)/host/image.o $(BUILD)/host/errf.o
test_compare_DEPS := $(BUILD)/host/compare.o $(BUILD)/host/image.o $(BUILD)/host/errf.o
test_scene_DEPS   := $(SCENE_LIB)
test_obj_DEPS     := $(BUILD)/host/obj.o $(BUILD)/host/errf.o
test_node_DEPS    := $(SCENE_LIB)

$(BUILD)/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CFLAGS_T) -Ihost -Icore -c $< -o $@

$(BUILD)/tests/%: $(BUILD)/tests/%.o $$($$*_DEPS)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $(filter %.o,$^) $(LDLIBS_H)

# Tests of the number-generic core, one binary per number type.
NUM_TESTS   := test_geom test_affine
NUM_TEST_BIN := $(foreach t,$(NUM_TESTS),$(foreach n,$(NUMBERS),$(BUILD)/tests/$(t)_$(n)))
define num_test_rules
$(BUILD)/tests/$(1)_$(2): tests/$(1).c $(wildcard tests/*.h) $(BUILD)/host/fx.o $(CORE_NUM:%=$(BUILD)/host/$(2)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(2) $$@"
	$$(Q)$$(CC) $$(CFLAGS_T) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(2)) -Icore -Ihost -o $$@ $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach t,$(NUM_TESTS),$(foreach n,$(NUMBERS),$(eval $(call num_test_rules,$(t),$(n)))))
TEST_BIN += $(NUM_TEST_BIN)
# Tests whose run is mostly their own arithmetic (the kernel differential
# test, the fixed-point sweeps, the lighting reference): -O0 would cost
# them more run time than it saves in compiling.
$(BUILD)/tests/test_diff.o $(BUILD)/tests/test_fx.o $(foreach n,$(NUMBERS),$(BUILD)/tests/test_shade_$(n)): TEST_OPT := -O2

# tests/test_bvh.c: the mesh queries on meshes built by host/meshbuild.c
# (compiled with it, in each number type: an instance holds numbers).
# tests/test_model.c: models in the world through the public API, the same way.
# $(call bvh_test_rules,NUMBER,DIR,CC,CFLAGS,TEST): TEST's rule under DIR
# (the build's, or tests/sanitize.mk's sanitized one: an explicit rule,
# ahead of the pattern rule for number-generic tests).
BVH_TESTS := test_bvh test_model
BVH_TEST_LIB := host/meshbuild.c host/obj.c host/errf.c
define bvh_test_rules
$(2)/tests/$(5)_$(1): tests/$(5).c $(BVH_TEST_LIB) host/meshbuild.h host/obj.h $(wildcard tests/*.h) $(2)/host/fx.o $(CORE_NUM:%=$(2)/host/$(1)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(1) $$@"
	$$(Q)$(3) $(4) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -o $$@ $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach t,$(BVH_TESTS),$(foreach n,$(NUMBERS),$(eval $(call bvh_test_rules,$(n),$(BUILD),$$(CC),$$(CFLAGS_H),$(t)))))
TEST_BIN += $(foreach t,$(BVH_TESTS),$(foreach n,$(NUMBERS),$(BUILD)/tests/$(t)_$(n)))

# Fragments add suites to SUITES_EXTRA and what they need to TEST_PREREQ.
SUITES_EXTRA :=
TEST_PREREQ  :=
TEST_FULL_PREREQ :=
-include tests/sanitize.mk
-include tests/diff.mk
-include host/version.mk
-include tests/color.mk
-include tests/oracle.mk
-include tests/fit.mk
-include tests/fx.mk
-include tests/examples.mk
-include tests/scene_light.mk
-include tests/scene_trace.mk
-include tests/skip.mk
-include tests/lit.mk
-include tests/trace.mk
-include tests/qemu_lit.mk
-include tests/growth.mk
-include tests/qemu_trace.mk
-include tests/order.mk
-include firmware/oled.mk

SUITES := $(TEST_BIN) tests/cli.sh tests/golden.sh tests/stress_scenes.sh tests/renderers.sh tests/freestanding.sh tests/layers.sh tests/doclinks.sh tests/qemu.sh \
          $(SUITES_EXTRA)

# make test builds what the suites need with TEST_JOBS parallel jobs (the
# machine's cores), then runs the suites in two lanes (tests/run.sh). It
# runs each suite's quick scope; make test-full runs the long sweeps too
# (FXRT_TEST_FULL=1: every seed scene on every board through the per-scene
# firmware, every renderer variant on target, the sanitized suites at full
# size, the kernel fuzzer; docs/TESTING.md lists what each scope runs).
TEST_JOBS ?= $(shell nproc 2>/dev/null || echo 2)
test-build: $(BUILD)/fxrt $(BUILD)/fxrt-scenec $(TEST_BIN) $(TEST_PREREQ)
test: deps
	$(Q)$(MAKE) --no-print-directory -j$(TEST_JOBS) test-build
	$(Q)BUILD=$(BUILD) tests/run.sh $(SUITES)
test-full: deps
	$(Q)$(MAKE) --no-print-directory -j$(TEST_JOBS) test-build $(TEST_FULL_PREREQ)
	$(Q)BUILD=$(BUILD) FXRT_TEST_FULL=1 tests/run.sh $(SUITES)

# --- firmware (firmware/firmware.mk) ----------------------------------------
include firmware/firmware.mk
include firmware/bench.mk
include firmware/meshq.mk

# --- demo ----------------------------------------------------------------
# make help: every target with its one-line use, read from docs/TARGETS.md
# (the page and the list cannot drift apart).
help:
	@echo "fxrt: make TARGET [VAR=value ...]  (docs/TARGETS.md has each in full)"
	@awk -F'|' '/^## / { sub(/^## /, ""); printf "\n%s\n", $$0 } \
	    /^\| `make/ { c = $$2; w = $$3; gsub(/`/, "", c); gsub(/^ +| +$$/, "", c); gsub(/`/, "", w); \
	    gsub(/\]\([^)]*\)/, "", w); gsub(/\[/, "", w); gsub(/^ +| +$$/, "", w); if (length(w) > 90) w = substr(w, 1, 87) "..."; \
	    printf "  %-34s %s\n", c, w }' docs/TARGETS.md
.PHONY: help

demo: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec $(OLED_TOOL)
	$(Q)BUILD=$(BUILD) tests/demo.sh
	$(Q)BUILD=$(BUILD) firmware/oled/oled-demo.sh

size: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) SIZE_UPDATE_DOCS=$(SIZE_UPDATE_DOCS) firmware/size.sh

# The docs' generated blocks (host/docblocks.sh): make doc-blocks
# [DOC_BLOCKS="lit trace"] [DOC_RUN=1: run their commands first]
# [DOCS_UPDATE=1: rewrite them in docs/]. make doc-images redraws the
# README's picture (host/docimages.sh).
doc-blocks:
	$(Q)BUILD=$(BUILD) DOC_RUN=$(DOC_RUN) DOCS_UPDATE=$(DOCS_UPDATE) host/docblocks.sh $(DOC_BLOCKS)
doc-images: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) host/docimages.sh

# Fuzzing (libFuzzer): each harness for FUZZ_SECONDS (default 60).
FUZZ_SECONDS ?= 60
fuzz: deps fuzz-scene fuzz-kernels

deps:
	$(Q)host/deps.sh

clean:
	rm -rf $(BUILD)

.PHONY: all test test-build test-full demo size doc-blocks doc-images deps clean fuzz
# Dependency files of the host build. Firmware objects' ones are read by
# firmware.mk for the one ELF being built: build/fw holds one directory per
# ELF the tests and benchmarks made (over a thousand .d files), and reading
# them all cost every make call about a second. build/same holds other
# revisions' trees (make same-code), whose files are not ours.
-include $(shell find $(BUILD) \( -path '$(BUILD)/fw' -o -path '$(BUILD)/same' \) -prune -o -name '*.d' -print 2>/dev/null)
