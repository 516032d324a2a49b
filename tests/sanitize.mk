# Sanitizers and fuzzing; -included by the top Makefile (docs/TESTING.md).
#
#   make sanitize            host tool + every unit test built with clang
#                            ASan+UBSan into $(BUILD)/san/, then
#                            tests/sanitize.sh runs them, cli.sh, golden.sh
#                            and the no-partial-output check
#   make fuzz-scene          libFuzzer over scene_parse for $(FUZZ_SECONDS) s;
#                            corpus and crash artifacts in $(BUILD)/fuzz/
#   make test                also runs tests/fuzz-short.sh (FUZZ_CI_SECONDS)
#                            and tests/sanitize.sh
#
# The sanitized build mirrors the normal one: its object and binary lists
# are the Makefile's (HOST_OBJ, UNIT_TESTS, NUM_TESTS, *_DEPS) with
# $(BUILD)/ replaced by $(BUILD)/san/, so a source added there is picked
# up here without editing this file.

SAN_CC     ?= clang
SAN_DIR    := $(BUILD)/san
SAN_FLAGS  := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -gline-tables-only -O1
SAN_CFLAGS := $(WARN) $(SAN_FLAGS) -D_POSIX_C_SOURCE=200809L -MMD -MP -Icore
# The test programs' own sources (tests/*.c, the checks, not the code under
# test) at -O0: the sanitizers check them as well at any level, and clang
# compiles them about ten times faster (tests/test_geom.c: 9 s at -O1, 0.8
# s at -O0, in each of three number types); the core and host/ stay at -O1.
# Tests whose run is mostly their own reference arithmetic stay at -O1
# (SAN_TEST_O1): at -O0 they would run longer than their compile saves.
SAN_TEST_CFLAGS = $(patsubst -O1,-O0,$(SAN_CFLAGS))
SAN_TEST_O1 := test_shade test_fx
$(foreach t,$(SAN_TEST_O1),$(eval $(SAN_DIR)/tests/$(t)%: SAN_TEST_CFLAGS = $$(SAN_CFLAGS)))

# $(call san_path,FILES): the sanitized twin of files under $(BUILD)/.
san_path = $(patsubst $(BUILD)/%,$(SAN_DIR)/%,$1)

# Recursive (=) so that tests added to UNIT_TESTS/NUM_TESTS after this file
# is read (e.g. by another fragment) are included too.
SAN_FXRT     = $(SAN_DIR)/fxrt
SAN_HOST_OBJ = $(call san_path,$(HOST_OBJ))
SAN_UNIT_BIN = $(UNIT_TESTS:%=$(SAN_DIR)/tests/%)
SAN_NUM_BIN  = $(foreach t,$(NUM_TESTS),$(foreach n,$(NUMBERS),$(SAN_DIR)/tests/$(t)_$(n)))
# Fragments with test binaries of their own add their sanitized twins here.
SAN_EXTRA_BIN ?=
SAN_BIN      = $(SAN_FXRT) $(SAN_UNIT_BIN) $(SAN_NUM_BIN) $(SAN_EXTRA_BIN)

$(SAN_FXRT): $$(SAN_HOST_OBJ)
	@echo "  LD san  $@"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -o $@ $(filter %.o,$^) $(LDLIBS_H)

$(SAN_DIR)/host/%.o: host/%.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -c $< -o $@

$(SAN_DIR)/host/fx.o: $(CORE_FX:%=$(SAN_DIR)/host/fx/%.o)
	@echo "  LD -r   $@"
	$(Q)ld -r -o $@ $(filter %.o,$^)
$(SAN_DIR)/host/fx/%.o: core/%.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -c $< -o $@

# core/*.c and host/engine.c once per number type, as number_rules does.
define san_number_rules
$(SAN_DIR)/host/$(1)/%.o: core/%.c
	@mkdir -p $$(@D)
	@echo "  CC san $(1)  $$<"
	$$(Q)$$(SAN_CC) $$(SAN_CFLAGS) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@
$(SAN_DIR)/host/engine-$(1).o: host/engine.c
	@mkdir -p $$(@D)
	@echo "  CC san $(1)  $$<"
	$$(Q)$$(SAN_CC) $$(SAN_CFLAGS) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -c $$< -o $$@

# Number-generic tests (NUM_TESTS): one binary per number type. The
# shorter stem makes this rule win over the unit-test rule below.
$(SAN_DIR)/tests/%_$(1): tests/%.c $(SAN_DIR)/host/fx.o $(CORE_NUM:%=$(SAN_DIR)/host/$(1)/%.o)
	@mkdir -p $$(@D)
	@echo "  CC/LD san $(1) $$@"
	$$(Q)$$(SAN_CC) $$(SAN_TEST_CFLAGS) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -o $$@ $$(filter %.c %.o,$$^) $$(LDLIBS_H)
endef
$(foreach n,$(NUMBERS),$(eval $(call san_number_rules,$(n))))

$(SAN_DIR)/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	@echo "  CC san  $<"
	$(Q)$(SAN_CC) $(SAN_TEST_CFLAGS) -Ihost -Icore -c $< -o $@

# Unit tests: test_X links test_X.o and the sanitized twins of test_X_DEPS
# (the Makefile enables .SECONDEXPANSION).
$(SAN_DIR)/tests/%: $(SAN_DIR)/tests/%.o $$(call san_path,$$($$*_DEPS))
	@echo "  LD san  $@"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -o $@ $(filter %.o,$^) $(LDLIBS_H)

# The oracle (tests/oracle.mk) and the differential kernel test
# (tests/diff.mk): their object lists with $(BUILD)/ replaced by
# $(SAN_DIR)/; the per-number test sources get their own rules here.
SAN_ORACLE = $(SAN_DIR)/tests/oracle
SAN_DIFF   = $(SAN_DIR)/tests/test_diff
define san_number_test_rules
$(SAN_DIR)/tests/oracle_num-$(1).o: tests/oracle_num.c
	@mkdir -p $$(@D)
	@echo "  CC san $(1)  $$<"
	$$(Q)$$(SAN_CC) $$(SAN_CFLAGS) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -c $$< -o $$@
$(SAN_DIR)/tests/diffk-$(1).o: tests/diffk.c
	@mkdir -p $$(@D)
	@echo "  CC san $(1)  $$<"
	$$(Q)$$(SAN_CC) $$(SAN_CFLAGS) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -c $$< -o $$@
endef
$(foreach n,$(NUMBERS),$(eval $(call san_number_test_rules,$(n))))

$(SAN_DIR)/multi/%.o: $$(addprefix $(SAN_DIR)/,$$(MULTI_$$*)) host/multi-ld.sh
	$(Q)$(multi_link)

$(SAN_ORACLE): $$(call san_path,$$(ORACLE_OBJ))
	@echo "  LD san  $@"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -o $@ $(filter %.o,$^) -lm

$(SAN_DIFF): $$(call san_path,$$(DIFF_OBJ))
	@echo "  LD san  $@"
	$(Q)$(SAN_CC) $(SAN_CFLAGS) -o $@ $(filter %.o,$^) -lm

# tests/test_bvh.c and test_model.c with host/meshbuild.c (the Makefile's bvh_test_rules).
$(foreach t,$(BVH_TESTS),$(foreach n,$(NUMBERS),$(eval $(call bvh_test_rules,$(n),$(SAN_DIR),$$(SAN_CC),$$(SAN_CFLAGS),$(t)))))
SAN_EXTRA_BIN += $(foreach t,$(BVH_TESTS),$(foreach n,$(NUMBERS),$(SAN_DIR)/tests/$(t)_$(n)))

# san-build: everything tests/sanitize.sh runs, and the list of test
# binaries it runs (so the script need not know the Makefile's names).
# The fuzz harnesses are sanitized already; sanitize.sh replays their
# corpora (the kernel harness, 48 more objects, only under make test-full).
# The sanitized oracle runs in the full scope only (sanitize.sh): make
# test-full and make sanitize build it.
san-build: $$(SAN_BIN) $$(SAN_DIFF) $$(FUZZ_SCENE_BIN)
	$(Q)printf '%s\n' $(SAN_UNIT_BIN) $(SAN_NUM_BIN) $(SAN_EXTRA_BIN) >$(SAN_DIR)/tests.list

sanitize: deps san-build $$(SAN_ORACLE)
	$(Q)BUILD=$(BUILD) tests/sanitize.sh

# --- libFuzzer ------------------------------------------------------------
FUZZ_DIR      := $(BUILD)/fuzz
FUZZ_CC       ?= clang
FUZZ_SAN      := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1
FUZZ_CFLAGS   := $(WARN) -D_POSIX_C_SOURCE=200809L -MMD -MP -Icore
FUZZ_TIMEOUT  ?= 5
FUZZ_MAX_LEN  ?= 4096
FUZZ_SCENE_BIN := $(FUZZ_DIR)/fuzz_scene
FUZZ_SCENE_CORPUS := $(FUZZ_DIR)/scene-corpus
FUZZ_SCENE_SEEDS = $(wildcard scenes/*.scene scenes/stress/*.scene scenes/lit/*.scene scenes/trace/*.scene \
    tests/bad-scenes/*.scene tests/scenes/*.scene)

$(FUZZ_DIR)/obj/%.o: host/%.c
	@mkdir -p $(@D)
	@echo "  CC fuzz $<"
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_SAN) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_DIR)/obj/fuzz_scene.o: tests/fuzz_scene.c
	@mkdir -p $(@D)
	@echo "  CC fuzz $<"
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_SAN) -fsanitize=fuzzer-no-link -Ihost -Icore -c $< -o $@

$(FUZZ_SCENE_BIN): $(FUZZ_DIR)/obj/fuzz_scene.o $(FUZZ_DIR)/obj/scene.o $(FUZZ_DIR)/obj/obj.o $(FUZZ_DIR)/obj/xform.o $(FUZZ_DIR)/obj/errf.o \
                  $(FUZZ_DIR)/obj/meshstore.o $(FUZZ_DIR)/obj/meshbuild.o
	@echo "  LD fuzz $@"
	$(Q)$(FUZZ_CC) $(FUZZ_SAN) -fsanitize=fuzzer -o $@ $(filter %.o,$^) -lm

# Keywords and edge values for libFuzzer's mutator (-dict).
FUZZ_SCENE_DICT_WORDS := image background camera perspective orthographic plane sphere \
    triangle box point normal center radius a b c min max color eye gaze up fov scale \
    8192 -8192 8192.0001 4096 4096.0001 180 179.99999 0.0000152587890625 0.00001 \
    1e-5 1e99999 1e-400 -0 0.5 1 nan inf 0x1 32767 65536 \
    ambient light directional spot position direction angle shadows on off material flat lambert \
    phong specular exponent 90 90.0001 1024 1025 64.0 \
    reflective transparent reflection index depth samples adaptive 0.01 0.00999 100 100.0001 1.33 16 17 \
    node end mesh file shading smooth rotate translate x y z 36000 36000.0001 scenes/models/cube.obj \
    ellipsoid parallelepiped u v w

$(FUZZ_DIR)/scene.dict: tests/sanitize.mk
	@mkdir -p $(@D)
	$(Q){ for w in $(FUZZ_SCENE_DICT_WORDS); do printf '"%s"\n' "$$w"; done; \
	      printf '%s\n' '"#"' '"\x09"' '"\x0d\x0a"' '"\x0a"' '"\x0d"'; } >$@

# Seeds are copied as seed-DIR_NAME; libFuzzer adds its finds (named by
# SHA-1) next to them. Crashes/timeouts/leaks go to $(FUZZ_DIR)/scene-*.
# The log is $(FUZZ_DIR)/fuzz-scene.log; the last lines summarise the run.
fuzz-scene: $(FUZZ_SCENE_BIN) $(FUZZ_DIR)/scene.dict
	$(Q)mkdir -p $(FUZZ_SCENE_CORPUS)
	$(Q)for f in $(FUZZ_SCENE_SEEDS); do cp "$$f" "$(FUZZ_SCENE_CORPUS)/seed-$$(printf '%s' "$$f" | tr / _)"; done
	@echo "  FUZZ    scene_parse for $(FUZZ_SECONDS) s (log $(FUZZ_DIR)/fuzz-scene.log)"
	$(Q)start=$$(date +%s); \
	$(FUZZ_SCENE_BIN) -max_total_time=$(FUZZ_SECONDS) -max_len=$(FUZZ_MAX_LEN) \
	    -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 -dict=$(FUZZ_DIR)/scene.dict \
	    -artifact_prefix=$(FUZZ_DIR)/scene- -print_final_stats=1 \
	    $(FUZZ_SCENE_CORPUS) >$(FUZZ_DIR)/fuzz-scene.log 2>&1; \
	rc=$$?; secs=$$(($$(date +%s) - start)); \
	execs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $(FUZZ_DIR)/fuzz-scene.log | tail -n 1); \
	rate=$$(sed -n 's/^stat::average_exec_per_sec: *//p' $(FUZZ_DIR)/fuzz-scene.log | tail -n 1); \
	files=$$(ls $(FUZZ_SCENE_CORPUS) | wc -l); \
	if [ $$rc -ne 0 ] || grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|==ERROR' $(FUZZ_DIR)/fuzz-scene.log; then \
	    grep -vE '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse|INITED|RELOAD)' $(FUZZ_DIR)/fuzz-scene.log | tail -n 60; \
	    echo "fuzz-scene: FAILED (exit $$rc) after $${execs:-?} executions; artifacts:"; \
	    find $(FUZZ_DIR) -maxdepth 1 -type f -name 'scene-*' -newer $(FUZZ_DIR)/scene.dict | sed 's/^/    /'; \
	    exit 1; \
	fi; \
	echo "fuzz-scene: $${execs:-0} executions in $${secs} s ($${rate:-0} exec/s), corpus $$files files, no crash"

# Everything make test needs for these suites. fuzz-short.sh runs before
# sanitize.sh so the latter can draw inputs from a fresh corpus.
SUITES_EXTRA += tests/fuzz-short.sh tests/sanitize.sh
TEST_PREREQ  += san-build $(FUZZ_SCENE_BIN)
TEST_FULL_PREREQ += $(DIFF_FUZZ_BIN) $(SAN_ORACLE)

.PHONY: sanitize san-build fuzz-scene
