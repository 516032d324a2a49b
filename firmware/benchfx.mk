# Fixed-point maths benchmark, included by the top Makefile.
#   make bench-fx [BENCHFX_BOARDS="mps2-an385 microbit"] [BENCHFX_UPDATE_DOCS=1]
# Builds firmware/benchfx.c for every measured board, runs it in QEMU (-icount) and
# prints a Markdown table: instructions and estimated cycles per call (the
# execution trace, firmware/cycles.sh), text bytes, worst error
# (from build/tests/test_fx). Writes build/benchfx/benchfx.md; with
# BENCHFX_UPDATE_DOCS=1 also the table in docs/BENCHMARKS.md.
# (Included before firmware.mk: board variables are only used in recipes.)
# The boards make bench measures (firmware/bench.mk: the lm3s6965evb counts
# as the MPS2-AN385).
BENCHFX_BOARDS ?= $(BENCH_BOARD_LIST)
BENCHFX_SRC := firmware/benchfx.c $(CORE_FX:%=core/%.c) firmware/startup.c firmware/semihost.c firmware/counter.c

BENCHFX_HDR := firmware/benchfx.h firmware/benchfx_gen.h core/math/fx.h core/math/vec3.h core/math/num.h core/fxrt_config.h

# The float counterparts (firmware/benchfx_num.c), built as the float
# renderer's firmware is (FXRT_NUMBER = 2, -fno-math-errno as in
# firmware.mk: soft float on the M0 and M3, the FPU on the M4F).
$(BUILD)/benchfx/%/benchfx_num.o: firmware/benchfx_num.c $(BENCHFX_HDR)
	@mkdir -p $(@D)
	@echo "  ARMCC   $@"
	$(Q)$(ARM_CC) $(WARN) -O2 -g $(CPU_$*) -ffreestanding -ffunction-sections -fdata-sections \
	  -fno-math-errno -DFXRT_NUMBER=2 -Icore -Ifirmware -c $< -o $@

$(BUILD)/benchfx/%/benchfx.elf: $(BENCHFX_SRC) $(BUILD)/benchfx/%/benchfx_num.o $(BENCHFX_HDR) $(wildcard linker/*.ld)
	@mkdir -p $(@D)
	@echo "  ARMCC   $@"
	$(Q)$(ARM_CC) $(WARN) -O2 -g $(CPU_$*) -ffreestanding -ffunction-sections -fdata-sections \
	  -DFXRT_NUMBER=1 -Icore -Ifirmware $(BENCHFX_SRC) $(BUILD)/benchfx/$*/benchfx_num.o -nostartfiles \
	  --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections -Wl,-Map=$(@D)/benchfx.map -Llinker -Tlinker/$*.ld -lm -o $@

bench-fx: $(BUILD)/tests/test_fx
	$(Q)$(MAKE) --no-print-directory $(foreach b,$(BENCHFX_BOARDS),$(BUILD)/benchfx/$(b)/benchfx.elf)
	$(Q)BUILD=$(BUILD) BENCHFX_UPDATE_DOCS=$(BENCHFX_UPDATE_DOCS) BENCHFX_TICKS='$(foreach b,$(BENCHFX_BOARDS),$(b):$(QEMU_M_$(b)):$(TICK_NS_$(b)))' \
	  firmware/benchfx.sh

.PHONY: bench-fx
