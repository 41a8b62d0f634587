# Plots of the benchmark results (gnuplot 5).
#   gnuplot -e "dir='benchmark/results'" benchmark/Stretch_minimizing_parameterization/plots.gp
# Reads the plot_*.dat files that benchmark_parameterizers --out DIR writes (one block per
# line, the first row of a block is its title) and writes PNG files next to them.

if (!exists("dir")) dir = "."
# true if the file exists and holds at least one data block
has_data(f) = system("grep -qs '^[0-9]' '".f."' && echo 1 || echo 0") eq "1"

set terminal pngcairo size 1300,1050 noenhanced font "sans,11"
set grid
set key outside below center Left reverse maxrows 7 height 1.5
set style data linespoints
set pointsize 1.2
# 17 distinct line types (the default cycle repeats after 8); line i is the i-th block
colors = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #000000 #8c564b #e377c2 #7f7f7f #bcbd22 #17becf #ff9896 #006400 #4b0082 #808000 #00ced1 #8b0000"
do for [i=1:17] {
  point = i % 13 + 1
  if (i <= 8) { set linetype i lc rgb word(colors, i) lw 2 pt point dt solid } \
  else { set linetype i lc rgb word(colors, i) lw 2 pt point dt 2 }
}

# Time against the number of vertices, log-log, one line per method
file = dir."/plot_time.dat"
if (has_data(file)) {
stats file using 1 nooutput
set output dir."/time_vs_vertices.png"
set title "Wall time of one parameterization call (median) against mesh size"
set xlabel "vertices"
set ylabel "seconds"
set logscale xy
set format y "%g"
set format x "%g"
plot for [i=0:STATS_blocks-1] file index i using 1:2 title columnheader(1)
unset output
}

# Peak memory against the number of vertices
file = dir."/plot_memory.dat"
if (has_data(file)) {
stats file using 1 nooutput
set output dir."/memory_vs_vertices.png"
set title "Peak resident memory of the process running one call (mesh included)"
set ylabel "MiB"
plot for [i=0:STATS_blocks-1] file index i using 1:2 title columnheader(1)
unset output
}

# L2 stretch against the step h of the stretch minimization, one line per mesh
set xlabel "step h"
set ylabel "normalized L2 stretch of U^h"
unset logscale x
set logscale y
set xtics 1
set format y "%.2f"
do for [id in "f_uopt uopt_eta05"] {
  file = dir."/plot_history_".id.".dat"
  if (!has_data(file)) { continue }
  stats file using 1 nooutput
  eta = (id eq "f_uopt") ? "1" : "0.5"
  set output dir."/stretch_vs_step_".id.".png"
  set title "Stretch minimization, eta = ".eta.": L2 stretch of U^h (the last step, where the stretch stops decreasing, is not kept)"
  plot for [i=0:STATS_blocks-1] file index i using 1:2 title columnheader(1)
  unset output
}
