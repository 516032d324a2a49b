# Firmware build, included by the top Makefile. One ELF per
# (BOARD, SCENE, NUMBER, SIZE, FB); test scripts call make once per ELF.
#   make fw   SCENE=scenes/abb6-sphere.scene BOARD=mps2-an385 NUMBER=q16 [SIZE=WxH] [FB=full|stream]
#   make qemu (same variables): build, run in QEMU, write
#             build/qemu/BOARD/NAME-NUMBER-WxH[-FW_TAG].ppm
# Without SIZE= the frame has the scene's own size (its `image` line, as
# `fxrt render` does), read by `fxrt size SCENE`. A space in SCENE's path
# works; it becomes '_' in NAME.

BOARD  ?= mps2-an385
NUMBER ?= q16
SCENE  ?= scenes/abb6-sphere.scene

# Per board: CPU flags, SysTick clock period in ns (QEMU's model), and the
# default frame mode (the micro:bit's 16 KB cannot hold a 160x120 frame).
# lm3s6965evb: this firmware leaves the clock at reset, where QEMU derives
# 80 ns (12.5 MHz: 200 MHz / 16, RCC's SYSDIV; make calibrate checks it);
# streaming, as a 160x120 frame (57.6 KB) would fill its 64 KB of RAM.
BOARDS := mps2-an385 mps2-an386 microbit lm3s6965evb
CPU_mps2-an385   := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
CPU_mps2-an386   := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
CPU_microbit     := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
CPU_lm3s6965evb  := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
QEMU_M_mps2-an385 := mps2-an385
QEMU_M_mps2-an386 := mps2-an386
QEMU_M_microbit   := microbit
QEMU_M_lm3s6965evb := lm3s6965evb
TICK_NS_mps2-an385 := 40
TICK_NS_mps2-an386 := 40
TICK_NS_microbit   := 62.5
TICK_NS_lm3s6965evb := 80
FB_mps2-an385 := full
FB_mps2-an386 := full
FB_microbit   := stream
FB_lm3s6965evb := stream
FB ?= $(FB_$(BOARD))
# Every board keeps every sphere's row-coherence state (fxrt-scenec
# --sphere-rows, about 120 B a sphere) where it fits: firmware/fit.sh
# compiles a scene whose state does not fit RAM (the micro:bit's 16 KB with
# many spheres) again without it.
SCENEC_OPTS_mps2-an385 := --sphere-rows
SCENEC_OPTS_mps2-an386 := --sphere-rows
SCENEC_OPTS_microbit   := --sphere-rows
SCENEC_OPTS_lm3s6965evb := --sphere-rows

FB_MODES := full stream

ifeq ($(CPU_$(BOARD)),)
$(error unknown BOARD '$(BOARD)' (one of: $(BOARDS)))
endif
ifeq ($(filter $(NUMBER),$(NUMBERS)),)
$(error unknown NUMBER '$(NUMBER)' (one of: $(NUMBERS)))
endif
ifneq ($(words $(FB))$(filter $(FB),$(FB_MODES)),1$(strip $(FB)))
$(error unknown FB '$(FB)' (one of: $(FB_MODES); default for $(BOARD): $(FB_$(BOARD))))
endif
ifneq ($(origin SIZE),undefined)
# W and H plain decimal integers in 1..4096 (FXRT_MAX_DIM), checked before
# anything is built.
SIZE_OK := $(shell awk -v s="$(subst ",,$(SIZE))" 'BEGIN { n = split(s, a, "x"); \
    print (n == 2 && a[1] ~ /^[0-9]+$$/ && a[2] ~ /^[0-9]+$$/ && a[1] + 0 >= 1 && a[2] + 0 >= 1 && \
           a[1] + 0 <= 4096 && a[2] + 0 <= 4096) ? "ok" : "bad" }')
ifneq ($(words $(SIZE)):$(SIZE_OK):$(findstring ",$(SIZE))$(findstring ',$(SIZE)),1:ok:)
$(error bad SIZE '$(SIZE)' (want WxH, each 1..4096, e.g. 160x120; without SIZE= the scene's own size is used))
endif
endif
ifneq ($(findstring ',$(SCENE))$(findstring ",$(SCENE))$(findstring $$,$(SCENE)),)
$(error SCENE '$(SCENE)': quotes and '$$' in the scene path are not supported (spaces are))
endif

# A space in SCENE: escaped in prerequisite lists, '_' in file names.
fw_space := $(subst ,, )
SCENE_DEP := $(subst $(fw_space),\$(fw_space),$(SCENE))

ARM_CC   := arm-none-eabi-gcc
FW_NAME  := $(subst ?,_,$(basename $(notdir $(subst $(fw_space),?,$(SCENE)))))
# FW_EXTRA adds compiler flags (e.g. -DFXRT_PIXEL=2); name them with FW_TAG.
FW_DIR   := $(BUILD)/fw/$(BOARD)/$(FW_NAME)-$(NUMBER)-$(SIZE)-$(FB)$(if $(FW_TAG),-$(FW_TAG))
FW_ELF   := $(FW_DIR)/fxrt.elf
FW_OUT   := $(FW_NAME)-$(NUMBER)-$(SIZE)$(if $(FW_TAG),-$(FW_TAG)).ppm
FB_FLAG  := $(if $(filter stream,$(FB)),-DFXRT_FB_MODE=2,-DFXRT_FB_MODE=1)
# Debug information for a user's debugger; the test scripts build without
# it (tests/lib.sh sets FW_DEBUG empty: the code is the same, the compile
# a quarter faster).
FW_DEBUG ?= -g
FW_CFLAGS := $(WARN) -O2 $(FW_DEBUG) $(CPU_$(BOARD)) -ffreestanding -ffunction-sections -fdata-sections \
             -fno-math-errno -fstack-usage -DFXRT_NUMBER=$(call num_id,$(NUMBER)) $(FB_FLAG) $(FW_EXTRA) \
             -include $(FW_DIR)/scene_config.h -I$(FW_DIR) -Icore -Ifirmware \
             '-DFXRT_OUT_PATH="$(FW_OUT).part"'
FW_LDFLAGS := -nostartfiles --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections \
              -Wl,-Map=$(FW_DIR)/fxrt.map -Llinker -Tlinker/$(BOARD).ld -lm
FW_SRC   := $(CORE_SRC:%=core/%.c) firmware/main.c firmware/startup.c \
            firmware/semihost.c firmware/counter.c
FW_OBJ   := $(patsubst %.c,$(FW_DIR)/%.o,$(FW_SRC))

# This ELF's dependency files only (the top Makefile skips build/fw).
-include $(wildcard $(FW_OBJ:.o=.d))

# The directory is named after the scene file's base name: scenes/lit/room
# and scenes/bench/room share one. The scene's path (with --all-kinds and
# the board's scene compiler options) is recorded, so that switching
# between them rebuilds instead of running the other scene's firmware.
$(FW_DIR)/scene-path: FORCE
	@mkdir -p $(@D)
	@echo '$(SCENE) $(FW_ALL_KINDS) $(SCENEC_OPTS_$(BOARD))' | cmp -s - $@ || \
	  echo '$(SCENE) $(FW_ALL_KINDS) $(SCENEC_OPTS_$(BOARD))' > $@

$(FW_DIR)/scene_data.h: $(SCENE_DEP) $(BUILD)/fxrt-scenec $(FW_DIR)/scene-path
	@mkdir -p $(@D)
	@echo "  SCENEC  $(SCENE) -> $(@D)"
	$(Q)$(BUILD)/fxrt-scenec '$(SCENE)' --number $(NUMBER) --size $(SIZE) --out $(@D) $(if $(FW_ALL_KINDS),--all-kinds) $(SCENEC_OPTS_$(BOARD))
$(FW_DIR)/scene_config.h: $(FW_DIR)/scene_data.h

# Rebuild when the flags change (the directory name does not encode them all).
$(FW_DIR)/cflags: FORCE
	@mkdir -p $(@D)
	@echo '$(FW_CFLAGS)' | cmp -s - $@ || echo '$(FW_CFLAGS)' > $@

$(FW_DIR)/%.o: %.c $(FW_DIR)/scene_data.h $(FW_DIR)/cflags
	@mkdir -p $(@D)
	@echo "  ARMCC   $<"
	$(Q)$(ARM_CC) $(FW_CFLAGS) -MMD -MP -c $< -o $@

# The link goes through firmware/fit.sh: a scene too big for the board fails
# with what fits (kinds and counts), not a linker overflow, and leaves no ELF.
# FIT_REPORT=1 prints the RAM figures even when it fits (make ram-table).
$(FW_ELF): $(FW_OBJ) $(wildcard linker/*.ld) firmware/fit.sh
	@echo "  ARMLD   $@"
	$(file >$(FW_DIR)/fit-cflags,$(FW_CFLAGS))
	$(file >$(FW_DIR)/fit-src,$(FW_SRC))
	$(file >$(FW_DIR)/fit-ldflags,$(foreach f,$(FW_LDFLAGS),$(if $(findstring -Map=,$(f))$(filter -T%,$(f)),,$(f))))
	$(Q)BUILD=$(BUILD) BOARD=$(BOARD) SCENE='$(SCENE)' ARM_CC=$(ARM_CC) CPU='$(CPU_$(BOARD))' FIT_REPORT=$(FIT_REPORT) \
	  firmware/fit.sh link $(FW_DIR) $@

ifeq ($(origin SIZE),undefined)
# No SIZE=: check the scene and take its size from the host tool, then
# build and run with SIZE set (the other variables pass on by MAKEFLAGS).
fw qemu: $(BUILD)/fxrt
	$(Q)size=$$($(BUILD)/fxrt size -- '$(SCENE)') && \
	  $(MAKE) --no-print-directory $@ SIZE=$$size
else
fw: $(FW_ELF)

# Run in QEMU: deterministic (-icount), with a timeout; prints instructions=N.
qemu: $(FW_ELF) $(BUILD)/fxrt
	$(Q)BOARD=$(BOARD) QEMU_M=$(QEMU_M_$(BOARD)) TICK_NS=$(TICK_NS_$(BOARD)) FXRT=$(BUILD)/fxrt \
	  firmware/qemu-run.sh $(FW_ELF) $(BUILD)/qemu/$(BOARD) $(FW_OUT)
endif

# The calibration image: a loop of exactly 2*10^6 instructions.
CAL_ELF := $(BUILD)/fw/$(BOARD)/calibrate.elf
$(CAL_ELF): firmware/calibrate.c firmware/startup.c firmware/semihost.c firmware/counter.c
	@mkdir -p $(@D)
	@echo "  ARMCC   $@"
	$(Q)$(ARM_CC) $(WARN) -Os $(CPU_$(BOARD)) -ffreestanding -Ifirmware $^ -nostartfiles \
	  --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections -Llinker -Tlinker/$(BOARD).ld -o $@
calibrate: $(CAL_ELF)
	$(Q)BOARD=$(BOARD) QEMU_M=$(QEMU_M_$(BOARD)) TICK_NS=$(TICK_NS_$(BOARD)) \
	  firmware/qemu-run.sh $(CAL_ELF) $(BUILD)/qemu/$(BOARD) -

.PHONY: fw qemu calibrate FORCE
FORCE:
