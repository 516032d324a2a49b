# Reflection and refraction: the accuracy suite (tests/trace.sh), the
# no-recursion proof (tests/norecurse.sh) and the bounce oracle
# (tests/test_trace.c, one binary per number type, also sanitized).
# Included by the top Makefile.
#
#   make trace        run tests/trace.sh alone (through tests/run.sh)
#   make norecurse    run tests/norecurse.sh alone
#   make cutoff       the cut-off against none (tests/cutoff.sh; not in make test)
#
# All three are part of `make test` (SUITES_EXTRA below).

trace: deps $(BUILD)/fxrt
	$(Q)BUILD=$(BUILD) tests/run.sh tests/trace.sh

norecurse: deps
	$(Q)BUILD=$(BUILD) tests/run.sh tests/norecurse.sh

.PHONY: trace norecurse
SUITES_EXTRA += tests/trace.sh tests/norecurse.sh

# tests/test_trace.c: the bounce model against a double oracle, one binary
# per number type (the Makefile's num_test_rules), also sanitized.
TRACE_TEST_BIN := $(foreach n,$(NUMBERS),$(BUILD)/tests/test_trace_$(n))
$(foreach n,$(NUMBERS),$(eval $(call num_test_rules,test_trace,$(n))))
SUITES_EXTRA  += $(TRACE_TEST_BIN)
TEST_PREREQ   += $(TRACE_TEST_BIN)
SAN_EXTRA_BIN += $(foreach n,$(NUMBERS),$(SAN_DIR)/tests/test_trace_$(n))

# The cut-off's effect (tests/cutoff.sh): a second host tool built with
# FXRT_ABLATE_CUTOFF in $(BUILD)/nocut, against the normal one. Not part of
# make test (the second build takes a minute).
#
#   make cutoff
cutoff: deps $(BUILD)/fxrt
	$(Q)$(MAKE) --no-print-directory BUILD=$(BUILD)/nocut HOSTCFLAGS="$(HOSTCFLAGS) -DFXRT_ABLATE=FXRT_ABLATE_CUTOFF" $(BUILD)/nocut/fxrt
	$(Q)BUILD=$(BUILD) CUTOFF_FXRT=$(BUILD)/nocut/fxrt tests/run.sh tests/cutoff.sh
.PHONY: cutoff
