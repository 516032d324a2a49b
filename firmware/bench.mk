# Benchmarks, included by the top Makefile (after firmware/firmware.mk).
#   make bench [BENCH_UPDATE_DOCS=1]   run time against error: the seed and
#       the bench scene sets at BENCH_SIZE, every board, every build (q16, float,
#       float-step, double; fast, reference loop, per-pixel ray caster), in QEMU;
#       error against the host double render. Summaries per set. Writes
#       build/bench/bench.csv, bench.md (TARGETS with PASS/MISS, best float
#       builds, per board, drift, per scene) and pareto-SET-BOARD.png;
#       BENCH_UPDATE_DOCS=1 also regenerates docs/BENCHMARKS.md and docs/bench/.
#       Subsets: BENCH_BOARDS, BENCH_BUILDS, BENCH_SETS, BENCH_SCENES;
#       BENCH_JOBS runs in parallel (default: nproc). See firmware/bench.sh.
#   make bench-host   the host tool under callgrind (both renderers), a quick
#       iteration aid only; needs valgrind. BENCH_PROFILE=SCENE prints a
#       per-function profile of that scene instead.
# See docs/BENCHMARKS.md. Counts are QEMU -icount instructions, not cycles.

BENCH_SIZE ?= 160x120
# board:cpu:frame-mode for every board, from firmware.mk's CPU_ and FB_ lines
# (cortex-m4 with -mfloat-abi=hard is "M4F").
bench_cpu = $(patsubst cortex-m%,M%,$(patsubst -mcpu=%,%,$(filter -mcpu=%,$(CPU_$(1)))))$(if $(filter -mfloat-abi=hard,$(CPU_$(1))),F)
# The measured boards: the lm3s6965evb (the OLED's board) is a Cortex-M3
# like the MPS2-AN385, streaming, and counts as it does; make qemu and its
# own suites cover it.
BENCH_BOARD_LIST := $(filter-out lm3s6965evb,$(BOARDS))
BENCH_BOARD_INFO = $(foreach b,$(BENCH_BOARD_LIST),$(b):$(call bench_cpu,$(b)):$(FB_$(b)))

# BENCH_SETS may name "frontier" (make frontier below) and "samples" (make
# bench-samples); without BENCH_SETS make bench runs the default sets, then
# the frontier and the samples bench.
bench_sets_plain = $(filter-out frontier samples,$(BENCH_SETS))
bench: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(if $(BENCH_SETS),$(if $(bench_sets_plain),$(Q)BUILD=$(BUILD) BENCH_SIZE=$(BENCH_SIZE) BENCH_BOARD_INFO='$(BENCH_BOARD_INFO)' \
	  BENCH_SETS='$(bench_sets_plain)' BENCH_UPDATE_DOCS=$(BENCH_UPDATE_DOCS) BENCH_TABLES_ONLY=$(BENCH_TABLES_ONLY) firmware/bench.sh),\
	  $(Q)BUILD=$(BUILD) BENCH_SIZE=$(BENCH_SIZE) BENCH_BOARD_INFO='$(BENCH_BOARD_INFO)' \
	  BENCH_UPDATE_DOCS=$(BENCH_UPDATE_DOCS) BENCH_TABLES_ONLY=$(BENCH_TABLES_ONLY) firmware/bench.sh)
	$(if $(BENCH_SETS),$(if $(filter frontier,$(BENCH_SETS)),$(frontier_cmd)),$(frontier_cmd))
	$(if $(BENCH_SETS),$(if $(filter samples,$(BENCH_SETS)),$(samples_cmd)),$(samples_cmd))

# Issue 12's cheap case (firmware/bench-samples.sh): scenes/samples/ (one
# object fills the view: every pixel is the cheap case) and, for
# information, the seed scenes, at samples 1, 2 and 4, q16, every board, at
# BENCH_SIZE; targets on scenes/samples/: samples N at most N times samples
# 1 per scene, geometric mean <= 1.5x (N = 2) and <= 2.5x (N = 4).
# make bench-samples [BENCH_UPDATE_DOCS=1]. Not in make test.
samples_cmd = $(Q)BUILD=$(BUILD) BENCH_SIZE=$(BENCH_SIZE) BENCH_BOARD_INFO='$(BENCH_BOARD_INFO)' \
	  BENCH_UPDATE_DOCS=$(BENCH_UPDATE_DOCS) firmware/bench-samples.sh
bench-samples: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(samples_cmd)

# The frontier of issue 12 (firmware/frontier.sh): every board, q16 / float
# step / double at samples 1, 2, 4, 4 adaptive on three lit scenes, the
# reflection and the glass scene at FRONTIER_SIZE (64x48), error against the
# converged image (double, samples 16); Pareto plot per board; stack figures.
#   make frontier [FRONTIER_UPDATE_DOCS=1] [FRONTIER_TABLES_ONLY=1]
# (BENCH_UPDATE_DOCS=1 and BENCH_TABLES_ONLY=1 work too.) Not in make test.
FRONTIER_SIZE ?= 64x48
frontier_cmd = $(Q)BUILD=$(BUILD) FRONTIER_SIZE=$(FRONTIER_SIZE) BENCH_BOARD_INFO='$(BENCH_BOARD_INFO)' \
	  FRONTIER_UPDATE_DOCS=$(or $(FRONTIER_UPDATE_DOCS),$(BENCH_UPDATE_DOCS)) \
	  FRONTIER_TABLES_ONLY=$(or $(FRONTIER_TABLES_ONLY),$(BENCH_TABLES_ONLY)) firmware/frontier.sh
frontier: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(frontier_cmd)

bench-host: deps $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) BENCH_SIZE=$(BENCH_SIZE) BENCH_PROFILE=$(BENCH_PROFILE) firmware/bench.sh --host

.PHONY: bench bench-host frontier bench-samples

# What each renderer optimisation saves (Q16.16, one board), with the
# frames checked byte-identical: make bench-ablation [BOARD=...]
bench-ablation: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) BOARD=$(BOARD) firmware/ablate.sh
.PHONY: bench-ablation

# How far the lit set's float / q16 ratio can go on a board (default the
# micro:bit) with any light sum on top of today's hit point
# (firmware/lit-bound.sh): make bench-lit-bound [LIT_BOUND_BOARD=...]
LIT_BOUND_BOARD ?= microbit
bench-lit-bound: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) BOARD=$(LIT_BOUND_BOARD) firmware/lit-bound.sh
.PHONY: bench-lit-bound

# RAM per object of each kind and the most objects that fit each board at
# FIT_SIZE (default 160x120), measured from the compiled firmware
# (firmware/fit.sh; the same figures the fw link step prints when a scene
# does not fit): make ram-table
ram-table: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) BENCH_BOARD_INFO='$(BENCH_BOARD_INFO)' FIT_SIZE=$(or $(FIT_SIZE),160x120) RAM_UPDATE_DOCS=$(RAM_UPDATE_DOCS) firmware/fit.sh table
.PHONY: ram-table

# Per-function instruction profile of one firmware run in QEMU (the target's
# own code, soft-float and libgcc helpers by name), for the missed targets:
#   make profile SCENE=scenes/lit/room.scene BOARD=mps2-an385 NUMBER=float [PROFILE_SIZE=80x60] [FW_EXTRA=...]
# (PROFILE_TOP=N in the environment lists N functions instead of 15)
profile: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) firmware/profile.sh '$(SCENE)' $(BOARD) $(NUMBER) $(or $(PROFILE_SIZE),80x60) '$(FW_EXTRA)'
.PHONY: profile

# Where a lit pixel's instructions and estimated cycles go, by layer and by
# function (firmware/lit-profile.sh): the peer scene on each board, the lit
# set's room. Writes build/bench/lit-profile.md (docs/bench/ with
# BENCH_UPDATE_DOCS=1).
bench-lit-profile: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) BENCH_UPDATE_DOCS=$(BENCH_UPDATE_DOCS) firmware/lit-profile.sh
.PHONY: bench-lit-profile

# Estimated cycles of one frame (firmware/cycles.sh; docs/BENCHMARKS.md, "Cycles"):
#   make cycles SCENE=scenes/lit/room.scene BOARD=mps2-an385 NUMBER=q16 [CYCLES_SIZE=80x60]
# (CYCLES_FRAME=1: the frame's own figures too; FW_EXTRA, FW_TAG as for make qemu)
cycles: deps $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) firmware/cycles.sh '$(SCENE)' $(BOARD) $(NUMBER) $(or $(CYCLES_SIZE),80x60)
.PHONY: cycles
SUITES += tests/cycles.sh

# A refactor's proof (tests/same-frames.sh, firmware/same-code.sh): every
# host frame, and the firmware's code function by function, against the
# revision BASE: make same-frames BASE=REV; make same-code BASE=REV
# [SAME_RUN=1 SAME_VERBOSE=1 SAME_RENAMES=FILE SAME_CONFIGS=...]
same-frames: $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) BASE=$(BASE) tests/same-frames.sh
same-code: deps
	$(Q)BUILD=$(BUILD) BASE=$(BASE) firmware/same-code.sh
.PHONY: same-frames same-code
