# The visiting order (render_setup sorts the objects nearest first each
# frame), the shadow rows (light/shadow.c: per-row masks of the objects
# that cannot block a plane's shadow rays), the flat objects' hit
# numerators kept across pixels, with the runs of their pixels shaded at
# once (frame/render_shade.c, FXRT_SHADE_RUNS), a model's quick
# box test (scene/bvh.c) and the triangles' shadow edges (light/shadow.c)
# must not change a frame:
# tests/order.sh renders every scene with the host tool and with the host
# tool built again with all five switched off (FXRT_ABLATE_ORDER,
# FXRT_ABLATE_SHADOW_ROWS, FXRT_ABLATE_FLAT_NUM, FXRT_ABLATE_BVH_QUICK,
# FXRT_SHADOW_EDGES 0),
# in every number type (built without -g: only its frames are read).
# Included by the top
# Makefile.
ORDER_FXRT := $(BUILD)/ablated/fxrt

$(ORDER_FXRT): $(wildcard core/*.h core/*/*.c core/*/*.h host/*.c host/*.h)
	@echo "  MAKE    $@ (FXRT_ABLATE_ORDER, FXRT_ABLATE_SHADOW_ROWS, FXRT_ABLATE_FLAT_NUM, FXRT_ABLATE_BVH_QUICK, FXRT_SHADOW_EDGES 0)"
	$(Q)$(MAKE) --no-print-directory -s BUILD=$(BUILD)/ablated HOSTCFLAGS='$(filter-out -g,$(HOSTCFLAGS)) -DFXRT_ABLATE="(FXRT_ABLATE_ORDER|FXRT_ABLATE_SHADOW_ROWS|FXRT_ABLATE_FLAT_NUM|FXRT_ABLATE_BVH_QUICK)" -DFXRT_SHADOW_EDGES=0' $(BUILD)/ablated/fxrt

TEST_PREREQ  += $(ORDER_FXRT)
SUITES_EXTRA += tests/order.sh
