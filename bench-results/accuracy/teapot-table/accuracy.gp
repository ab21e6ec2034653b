# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
68.034 0.260103 0.260103 "search, no tessellation"
30.895 0.212915 0.212915 "environment map 256 px"
70.333 0.209707 0.209707 "environment map 1024 px"
179.247 0.109298 0.109298 "full level 1"
1238.241 0.038880 0.038880 "full level 4"
1288.626 0.038880 0.035867 "full level 3"
745.538 0.038880 0.033087 "full level 2"
77.708 0.036532 0.036532 "adaptive angle 0.01"
78.620 0.021173 0.021173 "adaptive angle 0.003"
62.430 0.004405 0.004405 "G-buffer x0.5"
78.726 0.002835 0.002835 "adaptive angle 0.001"
66.038 0.001026 0.001026 "G-buffer x2"
83.615 0.000922 0.000922 "adaptive 2 px"
63.891 0.000755 0.000755 "G-buffer RGBA16F"
111.125 0.000558 0.000558 "adaptive 0.25 px"
81.585 0.000474 0.000474 "adaptive 1 px"
94.679 0.000446 0.000437 "adaptive 0.5 px"
37.704 0.000100 0.000100 "ray-cast every mirror"
EOD
$front << EOD
30.895 0.212915
37.704 0.000100
EOD
set title "teapot-table at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [24.541162:3631.840781]
set yrange [0.000071:0.367405]
set arrow 1 from 40.314, graph 0 to 40.314, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 40 ms, error 0" at 40.314, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
