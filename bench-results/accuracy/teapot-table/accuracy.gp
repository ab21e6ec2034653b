# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
73.855 0.260103 0.260103 "search, no tessellation"
27.735 0.212915 0.212915 "environment map 256 px"
71.446 0.209707 0.209707 "environment map 1024 px"
168.730 0.109298 0.109298 "full level 1"
1521.934 0.038880 0.038880 "full level 4"
1210.007 0.038880 0.035867 "full level 3"
649.424 0.038880 0.038880 "full level 2"
76.650 0.036532 0.036532 "adaptive angle 0.01"
89.215 0.021173 0.021173 "adaptive angle 0.003"
69.715 0.004405 0.004405 "G-buffer x0.5"
89.839 0.002835 0.002835 "adaptive angle 0.001"
78.034 0.001026 0.001026 "G-buffer x2"
88.116 0.000922 0.000922 "adaptive 2 px"
70.493 0.000755 0.000755 "G-buffer RGBA16F"
122.118 0.000558 0.000558 "adaptive 0.25 px"
86.784 0.000474 0.000474 "adaptive 1 px"
102.643 0.000446 0.000437 "adaptive 0.5 px"
EOD
$front << EOD
27.735 0.212915
69.715 0.004405
70.493 0.000755
86.784 0.000474
102.643 0.000446
EOD
set title "teapot-table at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key bottom left box opaque
set xrange [22.030560:4289.392973]
set yrange [0.000310:0.367405]
set arrow 1 from 39.810, graph 0 to 39.810, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 40 ms, error 0" at 39.810, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
