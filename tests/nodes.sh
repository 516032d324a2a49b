#!/usr/bin/env bash
# The node and mesh scenes' accuracy (scenes/nodes/): tests/lit.sh's
# checks at 640x480 with the mesh issue's figures for Q16.16 against
# double: at least 99.9 % of the pixels within 1/255 overall and away from
# discontinuities, PSNR at least 45 dB, fast and reference renderers
# byte-identical, and the lighting visible against the flat version (at
# least 5 % of the pixels change: the turned box covers 10 %; twice the flat version's colours: a
# flat-shaded mesh under a directional light has one colour per face).
# Pixels away from discontinuities are not held to 2/255 as the lit set's
# are: a shadow ray from within a few 2^-16 of an edge two mesh triangles
# share can be blocked by the neighbour in Q16.16 (docs/LIGHTING.md,
# "Shadow acne"); the table prints how many.
LIT_NAME=nodes LIT_DIR=scenes/nodes LIT_FAR_WITHIN2=- LIT_FAR_MAX=- LIT_FAR_WITHIN1=99.9 LIT_PSNR=45 \
    LIT_MIN_CHANGED_PCT=5 LIT_COLOUR_FACTOR=2 exec "$(dirname "$0")/lit.sh"
