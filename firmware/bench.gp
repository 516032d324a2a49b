# Pareto plot of one board and scene set for make bench (firmware/bench.sh):
#   gnuplot -e "data='D.dat'; front='D.front'; out='P.png'; board='B (Cortex-M3), seed scenes'; size='160x120'; zero=1e-4" firmware/bench.gp
# data rows: number loop instr_per_pixel mismatched_pct "label" (loop: fast,
# step, reference, raycast; fast is drawn as the shipped renderer); 0 % is
# written as `zero` so the log axis can show it. front: the Pareto points,
# sorted by x (lines join them; a diamond marks each, so a one-point front shows).
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 900,600 font "sans,10"
} else {
    set terminal png size 900,600
}
set output out
# stats first: it honours log scales and ranges set before it
stats data using (strcol(2) eq "fast" ? 1 : 0) nooutput
nfast = STATS_sum; nref = STATS_records - STATS_sum
stats data using 3 nooutput
xmin = STATS_min; xmax = STATS_max
stats data using 4 nooutput
ytop = STATS_max * 3 > 1 ? STATS_max * 3 : 1
set title sprintf("%s, %s: run time against error, each build averaged over the set", board, size)
set logscale x 10
set logscale y 10
set xlabel "instructions per pixel (geometric mean over the scenes; QEMU -icount instructions, not cycles)"
set ylabel "pixels differing from the double reference, % (mean; 0 = identical)"
if (xmin == xmax) { set xrange [xmin / 2 : xmax * 2] }
set yrange [zero / 8 : ytop]
set ytics ("0" zero, "0.001" 1e-3, "0.01" 1e-2, "0.1" 0.1, "1" 1, "10" 10, "100" 100)
set offsets graph 0.08, graph 0.25, 0, 0

set grid
set key top right box opaque
# Labels slant away from their point (fast up, the others down) so builds at
# the same error and close run times stay legible. A labels plot whose
# points are all NaN crashes gnuplot 5.4, so each is added only when needed.
lfast = nfast > 0 ? ', data using 3:(strcol(2) eq "fast" ? $4 : NaN):5 with labels left rotate by 40 offset 0.7, 0.7 font ",9" notitle' : ''
lref = nref > 0 ? ', data using 3:(strcol(2) eq "fast" ? NaN : $4):5 with labels left rotate by -40 offset 0.7, -0.7 font ",9" notitle' : ''
eval('plot front using 3:4 with linespoints lw 2 pt 12 ps 3.5 lc rgb "gray50" title "Pareto front", ' . \
     'data using 3:(strcol(2) eq "fast" ? $4 : NaN) with points pt 7 ps 1.6 lc rgb "#1f77b4" title "fast renderer", ' . \
     'data using 3:(strcol(2) eq "fast" ? NaN : $4) with points pt 6 ps 2.2 lw 2 lc rgb "#d62728" title "step, reference loop, ray caster"' . \
     lfast . lref)
