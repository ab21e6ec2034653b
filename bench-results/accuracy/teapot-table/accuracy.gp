# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
30.145 0.212915 0.212915 "environment map 256 px"
74.293 0.209707 0.209707 "environment map 1024 px"
95.005 0.004204 0.004204 "G-buffer x0.5"
100.918 0.000649 0.000649 "G-buffer x2"
72.216 0.000474 0.000474 "uncovered pixels show the background"
85.172 0.000340 0.000340 "G-buffer RGBA16F"
89.176 0.000167 0.000167 "search, no tessellation"
220.065 0.000167 0.000167 "hierarchy search, no tessellation"
80.647 0.000159 0.000154 "adaptive angle 0.01"
86.375 0.000159 0.000142 "adaptive angle 0.003"
79.594 0.000156 0.000131 "adaptive 2 px"
86.324 0.000117 0.000117 "adaptive angle 0.001"
31.355 0.000100 0.000100 "ray-cast every mirror"
245.748 0.000100 0.000100 "hierarchy search"
1754.196 0.000100 0.000100 "full level 4"
1699.482 0.000100 0.000092 "full level 3"
818.913 0.000100 0.000100 "full level 2"
246.443 0.000100 0.000092 "full level 1"
121.210 0.000100 0.000100 "adaptive 0.25 px"
93.132 0.000100 0.000092 "adaptive 0.5 px"
76.792 0.000100 0.000085 "adaptive 1 px"
EOD
$front << EOD
30.145 0.212915
31.355 0.000100
EOD
set title "teapot-table at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [23.945235:4943.994675]
set yrange [0.000060:0.300750]
set arrow 1 from 42.761, graph 0 to 42.761, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 43 ms, error 0" at 42.761, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
set label 2 "mismatch under 0.0001 (exact included) is drawn on this line" at graph 0.99, first 0.000100 right offset 0, 0.8 font ',8' textcolor rgb '#444444' noenhanced
set terminal pngcairo size 1100,750 font ',10'
set output "accuracy.png"
plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title 'Pareto front', \
     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \
     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle
set terminal svg size 1100,750 dynamic font ',10'
set output "accuracy.svg"
plot $front using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 1.6 linecolor rgb '#d62728' title 'Pareto front', \
     $settings using 1:2 with points pointtype 7 pointsize 1 linecolor rgb '#1f77b4' title 'setting', \
     $settings using 1:3:4 with labels left offset 0.8, 0 font ',8' noenhanced notitle
unset output
