# Colour sweep (tests/test_color.c): every colour 0.0000..1.0000 in steps of
# 0.0001, parsed, built and rendered by all three builds, gives the same
# 8-bit value (docs/ACCURACY.md, "Colour"). Included by the top Makefile.
COLOR_BIN := $(BUILD)/tests/test_color
test_color_DEPS := $(SCENE_LIB) $(BUILD)/host/engine_select.o $(BUILD)/host/fx.o \
                   $(call multi_objs,$(BUILD),fxrt,$(NUMBERS))

SUITES_EXTRA += $(COLOR_BIN)
TEST_PREREQ  += $(COLOR_BIN)
# Sanitized too (tests/sanitize.mk builds test_X from test_X_DEPS).
UNIT_TESTS += test_color
