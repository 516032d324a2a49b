# The oracle: the fast renderer against the per-pixel ray caster on every
# scene and on random scenes (tests/oracle.c, tests/oracle_num.c,
# tests/randscene.c; docs/TESTING.md). Included by the top Makefile.
#
#   make test                      tests/oracle.sh: every scene file and
#                                  ORACLE_TEST_SCENES random scenes
#   make oracle ORACLE_SCENES=N    N random scenes (default 20000) from
#                                  ORACLE_SEED (default 1)
#   make stress-expect             rewrite the generated "# expect:" lines
#                                  of scenes/stress/*.scene (unlit ones)

ORACLE_NUMBERS := q16 double
ORACLE_BIN     := $(BUILD)/tests/oracle
ORACLE_OBJ     := $(BUILD)/tests/oracle.o $(BUILD)/tests/randscene.o $(SCENE_LIB) $(BUILD)/host/fx.o \
                  $(call multi_objs,$(BUILD),oracle,$(ORACLE_NUMBERS))

define oracle_number_rules
$(BUILD)/tests/oracle_num-$(1).o: tests/oracle_num.c
	@mkdir -p $$(@D)
	@echo "  CC $(1)  $$<"
	$$(Q)$$(CC) $$(CFLAGS_H) -DFXRT_MULTI -DFXRT_NUMBER=$(call num_id,$(1)) -Icore -Ihost -c $$< -o $$@
endef
$(foreach n,$(ORACLE_NUMBERS),$(eval $(call oracle_number_rules,$(n))))

$(ORACLE_BIN): $(ORACLE_OBJ)
	@echo "  LD      $@"
	$(Q)$(CC) $(CFLAGS_H) -o $@ $^ -lm

SUITES_EXTRA += tests/oracle.sh
TEST_PREREQ  += $(ORACLE_BIN)

ORACLE_SCENES ?= 20000
ORACLE_SEED   ?= 1
oracle: $(ORACLE_BIN)
	$(Q)$(ORACLE_BIN) --random $(ORACLE_SCENES) --seed $(ORACLE_SEED) scenes/*.scene scenes/*/*.scene

# (unlit scenes only: lit ones have hand-written expectations; tests/oracle.sh)
ORACLE_FLAT_STRESS = $(shell grep -LE '^[[:space:]]*(light|ambient)[[:space:]]|[[:space:]]material[[:space:]]+(lambert|phong)' scenes/stress/*.scene)
stress-expect: $(ORACLE_BIN)
	$(Q)$(ORACLE_BIN) --stress-expect --write $(ORACLE_FLAT_STRESS)

.PHONY: oracle stress-expect
