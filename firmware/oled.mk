# The LM3S6965 evaluation board's OLED (SSD0323, 128x64, 16 greys) in QEMU
# (firmware/oled/, docs/OLED.md). Included by the top Makefile.
#   make oled-fw   OLED_SCENE=S [OLED_FRAMES=N OLED_TURN=DEG OLED_METHOD=M]
#                  the OLED firmware for scene S at 128x64 (frames, degrees
#                  the camera turns a frame, dithering: none bayer4 bayer8 fs,
#                  or cycle: frame f in method f mod 4)
#   make oled-qemu (same variables) OLED_OUT=DIR OLED_PREFIX=P
#                  run it with a screendump after every frame: DIR/P-FF.ppm
#   make oled-host (same variables) OLED_OUT=DIR
#                  the same program on the host: DIR/frame-FF.ppm (RGB)
#   make oled-demo the seed sphere and a lit scene on the display, and a
#                  turntable: build/demo/oled-*.png (firmware/oled/oled-demo.sh)
#   make oled-table  each dithering method's error (firmware/oled/oled-table.sh)
#                  OLED_UPDATE_DOCS=1 (for both): rewrite docs/OLED.md's blocks
#   make test-oled tests/oled.sh and the dithering unit test
# Everything under build/oled/ (build/fxrt-oled: the host tool).

OLED_SRC_DIR := firmware/oled
OLED_BUILD   := $(BUILD)/oled
OLED_TOOL    := $(BUILD)/fxrt-oled
OLED_BOARD   := lm3s6965evb

# --- host tool and unit test ----------------------------------------------
$(OLED_BUILD)/host/%.o: $(OLED_SRC_DIR)/%.c
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CFLAGS_H) -I$(OLED_SRC_DIR) -Ihost -c $< -o $@

$(OLED_TOOL): $(OLED_BUILD)/host/oled_tool.o $(OLED_BUILD)/host/dither.o $(BUILD)/host/image.o $(BUILD)/host/errf.o
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $^ $(LDLIBS_H)

test_oled_dither_DEPS := $(OLED_BUILD)/host/dither.o
$(BUILD)/tests/test_oled_dither.o: CFLAGS_H += -I$(OLED_SRC_DIR)
# Its ASan+UBSan twin, which tests/sanitize.sh runs (tests/sanitize.mk).
$(SAN_DIR)/oled/host/%.o: $(OLED_SRC_DIR)/%.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -I$(OLED_SRC_DIR) -c $< -o $@
$(SAN_DIR)/tests/test_oled_dither.o: SAN_CFLAGS += -I$(OLED_SRC_DIR)
SAN_EXTRA_BIN += $(SAN_DIR)/tests/test_oled_dither

# --- firmware and its host twin, one directory per configuration ----------
OLED_SCENE  ?= scenes/abb6-sphere.scene
OLED_FRAMES ?= 1
OLED_TURN   ?= 0
OLED_METHOD ?= fs
OLED_HANDSHAKE ?= 1
oled_method_id = $(if $(filter cycle,$1),-1,$(if $(filter none,$1),0,$(if $(filter bayer4,$1),1,$(if $(filter bayer8,$1),2,$(if $(filter fs,$1),3,bad)))))
OLED_METHOD_ID := $(call oled_method_id,$(OLED_METHOD))
OLED_NAME   := $(basename $(notdir $(OLED_SCENE)))
OLED_DIR    := $(OLED_BUILD)/fw/$(OLED_NAME)-f$(OLED_FRAMES)-t$(OLED_TURN)-$(OLED_METHOD)$(if $(filter 0,$(OLED_HANDSHAKE)),-nohs)
OLED_ELF    := $(OLED_DIR)/oled.elf
OLED_HOST   := $(OLED_DIR)/host/oled-show-host

OLED_FW_SRC := $(CORE_SRC:%=core/%.c) firmware/startup.c firmware/semihost.c firmware/counter.c \
               $(addprefix $(OLED_SRC_DIR)/,oled_board.c oled_show.c ssd0323.c lm3s6965.c dither.c)
OLED_FW_OBJ := $(patsubst %.c,$(OLED_DIR)/arm/%.o,$(OLED_FW_SRC))
OLED_HOST_SRC := $(CORE_SRC:%=core/%.c) $(addprefix $(OLED_SRC_DIR)/,oled_host.c oled_show.c dither.c)
OLED_HOST_OBJ := $(patsubst %.c,$(OLED_DIR)/host/%.o,$(OLED_HOST_SRC))
OLED_DEFS = -DFXRT_NUMBER=1 -DOLED_FRAMES=$(OLED_FRAMES) -DOLED_TURN_DEG=$(OLED_TURN) -DOLED_METHOD=$(OLED_METHOD_ID) \
            -DOLED_HANDSHAKE=$(OLED_HANDSHAKE) -include $(OLED_DIR)/scene_config.h -I$(OLED_DIR) -Icore -Ifirmware \
            -I$(OLED_SRC_DIR)
OLED_FW_CFLAGS = $(WARN) -O2 $(FW_DEBUG) $(CPU_$(OLED_BOARD)) -ffreestanding -ffunction-sections -fdata-sections \
                 -fno-math-errno -fstack-usage $(OLED_DEFS)

# The scene at the display's size. A turning camera may see other box
# faces than the scene's own (fxrt-scenec sizes the face pool for that
# one): the pool goes back to the core's default, 6 a box.
$(OLED_DIR)/scene-path: FORCE
	@mkdir -p $(@D)
	@echo '$(OLED_SCENE) $(OLED_TURN)' | cmp -s - $@ || echo '$(OLED_SCENE) $(OLED_TURN)' > $@
$(OLED_DIR)/scene_data.h: $(OLED_SCENE) $(BUILD)/fxrt-scenec $(OLED_DIR)/scene-path
	@echo "  SCENEC  $(OLED_SCENE) -> $(@D)"
	$(Q)$(BUILD)/fxrt-scenec '$(OLED_SCENE)' --number q16 --size 128x64 --out $(@D) $(SCENEC_OPTS_$(OLED_BOARD))
	$(Q)$(if $(filter-out 0,$(OLED_TURN)),sed -i '/^#define FXRT_RENDER_BOX_FACES /d' $(@D)/scene_config.h)
$(OLED_DIR)/scene_config.h: $(OLED_DIR)/scene_data.h
$(OLED_DIR)/cflags: FORCE
	@mkdir -p $(@D)
	@echo '$(OLED_FW_CFLAGS) $(CFLAGS_H)' | cmp -s - $@ || echo '$(OLED_FW_CFLAGS) $(CFLAGS_H)' > $@

$(OLED_DIR)/arm/%.o: %.c $(OLED_DIR)/scene_data.h $(OLED_DIR)/cflags
	@mkdir -p $(@D)
	@echo "  ARMCC   $<"
	$(Q)$(ARM_CC) $(OLED_FW_CFLAGS) -MMD -MP -c $< -o $@
$(OLED_ELF): $(OLED_FW_OBJ) linker/$(OLED_BOARD).ld linker/sections.ld
	@echo "  ARMLD   $@"
	$(Q)$(ARM_CC) $(CPU_$(OLED_BOARD)) -o $@ $(OLED_FW_OBJ) -nostartfiles --specs=nano.specs --specs=nosys.specs \
	  -Wl,--gc-sections -Wl,-Map=$(OLED_DIR)/oled.map -Llinker -Tlinker/$(OLED_BOARD).ld

$(OLED_DIR)/host/%.o: %.c $(OLED_DIR)/scene_data.h $(OLED_DIR)/cflags
	@mkdir -p $(@D)
	@echo "  CC      $<"
	$(Q)$(CC) $(CFLAGS_H) $(OLED_DEFS) -c $< -o $@
$(OLED_HOST): $(OLED_HOST_OBJ)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $^ -lm

OLED_OUT    ?= $(OLED_BUILD)/out
OLED_PREFIX ?= oled-$(OLED_NAME)
oled-check:
	@test "$(OLED_METHOD_ID)" != bad || { echo "OLED_METHOD '$(OLED_METHOD)': one of none bayer4 bayer8 fs cycle" >&2; exit 2; }
oled-fw: oled-check $(OLED_ELF)
oled-qemu: oled-check $(OLED_ELF)
	$(Q)firmware/oled/oled-run.sh $(OLED_ELF) $(OLED_OUT) $(OLED_PREFIX) $(OLED_FRAMES)
oled-host: oled-check $(OLED_HOST)
	@mkdir -p $(OLED_OUT)
	$(Q)$(OLED_HOST) $(OLED_OUT)

oled-demo: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec $(OLED_TOOL)
	$(Q)BUILD=$(BUILD) OLED_UPDATE_DOCS=$(OLED_UPDATE_DOCS) firmware/oled/oled-demo.sh
oled-table: $(BUILD)/fxrt $(OLED_TOOL)
	$(Q)BUILD=$(BUILD) OLED_UPDATE_DOCS=$(OLED_UPDATE_DOCS) firmware/oled/oled-table.sh

# The suites (tests/run.sh runs tests/oled.sh in its second lane: it
# builds only under build/oled/ and build/fw/lm3s6965evb/, which no other
# suite uses). The hook: this one line puts them into make test.
OLED_SUITES := $(BUILD)/tests/test_oled_dither tests/oled.sh
SUITES_EXTRA += $(OLED_SUITES)
TEST_PREREQ  += $(OLED_TOOL) $(BUILD)/tests/test_oled_dither
test-oled: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec $(OLED_TOOL) $(BUILD)/tests/test_oled_dither
	$(Q)BUILD=$(BUILD) tests/run.sh $(OLED_SUITES)

.PHONY: oled-check oled-fw oled-qemu oled-host oled-demo oled-table test-oled
