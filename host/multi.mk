# Programs that link the renderer in all three number types (the host tool,
# the scene compiler, test_color, the oracle, test_diff) link, per number
# type, one object that host/multi-ld.sh makes from that number's objects:
# their global symbols get the type's suffix, so the three builds of the
# core link side by side without renaming anything in the core. Included by
# the top Makefile after .SECONDEXPANSION.
#
# MULTI_<program>-<number>: the objects, relative to a build tree. The same
# lists serve the normal tree ($(BUILD)/), the sanitized one ($(BUILD)/san/)
# and the kernel fuzzer's, each with a rule of its own below.
multi_core = $(CORE_NUM:%=host/$(1)/%.o)
$(foreach n,$(NUMBERS),$(eval MULTI_fxrt-$(n) := host/engine-$(n).o $(call multi_core,$(n))))
$(foreach n,$(NUMBERS),$(eval MULTI_scenec-$(n) := host/engine-$(n).o host/scenec_emit-$(n).o host/scenec_world-$(n).o $(call multi_core,$(n))))
$(foreach n,$(NUMBERS),$(eval MULTI_oracle-$(n) := tests/oracle_num-$(n).o host/engine-$(n).o $(call multi_core,$(n))))
$(foreach n,$(NUMBERS),$(eval MULTI_diff-$(n) := tests/diffk-$(n).o $(call multi_core,$(n))))

# $(call multi_objs,TREE,PROGRAM,NUMBERS): the program's joined objects.
multi_objs = $(foreach n,$(3),$(1)/multi/$(2)-$(n).o)
# The number type is the stem's last word (fxrt-q16 -> q16).
multi_link = @mkdir -p $(@D); echo "  LD -r   $@"; host/multi-ld.sh $@ $(lastword $(subst -, ,$*)) $(filter %.o,$^)

$(BUILD)/multi/%.o: $$(addprefix $(BUILD)/,$$(MULTI_$$*)) host/multi-ld.sh
	$(Q)$(multi_link)
