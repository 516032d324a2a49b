# The LM3S6965 evaluation board's OLED (SSD0323, 128x64, 16 greys) in QEMU
# (firmware/oled/). Included by the top Makefile.
#   build/fxrt-oled   the host tool: the firmware's dithering on images,
#                     QEMU screendumps back to levels, the error table
# Everything under build/oled/.

OLED_SRC_DIR := firmware/oled
OLED_BUILD   := $(BUILD)/oled
OLED_TOOL    := $(BUILD)/fxrt-oled

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

# The suites; the hook line below puts them into make test.
OLED_SUITES := $(BUILD)/tests/test_oled_dither
SUITES_EXTRA += $(OLED_SUITES)
TEST_PREREQ  += $(OLED_TOOL) $(BUILD)/tests/test_oled_dither
