# The scene format's lighting keywords beyond the parser (test_scene has
# the parser): engine_describe/engine_build in each number type
# (tests/test_scene_light.c) and what fxrt-scenec emits for the firmware
# (tests/scenec_light.sh). Included by the top Makefile.
SCENE_LIGHT_BIN := $(foreach n,$(NUMBERS),$(BUILD)/tests/test_scene_light_$(n))
define scene_light_rules
$(BUILD)/tests/test_scene_light_$(1): tests/test_scene_light.c tests/check.h $(SCENE_LIB) \
    $(BUILD)/host/fx.o $(BUILD)/host/engine-$(1).o $(CORE_NUM:%=$(BUILD)/host/$(1)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(1) $$@"
	$$(Q)$$(CC) $$(CFLAGS_T) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -o $$@ \
	  $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach n,$(NUMBERS),$(eval $(call scene_light_rules,$(n))))

SUITES_EXTRA += $(SCENE_LIGHT_BIN) tests/scenec_light.sh
TEST_PREREQ  += $(SCENE_LIGHT_BIN)
