# Mesh queries on the host and the boards (firmware/meshq.c), included by
# the top Makefile after firmware.mk. tests/meshq.sh (in make test) and
# firmware/meshq.sh (make bench-mesh) drive these rules:
#   $(BUILD)/meshq/NAME/mesh.c, meshq_data.h   tests/meshq_gen.c from MESHQ_OBJ (MESHQ_RAYS rays, MESHQ_FLAT=--flat)
#   $(BUILD)/meshq/NAME/host                   the host build (q16)
#   $(BUILD)/meshq/NAME/BOARD.elf              a board's
MESHQ_GEN := $(BUILD)/meshq/meshq_gen
MESHQ_HOST_SRC := tests/meshq_gen.c host/meshbuild.c host/meshemit.c host/obj.c host/errf.c

$(MESHQ_GEN): $(MESHQ_HOST_SRC) host/meshbuild.h host/meshemit.h host/obj.h core/scene/bvh.h $(BUILD)/host/fx.o
	@mkdir -p $(@D)
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) -Icore -Ihost -o $@ $(MESHQ_HOST_SRC) $(BUILD)/host/fx.o -lm

$(BUILD)/meshq/%/meshq_data.h: $(MESHQ_GEN) $(MESHQ_OBJ)
	@mkdir -p $(@D)
	$(Q)$(MESHQ_GEN) $(MESHQ_OBJ) $(@D) $(MESHQ_RAYS) $(MESHQ_FLAT) >$(@D)/gen.txt

$(BUILD)/meshq/%/host: firmware/meshq.c $(BUILD)/meshq/%/meshq_data.h $(BUILD)/host/fx.o $(CORE_NUM:%=$(BUILD)/host/q16/%.o)
	@echo "  CC/LD   $@"
	$(Q)$(CC) $(CFLAGS_H) -DMESHQ_HOST -DFXRT_MULTI -Icore -I$(@D) -o $@ firmware/meshq.c $(@D)/mesh.c \
	  $(BUILD)/host/fx.o $(CORE_NUM:%=$(BUILD)/host/q16/%.o) -lm

# (the core files the queries use, not the whole core: each test's ELFs build in a second;
# FXRT_MAX_MODELS=1: a bare board has no models by default, and scene/bvh.c
# compiles only where there are)
MESHQ_FW_SRC := firmware/meshq.c core/scene/bvh.c core/scene/geom.c $(wildcard core/math/*.c) \
                firmware/startup.c firmware/semihost.c firmware/counter.c
define meshq_board_rule
$(BUILD)/meshq/%/$(1).elf: $(MESHQ_FW_SRC) $(BUILD)/meshq/%/meshq_data.h $(wildcard linker/*.ld)
	@echo "  ARMCC   $$@"
	$$(Q)$$(ARM_CC) $$(WARN) -O2 $$(CPU_$(1)) -ffreestanding -ffunction-sections -fdata-sections -fno-math-errno \
	  -DFXRT_NUMBER=1 -DFXRT_MAX_MODELS=1 -Icore -Ifirmware -I$$(@D) $$(MESHQ_FW_SRC) $$(@D)/mesh.c -nostartfiles \
	  --specs=nano.specs --specs=nosys.specs -Wl,--gc-sections -Wl,-Map=$$(@D)/$(1).map -Llinker -Tlinker/$(1).ld -lm -o $$@
endef
$(foreach b,$(BOARDS),$(eval $(call meshq_board_rule,$(b))))

# make test: tests/meshq.sh (fxrt-scenec --mesh, host and boards alike).
SUITES += tests/meshq.sh
# Built before the suites run: meshq.sh and cycles.sh both use it, and
# tests/run.sh may run them side by side.
test-build: $(MESHQ_GEN)

# make bench-mesh [MESHQ_UPDATE_DOCS=1]: every model's bytes and queries
# on every board (firmware/meshq.sh; docs/bench/meshes.md).
bench-mesh: $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) MESHQ_UPDATE_DOCS=$(MESHQ_UPDATE_DOCS) \
	  MESHQ_TICKS='$(foreach b,mps2-an385 mps2-an386 microbit,$(b):$(TICK_NS_$(b)))' firmware/meshq.sh
.PHONY: bench-mesh

# make bench-models [MODELS_UPDATE_DOCS=1] [MODELS_ONLY="ico80 spot"]: models
# in scenes on a floor, lit and flat, rendered by the firmware on every
# board (firmware/models.sh; docs/bench/models.md).
bench-models: deps $(BUILD)/fxrt $(BUILD)/fxrt-scenec
	$(Q)BUILD=$(BUILD) MODELS_UPDATE_DOCS=$(MODELS_UPDATE_DOCS) firmware/models.sh
.PHONY: bench-models

# make models-plot: docs/bench/models.png (the growth curve, log-log) drawn
# again from docs/bench/models.md, the table make bench-models generated.
models-plot:
	$(Q)mkdir -p $(BUILD)/models
	$(Q)firmware/models-plot.sh docs/bench/models.md docs/bench/models.png $(BUILD)/models/models-plot.dat
.PHONY: models-plot
