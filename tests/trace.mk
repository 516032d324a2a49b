# Reflection and refraction: the accuracy suite (tests/trace.sh), the
# no-recursion proof (tests/norecurse.sh) and the bounce oracle
# (tests/test_trace.c, one binary per number type, also sanitized).
# Included by the top Makefile.
#
#   make trace        run tests/trace.sh alone (through tests/run.sh)
#   make norecurse    run tests/norecurse.sh alone
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
