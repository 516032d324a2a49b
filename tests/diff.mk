# Differential tests of the Q16.16 kernels against the double build
# (tests/test_diff.c, tests/diffk.c) and the kernel fuzzer
# (tests/fuzz_kernels.c). Included by the top Makefile; variables DIFF_*.
#
#   make test           runs build/tests/test_diff (10^6 cases per kind; ten
#                       kinds, five of them lighting) and test_shade_*
#   make stress         10^8 cases per kind on every core, with progress
#   make fuzz-kernels   libFuzzer for FUZZ_SECONDS, artifacts in build/fuzz/

DIFF_NUMBERS := q16 float double
DIFF_BIN     := $(BUILD)/tests/test_diff
DIFF_OBJ     := $(BUILD)/tests/test_diff.o $(BUILD)/host/fx.o $(call multi_objs,$(BUILD),diff,$(DIFF_NUMBERS))

define diff_number_rules
$(BUILD)/tests/diffk-$(1).o: tests/diffk.c
	@mkdir -p $$(@D)
	@echo "  CC $(1)  $$<"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -c $$< -o $$@
endef
$(foreach n,$(DIFF_NUMBERS),$(eval $(call diff_number_rules,$(n))))

$(DIFF_BIN): $(DIFF_OBJ)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $^ -lm

SUITES_EXTRA += $(DIFF_BIN)
TEST_PREREQ  += $(DIFF_BIN)

# tests/test_shade.c: lit worlds built through the API, one binary per
# number type (the Makefile's num_test_rules), also sanitized (sanitize.mk
# builds SAN_EXTRA_BIN and sanitize.sh runs them).
SHADE_TEST_BIN := $(foreach n,$(NUMBERS),$(BUILD)/tests/test_shade_$(n))
$(foreach n,$(NUMBERS),$(eval $(call num_test_rules,test_shade,$(n))))
SUITES_EXTRA  += $(SHADE_TEST_BIN)
TEST_PREREQ   += $(SHADE_TEST_BIN)
SAN_EXTRA_BIN += $(foreach n,$(NUMBERS),$(SAN_DIR)/tests/test_shade_$(n))

# --- make stress -----------------------------------------------------------
DIFF_STRESS_CASES ?= 100000000
DIFF_JOBS         ?= $(shell nproc 2>/dev/null || echo 1)
DIFF_STRESS_LOG   := $(BUILD)/tests/logs/stress.log

stress: $(DIFF_BIN)
	@mkdir -p $(dir $(DIFF_STRESS_LOG))
	@echo "  STRESS  $(DIFF_BIN) $(DIFF_STRESS_CASES) --jobs $(DIFF_JOBS) --progress (log: $(DIFF_STRESS_LOG))"
	$(Q)$(DIFF_BIN) $(DIFF_STRESS_CASES) --jobs $(DIFF_JOBS) --progress >$(DIFF_STRESS_LOG); rc=$$?; \
	  cat $(DIFF_STRESS_LOG); exit $$rc

# --- make fuzz-kernels -------------------------------------------------------
# Everything the harness links (core, fx, diffk) is rebuilt with clang and the
# fuzzer's instrumentation into its own object directory.
DIFF_FUZZ_CC     ?= clang
DIFF_FUZZ_DIR    := $(BUILD)/fuzz
DIFF_FUZZ_OBJDIR := $(DIFF_FUZZ_DIR)/kernels-obj
DIFF_FUZZ_BIN    := $(DIFF_FUZZ_DIR)/fuzz_kernels
DIFF_FUZZ_CORPUS := $(DIFF_FUZZ_DIR)/kernels-corpus
DIFF_FUZZ_SAN    := -fsanitize=address,undefined -fno-sanitize-recover=all
DIFF_FUZZ_CFLAGS := $(WARN) -O1 -g -D_POSIX_C_SOURCE=200809L -Icore $(DIFF_FUZZ_SAN) -fsanitize=fuzzer-no-link
DIFF_FUZZ_OBJ    := $(DIFF_FUZZ_OBJDIR)/host/fx.o $(call multi_objs,$(DIFF_FUZZ_OBJDIR),diff,$(DIFF_NUMBERS))

$(DIFF_FUZZ_OBJDIR)/host/fx.o: $(CORE_FX:%=$(DIFF_FUZZ_OBJDIR)/host/fx/%.o)
	@echo "  LD -r   $@"
	$(Q)ld -r -o $@ $(filter %.o,$^)
$(DIFF_FUZZ_OBJDIR)/host/fx/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  FUZZCC  $<"
	$(Q)$(DIFF_FUZZ_CC) $(DIFF_FUZZ_CFLAGS) -MMD -MP -c $< -o $@

define diff_fuzz_rules
$(DIFF_FUZZ_OBJDIR)/host/$(1)/%.o: core/%.c
	@mkdir -p $$(@D)
	@echo "  FUZZCC $(1) $$<"
	$$(Q)$$(DIFF_FUZZ_CC) $$(DIFF_FUZZ_CFLAGS) -MMD -MP -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@
$(DIFF_FUZZ_OBJDIR)/tests/diffk-$(1).o: tests/diffk.c
	@mkdir -p $$(@D)
	@echo "  FUZZCC $(1) $$<"
	$$(Q)$$(DIFF_FUZZ_CC) $$(DIFF_FUZZ_CFLAGS) -MMD -MP -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -c $$< -o $$@
endef
$(foreach n,$(DIFF_NUMBERS),$(eval $(call diff_fuzz_rules,$(n))))

$(DIFF_FUZZ_OBJDIR)/multi/%.o: $$(addprefix $(DIFF_FUZZ_OBJDIR)/,$$(MULTI_$$*)) host/multi-ld.sh
	$(Q)$(multi_link)

$(DIFF_FUZZ_BIN): tests/fuzz_kernels.c tests/test_diff.c tests/diffk.h tests/check.h $(DIFF_FUZZ_OBJ)
	@mkdir -p $(@D)
	@echo "  FUZZLD  $@"
	$(Q)$(DIFF_FUZZ_CC) $(DIFF_FUZZ_CFLAGS) -fsanitize=fuzzer -o $@ tests/fuzz_kernels.c $(DIFF_FUZZ_OBJ) -lm

# clang and libclang-rt come from make deps.
$(DIFF_FUZZ_OBJ): | deps

# Runs for FUZZ_SECONDS (top Makefile), keeps its corpus between runs, and
# fails, with the case printed and the input in build/fuzz/kernels-crash-*,
# on a violated bound, a crash, a leak or a sanitizer report.
fuzz-kernels: $(DIFF_FUZZ_BIN)
	@mkdir -p $(DIFF_FUZZ_CORPUS)
	@echo "  FUZZ    kernels for $(FUZZ_SECONDS) s (log $(DIFF_FUZZ_DIR)/fuzz-kernels.log)"
	$(Q)start=$$(date +%s); \
	$(DIFF_FUZZ_BIN) -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    -artifact_prefix=$(DIFF_FUZZ_DIR)/kernels- $(DIFF_FUZZ_CORPUS) >$(DIFF_FUZZ_DIR)/fuzz-kernels.log 2>&1; \
	rc=$$?; secs=$$(($$(date +%s) - start)); \
	execs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $(DIFF_FUZZ_DIR)/fuzz-kernels.log | tail -n 1); \
	rate=$$(sed -n 's/^stat::average_exec_per_sec: *//p' $(DIFF_FUZZ_DIR)/fuzz-kernels.log | tail -n 1); \
	files=$$(ls $(DIFF_FUZZ_CORPUS) | wc -l); \
	if [ $$rc -ne 0 ] || grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|^fuzz_kernels:' \
	    $(DIFF_FUZZ_DIR)/fuzz-kernels.log; then \
	    grep -vE '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse|INITED|RELOAD)|^    #[0-9]' $(DIFF_FUZZ_DIR)/fuzz-kernels.log | tail -n 40; \
	    echo "fuzz-kernels: FAILED (exit $$rc) after $${execs:-?} executions; artifacts:"; \
	    ls -1d $(DIFF_FUZZ_DIR)/kernels-* 2>/dev/null | grep -v -e '-corpus$$' -e '-obj$$'; \
	    echo "replay: $(DIFF_FUZZ_BIN) ARTIFACT"; \
	    exit 1; \
	fi; \
	echo "fuzz-kernels: $${execs:-0} executions in $${secs} s ($${rate:-0} exec/s), corpus $$files files, no finding"

.PHONY: stress fuzz-kernels
