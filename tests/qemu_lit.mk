# Lit scenes on the boards (issue 11): tests/qemu_lit.sh, every scenes/lit/
# scene in QEMU on all three boards byte-identical to the host q16 render,
# full-frame and streaming firmware, stack use. Runs in make test.
SUITES_EXTRA += tests/qemu_lit.sh

test-qemu-lit: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) tests/run.sh tests/qemu_lit.sh
.PHONY: test-qemu-lit
