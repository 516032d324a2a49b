# examples/ and the public API's tests (included by the top Makefile).
#   build/examples/host/orbit OUTDIR      the orbit example on the host
#   build/examples/microbit/orbit.elf     the same program for the micro:bit
#   build/tests/test_fxrt_{q16,float,double}  the API's unit test
# tests/examples.sh runs both builds and compares their frames.

# Each example's configuration: the core and the application are compiled
# with the same macros (docs/EMBEDDING.md). Capacities are the example's
# own object counts. orbit: flat, 64 x 48; lit: lights, bounces and 2 x 2
# adaptive samples at 48 x 36 (the renderer holds 2 x 48 columns).
EXAMPLE_CFG := -DFXRT_NUMBER=1 -DFXRT_MAX_PLANES=1 -DFXRT_MAX_SPHERES=2 -DFXRT_MAX_TRIANGLES=1 \
               -DFXRT_MAX_BOXES=1 -DFXRT_RENDER_MAX_WIDTH=64 -DFXRT_MAX_DEPTH=0 -DFXRT_MAX_SAMPLES=1
EXAMPLE_CFG_orbit := $(EXAMPLE_CFG)
EXAMPLE_CFG_lit   := -DFXRT_NUMBER=1 -DFXRT_MAX_PLANES=1 -DFXRT_MAX_SPHERES=2 -DFXRT_MAX_TRIANGLES=1 \
                     -DFXRT_MAX_BOXES=1 -DFXRT_RENDER_MAX_WIDTH=96 -DFXRT_MAX_LIGHTS=2 -DFXRT_MAX_DEPTH=4 \
                     -DFXRT_MAX_SAMPLES=2 -DFXRT_ADAPTIVE=1
EXAMPLES := orbit lit
# The core's sources as the Makefile lists them (without the optional ray caster).
EXAMPLE_CORE = $(CORE_FX) $(filter-out frame/raycast,$(CORE_NUM))
EX_HOST := $(BUILD)/examples/host
EX_MB   := $(BUILD)/examples/microbit
EX_OBJ  := $(BUILD)/examples/obj

EX_MB_CFLAGS = $(WARN) -O2 -g $(CPU_microbit) -ffreestanding -ffunction-sections -fdata-sections \
               -fstack-usage -Icore -Ifirmware -Iexamples

# example_rules NAME: the host program $(EX_HOST)/NAME and the micro:bit's
# $(EX_MB)/NAME.elf, each with the core compiled in NAME's configuration
# (the host program at TEST_OPT, -O0: a test program, whose frames must
# equal the micro:bit's -O2 build's).
define example_rules
$(EX_OBJ)/host-$(1)/core/%.o: core/%.c tests/examples.mk
	@mkdir -p $$(@D)
	@echo "  CC ex   $$<"
	$$(Q)$$(CC) $$(CFLAGS_T) $$(EXAMPLE_CFG_$(1)) -Icore -c $$< -o $$@
$(EX_OBJ)/host-$(1)/%.o: examples/%.c tests/examples.mk
	@mkdir -p $$(@D)
	@echo "  CC ex   $$<"
	$$(Q)$$(CC) $$(CFLAGS_T) $$(EXAMPLE_CFG_$(1)) -Icore -c $$< -o $$@
$(EX_HOST)/$(1): $$(EXAMPLE_CORE:%=$(EX_OBJ)/host-$(1)/core/%.o) $(EX_OBJ)/host-$(1)/$(1).o $(EX_OBJ)/host-$(1)/io_host.o
	@mkdir -p $$(@D)
	@echo "  LD      $$@"
	$$(Q)$$(CC) $$(CFLAGS_H) -o $$@ $$^
$(EX_OBJ)/microbit-$(1)/core/%.o: core/%.c tests/examples.mk
	@mkdir -p $$(@D)
	@echo "  ARMCC   $$<"
	$$(Q)$$(ARM_CC) $$(EX_MB_CFLAGS) $$(EXAMPLE_CFG_$(1)) -MMD -MP -c $$< -o $$@
$(EX_OBJ)/microbit-$(1)/fw/%.o: firmware/%.c tests/examples.mk
	@mkdir -p $$(@D)
	@echo "  ARMCC   $$<"
	$$(Q)$$(ARM_CC) $$(EX_MB_CFLAGS) $$(EXAMPLE_CFG_$(1)) -MMD -MP -c $$< -o $$@
$(EX_OBJ)/microbit-$(1)/%.o: examples/%.c tests/examples.mk
	@mkdir -p $$(@D)
	@echo "  ARMCC   $$<"
	$$(Q)$$(ARM_CC) $$(EX_MB_CFLAGS) $$(EXAMPLE_CFG_$(1)) -MMD -MP -c $$< -o $$@
$(EX_MB)/$(1).elf: $$(EXAMPLE_CORE:%=$(EX_OBJ)/microbit-$(1)/core/%.o) $(EX_OBJ)/microbit-$(1)/$(1).o $(EX_OBJ)/microbit-$(1)/io_board.o \
                    $(EX_OBJ)/microbit-$(1)/fw/startup.o $(EX_OBJ)/microbit-$(1)/fw/semihost.o $(EX_OBJ)/microbit-$(1)/fw/counter.o $$(wildcard linker/*.ld)
	@mkdir -p $$(@D)
	@echo "  ARMLD   $$@"
	$$(Q)$$(ARM_CC) $$(CPU_microbit) -o $$@ $$(filter %.o,$$^) -nostartfiles --specs=nano.specs --specs=nosys.specs \
	  -Wl,--gc-sections -Wl,-Map=$(EX_MB)/$(1).map -Llinker -Tlinker/microbit.ld
endef
$(foreach e,$(EXAMPLES),$(eval $(call example_rules,$(e))))

examples: $(foreach e,$(EXAMPLES),$(EX_HOST)/$(e) $(EX_MB)/$(e).elf)

# The API's unit test, once per number type (like test_geom).
TEST_FXRT_BIN := $(foreach n,$(NUMBERS),$(BUILD)/tests/test_fxrt_$(n))
define test_fxrt_rule
$(BUILD)/tests/test_fxrt_$(1): tests/test_fxrt.c $(BUILD)/host/fx.o $(CORE_NUM:%=$(BUILD)/host/$(1)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(1) $$@"
	$$(Q)$$(CC) $$(CFLAGS_T) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -o $$@ $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach n,$(NUMBERS),$(eval $(call test_fxrt_rule,$(n))))

SUITES_EXTRA += $(TEST_FXRT_BIN) tests/examples.sh tests/cmake.sh
TEST_PREREQ  += $(TEST_FXRT_BIN) $(foreach e,$(EXAMPLES),$(EX_HOST)/$(e) $(EX_MB)/$(e).elf)
.PHONY: examples

# On-board set-up of many scenes in one ELF (tests/qemu.sh):
#   make onboard BOARD=b ONB_DIR=dir   (dir from tests/onboard_gen.sh)
ONB_DIR ?= $(BUILD)/onboard
ONB_SRC = $(CORE_SRC:%=core/%.c) tests/onboard_main.c firmware/startup.c firmware/semihost.c \
          firmware/counter.c
onboard:
	@echo "  ARMCC   $(ONB_DIR)/onboard.elf"
	$(Q)$(ARM_CC) $(WARN) -O2 $(CPU_$(BOARD)) -ffreestanding -ffunction-sections -fdata-sections -DFXRT_NUMBER=1 \
	  -include $(ONB_DIR)/scene_config.h -I$(ONB_DIR) -Icore -Ifirmware $(ONB_SRC) -nostartfiles \
	  --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections -Llinker -Tlinker/$(BOARD).ld -o $(ONB_DIR)/onboard.elf
.PHONY: onboard
# Sanitized too (tests/sanitize.mk's number-generic rule).
NUM_TESTS += test_fxrt
