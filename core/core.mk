# The core's sources by layer (make fragments and scripts read this file):
#   CORE_FX   the Q16.16 scalar library, the same in every number type
#   CORE_NUM  the number-generic renderer, built once per number type
# Paths are relative to core/, without .c.
CORE_FX  := math/fx math/fx128 math/trig
CORE_NUM := math/num math/color scene/cam scene/geom scene/plane scene/sphere scene/triangle scene/box scene/mesh scene/world \
            vis/setup_forms vis/setup vis/setup_plane vis/setup_sphere vis/setup_triangle vis/setup_box vis/cull vis/order vis/depth vis/fill vis/row vis/flat vis/claim vis/sphere vis/reference frame/render frame/render_shade frame/render_sample \
            light/shade light/shadow light/trace light/hit frame/raycast frame/api
CORE_SRC := $(CORE_FX) $(CORE_NUM)
