# The scene format's reflection, refraction and supersampling keywords
# beyond the parser (test_scene has the parser): engine_describe,
# engine_build and the key pass of engine_render in each number type
# (tests/test_scene_trace.c), and what fxrt-scenec emits for them
# (tests/scenec_trace.sh). Included by the top Makefile.
SCENE_TRACE_BIN := $(foreach n,$(NUMBERS),$(BUILD)/tests/test_scene_trace_$(n))
define scene_trace_rules
$(BUILD)/tests/test_scene_trace_$(1): tests/test_scene_trace.c tests/check.h $(SCENE_LIB) \
    $(BUILD)/host/fx.o $(BUILD)/host/engine-$(1).o $(CORE_NUM:%=$(BUILD)/host/$(1)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(1) $$@"
	$$(Q)$$(CC) $$(CFLAGS_T) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -o $$@ \
	  $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach n,$(NUMBERS),$(eval $(call scene_trace_rules,$(n))))

SUITES_EXTRA += $(SCENE_TRACE_BIN) tests/scenec_trace.sh
TEST_PREREQ  += $(SCENE_TRACE_BIN)
