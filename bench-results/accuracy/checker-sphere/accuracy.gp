# gnuplot script written by `specula bench accuracy`; rerun with: gnuplot <this file>
# settings: frame ms, mirror mismatch, label height, name
$settings << EOD
27.791 0.236485 0.236485 "environment map 256 px"
71.809 0.229739 0.229739 "environment map 1024 px"
33.190 0.009325 0.009325 "G-buffer x0.5"
35.585 0.003460 0.003460 "uncovered pixels show the background"
62.379 0.002463 0.002463 "G-buffer x2"
37.211 0.000628 0.000628 "G-buffer RGBA16F"
35.227 0.000100 0.000100 "ray-cast every mirror"
160.406 0.000100 0.000100 "hierarchy search"
50.537 0.000100 0.000092 "hierarchy search, no tessellation"
429.552 0.000100 0.000100 "full level 4"
162.113 0.000100 0.000092 "full level 3"
69.546 0.000100 0.000100 "full level 2"
41.539 0.000100 0.000085 "full level 1"
44.528 0.000100 0.000079 "adaptive angle 0.001"
42.333 0.000100 0.000072 "adaptive angle 0.003"
41.572 0.000100 0.000067 "adaptive angle 0.01"
63.249 0.000100 0.000062 "adaptive 0.25 px"
49.695 0.000100 0.000057 "adaptive 0.5 px"
45.025 0.000100 0.000052 "adaptive 1 px"
41.804 0.000100 0.000048 "adaptive 2 px"
38.880 0.000100 0.000045 "search, no tessellation"
EOD
$front << EOD
27.791 0.236485
33.190 0.009325
35.227 0.000100
EOD
set title "checker-sphere at 640x480: 8 poses, 12 deg orbit, llvmpipe (LLVM 15.0.6, 256 bits)" noenhanced
set xlabel 'frame time, ms (median over the camera path; log scale)'
set ylabel 'mirror mismatch against the ray tracer (share of mirror pixels; log scale)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key top right box opaque
set xrange [22.075393:1210.641456]
set yrange [0.000032:0.334045]
set arrow 1 from 45.906, graph 0 to 45.906, graph 1 nohead dashtype 2 linecolor rgb '#444444'
set label 1 "ray-traced reference: 46 ms, error 0" at 45.906, graph 0.25 rotate by 90 offset -1, 0 center noenhanced
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
