# The "skip what the scene does not need" tests (tests/skip.sh): the work
# counters (tests/test_skip.c, core built with FXRT_STATS 1, once per
# number type) and the link-time checks. Included by the top Makefile.
SKIP_NUMBERS := q16 double
SKIP_BIN     := $(SKIP_NUMBERS:%=$(BUILD)/tests/test_skip_%)

define skip_rules
$(BUILD)/tests/test_skip_$(1): tests/test_skip.c tests/check.h $(wildcard core/*.h core/*/*.c core/*/*.h)
	@mkdir -p $$(@D)
	@echo "  CC/LD $(1) $$@"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_STATS=1 -DFXRT_NUMBER=$$(call num_id,$(1)) -Icore -Wl,--wrap=geom_sphere_hit -Wl,--wrap=geom_sphere_occludes -Wl,--wrap=render_setup -Wl,--wrap=shade_flat_plane_pixels \
	  -o $$@ tests/test_skip.c $$(wildcard core/*/*.c) -lm
endef
$(foreach n,$(SKIP_NUMBERS),$(eval $(call skip_rules,$(n))))

TEST_PREREQ += $(SKIP_BIN)
SUITES_EXTRA += tests/skip.sh
