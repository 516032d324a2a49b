# Fixed-point maths: exhaustive and sampled checks, the multiply-only (M0)
# code paths on the host, and the maths benchmark. Included by the top
# Makefile.
#   make test            also runs build/tests/test_fx_nohw (test_fx against
#                        the Cortex-M0 code paths) and tests/fx_sampled.sh
#                        (every 4099th input of the exhaustive sweeps)
#   make fx-exhaustive   fx_sqrt over all 2^31 non-negative inputs, fx_rsqrt
#                        and sin/cos likewise, on both code paths, FX_JOBS
#                        processes (default 2)
#   make bench-fx        see firmware/benchfx.mk

# The M0's paths (no UDIV, no CLZ, no UMULL) built for the host.
FX_NOHW_FLAGS := -DFX_HAVE_UDIV=0 -DFX_HAVE_CLZ=0 -DFX_HAVE_UMULL=0
FX_JOBS ?= 2

$(BUILD)/tests/fx-nohw.o: $(CORE_FX:%=$(BUILD)/tests/fx-nohw/%.o)
	@echo "  LD -r   $@"
	$(Q)ld -r -o $@ $(filter %.o,$^)
$(BUILD)/tests/fx-nohw/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC nohw $<"
	$(Q)$(CC) $(CFLAGS_H) $(FX_NOHW_FLAGS) -c $< -o $@

# The test itself is compiled with the same flags: fx.h's inline products
# (fx_umul32, fx_smul32, fx_smul_small) then take their M0 paths too.
$(BUILD)/tests/test_fx_nohw: tests/test_fx.c tests/check.h core/math/fx.h core/fxrt_config.h $(BUILD)/tests/fx-nohw.o
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) $(FX_NOHW_FLAGS) -DTEST_FX_NAME='"test_fx_nohw"' -Icore -o $@ tests/test_fx.c $(BUILD)/tests/fx-nohw.o -lm

# tests/test_bvh.c in Q16.16 through the M0's paths too (test_bvh_nohw):
# the leak test and the oracle's queries on the micro:bit's arithmetic (the
# quick box test's two-product quotients and wider margins, and Knuth's
# digits by reciprocal), on the host, with the rays the boards' own checks
# cannot afford. The mesh queries (scene/bvh.c) and the maths compiled
# again with FX_NOHW_FLAGS; the rest of the core is the host's Q16.16 build
# (the queries' internals are bvh.c's own, and no record the other files
# share depends on those flags).
$(BUILD)/tests/nohw/q16/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC nohw $<"
	$(Q)$(CC) $(CFLAGS_H) $(FX_NOHW_FLAGS) -DFXRT_MULTI -DFXRT_NUMBER=1 -c $< -o $@
$(BUILD)/tests/test_bvh_nohw: tests/test_bvh.c $(BVH_TEST_LIB) host/meshbuild.h host/obj.h $(wildcard tests/*.h) \
                              $(BUILD)/tests/fx-nohw.o $(BUILD)/tests/nohw/q16/scene/bvh.o \
                              $(patsubst %,$(BUILD)/host/q16/%.o,$(filter-out scene/bvh,$(CORE_NUM)))
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) $(FX_NOHW_FLAGS) -DFXRT_MULTI -DFXRT_NUMBER=1 -DTEST_BVH_NAME='"test_bvh_nohw"' -Icore -Ihost \
	  -o $@ $(filter %.c %.o,$^) $(LDLIBS_H)
SUITES_EXTRA += $(BUILD)/tests/test_bvh_nohw
TEST_PREREQ  += $(BUILD)/tests/test_bvh_nohw

$(BUILD)/tests/fx_exhaustive: tests/fx_exhaustive.c tests/check.h $(BUILD)/host/fx.o
	@mkdir -p $(@D)
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) -Icore -o $@ tests/fx_exhaustive.c $(BUILD)/host/fx.o -lm

$(BUILD)/tests/fx_exhaustive_nohw: tests/fx_exhaustive.c tests/check.h $(BUILD)/tests/fx-nohw.o
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) -Icore -o $@ tests/fx_exhaustive.c $(BUILD)/tests/fx-nohw.o -lm

# test_geom (renderers against the kernels and each other) on the Q16.16
# core built with the same flags: the visibility pass's M0 paths (depth
# compares from 15-bit products first, render_depth_less) on the host.
$(BUILD)/host/q16-nohw/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC nohw $<"
	$(Q)$(CC) $(CFLAGS_H) $(FX_NOHW_FLAGS) -DFXRT_MULTI -DFXRT_NUMBER=1 -c $< -o $@

$(BUILD)/tests/test_geom_q16_nohw: tests/test_geom.c $(wildcard tests/*.h) $(BUILD)/tests/fx-nohw.o \
    $(CORE_NUM:%=$(BUILD)/host/q16-nohw/%.o)
	@echo "  CC/LD nohw $@"
	$(Q)$(CC) $(CFLAGS_T) $(FX_NOHW_FLAGS) -DFXRT_MULTI -DFXRT_NUMBER=1 -DTEST_GEOM_NAME='"test_geom_q16_nohw"' \
	    -Icore -Ihost -o $@ $(filter %.c %.o,$^) $(LDLIBS_H)

SUITES_EXTRA += $(BUILD)/tests/test_geom_q16_nohw
TEST_PREREQ  += $(BUILD)/tests/test_geom_q16_nohw

FX_EXH_BIN := $(BUILD)/tests/fx_exhaustive $(BUILD)/tests/fx_exhaustive_nohw

fx-exhaustive: $(FX_EXH_BIN)
	$(Q)for b in $(FX_EXH_BIN); do \
	    echo "  EXHAUST $$b --jobs $(FX_JOBS)"; start=$$(date +%s); \
	    $$b --jobs $(FX_JOBS) || exit 1; \
	    echo "  ($$(($$(date +%s) - start)) s)"; \
	done

SUITES_EXTRA += $(BUILD)/tests/test_fx_nohw tests/fx_sampled.sh
TEST_PREREQ  += $(BUILD)/tests/test_fx_nohw $(FX_EXH_BIN)

.PHONY: fx-exhaustive

include firmware/benchfx.mk

# test_fx_nohw under ASan+UBSan too (tests/sanitize.sh runs tests.list).
$(SAN_DIR)/tests/fx-nohw.o: $(CORE_FX:%=$(SAN_DIR)/tests/fx-nohw/%.o)
	@echo "  LD -r   $@"
	$(Q)ld -r -o $@ $(filter %.o,$^)
$(SAN_DIR)/tests/fx-nohw/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC san nohw $<"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) $(FX_NOHW_FLAGS) -c $< -o $@
$(SAN_DIR)/tests/test_fx_nohw: tests/test_fx.c tests/check.h $(SAN_DIR)/tests/fx-nohw.o
	@echo "  CC/LD san $@"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -DTEST_FX_NAME='"test_fx_nohw"' -Icore -o $@ tests/test_fx.c $(SAN_DIR)/tests/fx-nohw.o -lm
SAN_EXTRA_BIN += $(SAN_DIR)/tests/test_fx_nohw
