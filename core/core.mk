# The core's sources by layer (make fragments and scripts read this file):
#   CORE_FX   the Q16.16 scalar library, the same in every number type
#   CORE_NUM  the number-generic renderer, built once per number type:
#             every other .c of the core's folders, so a new file (a new
#             kind's scene/<kind>.c and vis/setup_<kind>.c) needs no edit here
# Paths are relative to core/, without .c.
CORE_FX  := math/fx math/fx128 math/trig
CORE_NUM := $(filter-out $(CORE_FX),$(patsubst core/%.c,%,$(sort $(wildcard core/*/*.c))))
CORE_SRC := $(CORE_FX) $(CORE_NUM)
