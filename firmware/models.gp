# The growth curve of make bench-models (firmware/models-plot.sh draws it):
#   gnuplot -e "series='S'; data='D.dat'; names='b,lit b,flat ...'; out='P.png'" firmware/models.gp
# series: one block per board and scene ("triangles instr_per_px" rows,
# blocks two blank lines apart), named in order by names' words; data:
# "model triangles board scene instr_per_px" rows, of which the Spot
# models' are drawn as single points.
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 900,600 font "sans,10"
} else {
    set terminal png size 900,600
}
set output out
set title "make bench-models: growth with the triangle count (a model on a floor, Q16.16, 160x120, QEMU -icount)"
set logscale x 10
set logscale y 10
set xlabel "triangles in the model (icospheres; log scale)"
set ylabel "instructions per pixel (log scale)"
set xrange [40 : 200000]
set yrange [100 : 100000]
set grid
set key inside left top font ",8" spacing 0.9
n = words(names)
board(i) = word(names, i)[1 : strstrt(word(names, i), ",") - 1]
scene(i) = word(names, i)[strstrt(word(names, i), ",") + 1 :]
colour(b) = b eq "mps2-an385" ? "#1f77b4" : b eq "mps2-an386" ? "#2ca02c" : "#d62728"
dash(s) = s eq "lit" ? 1 : 2
# The M3 and the M4F run the same integer code, so their lines nearly meet:
# the M3 drawn last, thin, with filled points, over the others.
mark(b) = b eq "mps2-an385" ? 7 : 6
# The targets at 5,120 triangles on the M3: lit <= 4,000, flat <= 200.
set label 1 "target, lit (M3)" at 5120, 4000 offset 1, 0.6 font ",8"
set label 2 "target, flat (M3)" at 5120, 200 offset 1, 0.6 font ",8"
set object 1 circle at 5120, 4000 size char 0.4 fc rgb "black" fs solid
set object 2 circle at 5120, 200 size char 0.4 fc rgb "black" fs solid
plot for [i = n : 1 : -1] series index (i - 1) using 1:2 with linespoints lw (board(i) eq "mps2-an385" ? 1.5 : 3) dt dash(scene(i)) pt mark(board(i)) ps 0.9 \
         lc rgb colour(board(i)) title sprintf("%s, %s", board(i), scene(i)), \
     data using (strcol(1)[1:4] eq "spot" ? $2 : NaN):(strcol(4) eq "lit" ? $5 : NaN) with points pt 5 ps 1 lc rgb "black" \
         title "Spot (1,654 and 23,062), lit, each board", \
     data using (strcol(1)[1:4] eq "spot" ? $2 : NaN):(strcol(4) eq "flat" ? $5 : NaN) with points pt 4 ps 1 lc rgb "black" \
         title "Spot, flat, each board"
