# The visiting order (render_setup sorts the objects nearest first each
# frame) must not change a frame: tests/order.sh renders every scene with
# the host tool and with the host tool built again with FXRT_ABLATE_ORDER
# (scene order), in every number type. Included by the top Makefile.
ORDER_FXRT := $(BUILD)/noorder/fxrt

$(ORDER_FXRT): $(wildcard core/*.h core/*/*.c core/*/*.h host/*.c host/*.h)
	@echo "  MAKE    $@ (FXRT_ABLATE_ORDER)"
	$(Q)$(MAKE) --no-print-directory -s BUILD=$(BUILD)/noorder HOSTCFLAGS='$(HOSTCFLAGS) -DFXRT_ABLATE=FXRT_ABLATE_ORDER' $(BUILD)/noorder/fxrt

TEST_PREREQ  += $(ORDER_FXRT)
SUITES_EXTRA += tests/order.sh
