# fxrt --version: the version is FXRT_VERSION in host/version.h; the host
# tool also embeds `git describe` when built in a git checkout. The header
# is rewritten only when the description changes, so main.o rebuilds then
# and only then; git runs only when the host tool is a goal's prerequisite.
FXRT_GIT_H := $(BUILD)/host/git_describe.h

$(FXRT_GIT_H): FORCE
	@mkdir -p $(@D)
	$(Q)d=$$(git describe --always --dirty 2>/dev/null | tr -cd 'A-Za-z0-9._+-'); \
	  if [ -n "$$d" ]; then l="#define FXRT_GIT_DESCRIBE \"$$d\""; else l="/* not a git checkout */"; fi; \
	  echo "$$l" | cmp -s - $@ || echo "$$l" >$@

$(BUILD)/host/main.o: $(FXRT_GIT_H)
$(BUILD)/host/main.o: CFLAGS_H += -include $(FXRT_GIT_H)
