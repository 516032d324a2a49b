# Pareto plot of one board for make frontier (firmware/frontier-report.sh):
#   gnuplot -e "data='D.dat'; front='D.front'; out='P.png'; board='B (Cortex-M3)'; size='64x48'" firmware/frontier.gp
# data rows: number loop samples instr_per_pixel mae "label" (samples 1 2 4 4a);
# front: the Pareto points (same columns, no label), sorted by x.
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 1000,650 font "sans,10"
} else {
    set terminal png size 1000,650
}
set output out
stats data using 4 nooutput
xmin = STATS_min; xmax = STATS_max
stats data using 5 nooutput
ymin = STATS_min; ymax = STATS_max
set title sprintf("%s, %s: instructions per pixel against error from the converged image (16x16 samples, double)", board, size)
set logscale x 10
set logscale y 2
set format y "%g"
set xlabel "instructions per pixel (geometric mean over the scenes; QEMU -icount instructions)"
set ylabel "mean absolute error per channel, 1/255 units (mean over the scenes)"
set xrange [xmin / 1.6 : xmax * 2.5]
set yrange [ymin / 1.5 : ymax * 1.5]
set grid
set key top right box opaque
col(n) = n eq "q16" ? 1 : n eq "float" ? 2 : 3
plot front using 4:5 with lines lw 2 lc rgb "gray50" title "Pareto front", \
     front using 4:5 with points pt 12 ps 3.2 lw 2 lc rgb "gray50" notitle, \
     data using 4:(strcol(1) eq "q16" ? $5 : NaN) with points pt 7 ps 1.6 lc rgb "#1f77b4" title "q16", \
     data using 4:(strcol(1) eq "float" ? $5 : NaN) with points pt 5 ps 1.4 lc rgb "#2ca02c" title "float (step)", \
     data using 4:(strcol(1) eq "double" ? $5 : NaN) with points pt 9 ps 1.7 lc rgb "#d62728" title "double", \
     data using 4:5:6 with labels left rotate by 25 offset 0.8, 0.5 font ",8" notitle
