# Trace scenes on the boards (issue 12): tests/qemu_trace.sh, every
# scenes/trace/ and scenes/stress/trace-* scene (and samples 2 / samples 2
# adaptive variants) in QEMU on all three boards byte-identical to the
# host q16 render, the deepest scene's stack per board, the reflection
# scene at 160x120 samples 2 on the micro:bit, float on the M4F. Runs in
# make test.
SUITES_EXTRA += tests/qemu_trace.sh

test-qemu-trace: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) tests/run.sh tests/qemu_trace.sh
.PHONY: test-qemu-trace
